//! The per-contact state of the time-stepped friction models ([`ContactHistory`],
//! what a DEM engine keeps per pair) and the turning of a stored vector into the
//! current tangent plane; shared by [`crate::step`] and the micro-slip form.

use nalgebra::Vector3;

/// The history of one contact, carried from step to step: zero when the contact
/// forms, discarded when it breaks. `#[repr(C)]` and all doubles, so that a DEM
/// engine can keep it in its per-pair history arrays (8 doubles for the LAMMPS
/// models, which `pair granular` keeps in 3 (+1 for `mindlin_rescale`) + 3 + 3,
/// and the [`crate::micro_slip::BED_LEN`] doubles of the micro-slip bed after
/// them, used by `mindlin_deresiewicz` only).
///
/// When the roles of `i` and `j` are swapped (LAMMPS `newton` bookkeeping), the
/// vectors change sign and the scalars do not (LAMMPS's
/// `transfer_history_factor`); in the micro-slip bed, whose springs are stored
/// as components in the basis `(e₁, n × e₁)`, the signs of `e₁` and of every
/// second component change.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactHistory {
    /// Accumulated tangential displacement ξ (m), in the tangent plane; for
    /// `mindlin_deresiewicz` the elastic tangential force `T` of the bed (N; the
    /// force on body `i` is `−T`).
    pub tangential: [f64; 3],
    /// `mindlin_rescale`: the contact radius of the last update (m); unused by
    /// the other models.
    pub tangential_contact_radius: f64,
    /// Accumulated rolling displacement (m), in the tangent plane.
    pub rolling: [f64; 3],
    /// Accumulated twist angle (rad).
    pub twisting: f64,
    /// `mindlin_deresiewicz`: the compact spring bed of the method of
    /// dimensionality reduction ([`crate::micro_slip`]: its basis, spacing, last
    /// squared contact radius and the displacements of its springs).
    pub micro_slip: [f64; crate::micro_slip::BED_LEN],
}

impl Default for ContactHistory {
    fn default() -> Self {
        ContactHistory {
            tangential: [0.0; 3],
            tangential_contact_radius: 0.0,
            rolling: [0.0; 3],
            twisting: 0.0,
            micro_slip: [0.0; crate::micro_slip::BED_LEN],
        }
    }
}

/// Projects `v` into the plane normal to the unit vector `n` and restores its
/// length (LAMMPS `rotate_rescale_vec`; a vector along `n` collapses to zero).
pub fn rotate_into_plane(v: Vector3<f64>, n: &Vector3<f64>) -> Vector3<f64> {
    let length = v.norm();
    let projected = v - n * n.dot(&v);
    let new_length = projected.norm();
    if new_length > 0.0 {
        projected * (length / new_length)
    } else {
        Vector3::zeros()
    }
}
