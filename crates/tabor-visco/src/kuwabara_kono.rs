//! The Kuwabara-Kono viscous force of a Kelvin-Voigt contact, seed 000 eq. (5.66):
//! `F_d = 2 η_c a δ̇`, with η_c = E* A the contact viscosity (A the dissipative
//! time) and a the contact radius. For a Hertzian contact (a = √(Rδ)) this is the
//! damping term of (5.66), `(4/3)E*√R · (3/2) A δ^(1/2) δ̇`; with adhesion the
//! contact radius of the adhesive law is used (tabor's coupled viscous-adhesive
//! model, `tabor-viscoadhesive`; LAMMPS's `damping viscoelastic` has the same form).
//! The one formula the workspace's per-step force laws share (`tabor-ffi`,
//! `tabor-viscoadhesive`).

/// The Kuwabara-Kono viscous force (N, > 0 opposing approach): `2 η_c a δ̇` with
/// `contact_viscosity` η_c = E*A (Pa·s), `contact_radius` a (m; a negative value
/// counts as 0) and `overlap_rate` δ̇ (m/s, > 0 approaching). Not validated (this
/// sits in per-step inner loops): NaN in, NaN out.
///
/// Seed 000, eq. (5.66).
#[inline]
pub fn viscous_force(contact_viscosity: f64, contact_radius: f64, overlap_rate: f64) -> f64 {
    2.0 * contact_viscosity * contact_radius.max(0.0) * overlap_rate
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn is_the_damping_term_of_the_hertzian_kuwabara_kono_law() {
        // (5.66): F = (4/3)E*√R (δ^(3/2) + (3/2) A δ^(1/2) δ̇); the damping part with
        // a = √(Rδ) and η_c = E* A
        let (e, r, a_time, d, v) = (7e10_f64, 2e-6_f64, 3e-9_f64, 4e-9_f64, 0.7_f64);
        let expected = 4.0 / 3.0 * e * r.sqrt() * 1.5 * a_time * d.sqrt() * v;
        let f = viscous_force(e * a_time, (r * d).sqrt(), v);
        assert!((f / expected - 1.0).abs() < 1e-14, "{f} vs {expected}");
        assert_eq!(viscous_force(1.0, -1.0, 1.0), 0.0);
    }
}
