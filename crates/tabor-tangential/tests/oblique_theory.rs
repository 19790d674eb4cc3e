//! The oblique impact against theory: frictionless and gross-sliding limits
//! (exact, rigid-body Coulomb), the stick limit against an independent
//! integration, Maw-Barber-Fawcett's tangential restitution, energy bookkeeping.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use approx::assert_relative_eq;
use tabor_dynamics::SimulationSettings;
use tabor_elastic::ElasticContact;
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact};
use tabor_tangential::{EffectiveShear, Friction, Tangential, Twisting};

const R: f64 = 1e-6;
const RHO: f64 = 2650.0;
const E_Y: f64 = 54e9;
const NU: f64 = 0.17;

fn effective_modulus_flat() -> f64 {
    // sphere on a rigid flat of the same material, LAMMPS wall: E/(2(1 − ν²))... here
    // a flat of the same material: 1/E* = 2(1 − ν²)/E
    E_Y / (2.0 * (1.0 - NU * NU))
}

fn on_flat(mu: f64) -> (ObliqueImpact, ElasticContact) {
    let shear = EffectiveShear::of_pair(E_Y, NU, E_Y, NU).unwrap();
    let friction = Friction::sliding(Tangential::mindlin(shear, 0.0, mu).unwrap());
    let imp = ObliqueImpact {
        sphere: Body::solid_sphere(R, RHO).unwrap(),
        target: Body::flat(),
        normal: NormalContact::ELASTIC,
        friction: Some(friction),
        sphere_spin: [0.0; 3],
        target_spin: [0.0; 3],
    };
    (
        imp,
        ElasticContact::hertz(effective_modulus_flat(), R).unwrap(),
    )
}

fn settings() -> SimulationSettings {
    SimulationSettings::with_tolerance(1e-9).unwrap()
}

#[test]
fn frictionless_impact_keeps_the_tangential_velocity() {
    let (mut imp, mut law) = on_flat(0.3);
    imp.friction = None;
    let out = imp.simulate(&mut law, 0.5, 40.0, &settings()).unwrap();
    assert_relative_eq!(out.normal_restitution, 1.0, max_relative = 1e-8);
    assert_relative_eq!(
        out.tangential_restitution.unwrap(),
        -1.0,
        max_relative = 1e-12
    );
    assert!(out.energy_error < 1e-8, "{}", out.energy_error);
}

#[test]
fn gross_sliding_is_rigid_body_coulomb() {
    // sliding throughout: the friction impulse is μ P_n with P_n = 2 m v_n (e_n = 1),
    // so the contact point slows by μ P_n (1/m + R²/I) = 7 μ v_n (solid sphere) and
    // the sphere spins up to ω_z = −R μ P_n / I = −5 μ v_n / R. A flat target: the
    // torque arm is R exactly (LAMMPS's wall), so the closed form is exact.
    let mu = 0.1;
    let (imp, mut law) = on_flat(mu);
    for &(v, angle) in &[(0.3, 80.0), (1.0, 70.0), (0.05, 85.0)] {
        let out = imp.simulate(&mut law, v, angle, &settings()).unwrap();
        let a = f64::to_radians(angle);
        let vn = v * a.cos();
        assert_eq!(out.slip_switches, 0, "slides throughout");
        assert_relative_eq!(out.normal_restitution, 1.0, max_relative = 1e-8);
        let et = -1.0 + 7.0 * mu / a.tan();
        assert_relative_eq!(out.tangential_restitution.unwrap(), et, max_relative = 1e-8);
        assert_relative_eq!(
            out.after.sphere.angular_velocity[2],
            -5.0 * mu * vn / R,
            max_relative = 1e-8
        );
        // all of the loss is sliding friction: μ P_n times the mean slip speed
        let loss = out.energy_loss;
        assert_relative_eq!(
            out.losses.sliding_friction + out.losses.tangential_spring,
            loss,
            max_relative = 1e-7
        );
        assert!(out.energy_error < 1e-8, "{}", out.energy_error);
    }
}

/// Maw, Barber & Fawcett (1976), Wear 38, 101: the tangential restitution β of the
/// contact point against the normalized angle Ψ = κ tan α / μ, κ = 4G*/E*
/// (= 2(1 − ν)/(2 − ν) for equal materials), for a solid sphere (K = 2/5).
///
/// Where the sphere slides throughout (Ψ ≥ 7κ, the contact point never stops),
/// every Coulomb model gives MBF's line β = −1 + 7κ/Ψ exactly (the impulse ratio
/// is μ): the library must reproduce it to the integration tolerance. Below it
/// MBF resolve the Mindlin-Deresiewicz micro-slip annulus, which LAMMPS's
/// `mindlin` (the model here) does not have (`mindlin_deresiewicz` has it:
/// `tests/micro_slip.rs` checks MBF's figure). So below the line `mindlin` is
/// checked against an independent integration of its own definition
/// ([`mindlin_reference`]): LAMMPS's no-slip spring `k_t a` on the total
/// displacement, capped at `μ F_n`, in explicit time steps.
#[test]
fn maw_barber_fawcett_sliding_line_and_mindlin_below_it() {
    let mu = 0.2;
    let (imp, mut law) = on_flat(mu);
    let shear = EffectiveShear::of_pair(E_Y, NU, E_Y, NU).unwrap().modulus();
    let kappa = 4.0 * shear / effective_modulus_flat();
    assert!((kappa - 2.0 * (1.0 - NU) / (2.0 - NU)).abs() < 1e-12);
    let beta = |psi: f64, law: &mut ElasticContact| {
        let angle = (psi * mu / kappa).atan().to_degrees();
        let out = imp.simulate(law, 0.5, angle, &settings()).unwrap();
        assert!(out.energy_error < 1e-8);
        (out.tangential_restitution.unwrap(), out.slip_switches)
    };
    // the sliding line: beyond Ψ = 7κ the contact point never stops
    for psi in [7.5 * kappa, 10.0, 20.0] {
        let (b, switches) = beta(psi, &mut law);
        assert_eq!(switches, 0, "Ψ = {psi}: slides throughout");
        assert_relative_eq!(b, -1.0 + 7.0 * kappa / psi, max_relative = 1e-8);
    }
    // below it: LAMMPS's mindlin, integrated independently (first order in the
    // step: the extrapolation 2 X(dt/2) − X(dt), within twice the difference of
    // the two runs plus the library's integration error)
    for psi in [0.02, 1.0, 3.0] {
        let angle = (psi * mu / kappa).atan();
        let coarse = mindlin_reference(angle, mu, 4000);
        let fine = mindlin_reference(angle, mu, 8000);
        let expected = 2.0 * fine - coarse;
        let (b, _) = beta(psi, &mut law);
        assert!(
            (b - expected).abs() < 2.0 * (fine - coarse).abs() + 1e-6,
            "Ψ = {psi}: library {b}, reference {expected} (fine {fine}, coarse {coarse})"
        );
    }
}

/// LAMMPS's `mindlin` on a flat, integrated here in explicit steps (`steps` per
/// Hertz contact time, symplectic Euler): Hertz normal force; the stored
/// displacement ξ grows by the contact point's slip `c dt`; the force
/// `−8 G* a ξ` is capped at `μ F_n` with ξ reset to the capped force's elastic
/// part; the contact point's velocity changes by `χ F_t/m dt` (χ = 7/2).
/// Returns β = −c'/c.
fn mindlin_reference(alpha: f64, mu: f64, steps: usize) -> f64 {
    let m = 4.0 / 3.0 * std::f64::consts::PI * RHO * R.powi(3);
    let e_star = effective_modulus_flat();
    let k_t = 8.0 * EffectiveShear::of_pair(E_Y, NU, E_Y, NU).unwrap().modulus();
    let stiff = 4.0 / 3.0 * e_star * R.sqrt();
    let (v, chi) = (0.5, 3.5);
    let (mut vn, mut c) = (v * alpha.cos(), v * alpha.sin());
    let c0 = c;
    let d_max = (1.25 * m * vn * vn / stiff).powf(0.4);
    let dt = 2.9432 * d_max / vn / steps as f64;
    let (mut d, mut xi) = (0.0, 0.0f64);
    loop {
        d += vn * dt;
        if d <= 0.0 {
            break;
        }
        let a = (R * d).sqrt();
        let f_n = stiff * d.powf(1.5);
        xi += c * dt;
        let mut f_t = -k_t * a * xi;
        if f_t.abs() > mu * f_n {
            f_t = f_t.signum() * mu * f_n;
            xi = -f_t / (k_t * a);
        }
        vn -= f_n / m * dt;
        c += chi * f_t / m * dt;
    }
    -c / c0
}

/// A pure twist: a sphere spinning about the line of centres hits a flat head-on
/// (α = 0). No sliding, no rolling; only `marshall`'s twisting torque acts, and
/// while the contact twists in gross slip it is the limit `(2/3) μ a F_n`
/// (Marshall 2009, eq. 44; `F_n0` = the Hertz force, no adhesion or damping). With
/// Hertz's `a = √(Rδ)`, `F_n = (4/3) E* √R δ^{3/2}`, the spin drops by
/// `Δω = (2/3) μ (4/3) E* R ∫δ² dt / I`, and over Hertz's impact (maximum overlap
/// `δ_m = (15 m v² / (16 E* √R))^{2/5}`, `δ̇ = v √(1 − (δ/δ_m)^{5/2})`)
/// `∫δ² dt = 2 ∫₀^{δ_m} δ²/δ̇ dδ = (4/5) B(6/5, 1/2) δ_m³ / v`. The spin stays
/// large enough (4 Δω) that the contact never sticks. The normal motion is
/// untouched and the whole loss is the twisting work.
#[test]
fn pure_twist_decays_by_marshalls_limit() {
    let mu = 0.3;
    let v = 0.5;
    let shear = EffectiveShear::of_pair(E_Y, NU, E_Y, NU).unwrap();
    let friction = Friction::sliding(Tangential::mindlin(shear, 0.0, mu).unwrap())
        .with_twisting(Twisting::Marshall);
    let sphere = Body::solid_sphere(R, RHO).unwrap();
    let e_star = effective_modulus_flat();
    let delta_m = (15.0 * sphere.mass * v * v / (16.0 * e_star * R.sqrt())).powf(0.4);
    let beta = tabor_numerics::special::beta(1.2, 0.5).unwrap();
    let integral = 0.8 * beta * delta_m.powi(3) / v;
    let drop = 2.0 / 3.0 * mu * 4.0 / 3.0 * e_star * R * integral / sphere.moment_of_inertia;
    let spin = 4.0 * drop;
    let imp = ObliqueImpact {
        sphere,
        target: Body::flat(),
        normal: NormalContact::ELASTIC,
        friction: Some(friction),
        sphere_spin: [spin, 0.0, 0.0],
        target_spin: [0.0; 3],
    };
    let mut law = ElasticContact::hertz(e_star, R).unwrap();
    let out = imp.simulate(&mut law, v, 0.0, &settings()).unwrap();
    let w = out.after.sphere.angular_velocity;
    assert_relative_eq!(spin - w[0], drop, max_relative = 1e-9);
    assert!(
        w[1].abs() < 1e-9 * spin && w[2].abs() < 1e-9 * spin,
        "{w:?}"
    );
    assert_relative_eq!(out.normal_restitution, 1.0, max_relative = 1e-8);
    assert_relative_eq!(out.losses.twisting, out.energy_loss, max_relative = 1e-7);
    assert!(out.energy_error < 1e-8, "{}", out.energy_error);
}

/// The stick limit against an independent integration. With a friction
/// coefficient so large that the contact never slides (μ = 10⁸: it could slide
/// only where `F_n < k_t a |ξ|/μ`, below 10⁻⁸ of the maximum overlap), a sphere
/// on a flat with LAMMPS's `mindlin` obeys, with `c` the sliding velocity of the
/// contact point and `ξ` the stored displacement,
///
/// `δ̈ = −(4/3) E* √R δ^{3/2}/m`, `ξ̇ = c`, `ċ = −8 G* √(R δ) ξ (1/m + R²/I)`
///
/// (the torque arm of a wall is R, so the normal motion is Hertz's, and the
/// contact lasts `t_c = 2 (δ_m/v_n) (2/5) B(2/5, 1/2)`). Integrated here by
/// classical Runge-Kutta on N = 4000 and 8000 equal steps over `t_c`; the library
/// (Dormand-Prince with located events) must agree with the finer one within
/// twice their difference plus 10⁻⁸ (its own tolerance, 10⁻⁹). Twice the
/// difference bounds the fine run's error for any convergence order p ≥ 1 (it is
/// diff/(2^p − 1)); `a ∝ √δ` at the ends makes p = 3/2 here, and Richardson's
/// extrapolation at that order lands on the library's β (−1.0407103) to 10⁻⁹.
/// The answer is linear in `c`, so β is the same at every angle: the stick limit
/// MBF's curve tends to as Ψ → 0 (for LAMMPS's `mindlin` on this sphere: the
/// contact point leaves in the direction it came, 4 % faster).
#[test]
fn stick_limit_matches_an_independent_integration() {
    let (imp, mut law) = on_flat(1e8);
    let shear = EffectiveShear::of_pair(E_Y, NU, E_Y, NU).unwrap().modulus();
    let e_star = effective_modulus_flat();
    let (m, inertia) = (imp.sphere.mass, imp.sphere.moment_of_inertia);
    let v = 0.5;
    let beta_rk4 = |alpha: f64, steps: usize| {
        let (vn, c0) = (v * alpha.to_radians().cos(), v * alpha.to_radians().sin());
        let delta_m = (15.0 * m * vn * vn / (16.0 * e_star * R.sqrt())).powf(0.4);
        let b = tabor_numerics::special::beta(0.4, 0.5).unwrap();
        let t_c = 2.0 * delta_m / vn * 0.4 * b;
        let h = t_c / steps as f64;
        // y = [δ, δ̇, ξ, c]
        let rate = |y: [f64; 4]| {
            let d = y[0].max(0.0);
            [
                y[1],
                -4.0 / 3.0 * e_star * R.sqrt() * d.powf(1.5) / m,
                y[3],
                -8.0 * shear * (R * d).sqrt() * y[2] * (1.0 / m + R * R / inertia),
            ]
        };
        let add = |y: [f64; 4], k: [f64; 4], s: f64| std::array::from_fn(|i| y[i] + s * k[i]);
        let mut y = [0.0, vn, 0.0, c0];
        for _ in 0..steps {
            let k1 = rate(y);
            let k2 = rate(add(y, k1, 0.5 * h));
            let k3 = rate(add(y, k2, 0.5 * h));
            let k4 = rate(add(y, k3, h));
            y = std::array::from_fn(|i| {
                y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
            });
        }
        -y[3] / c0
    };
    for alpha in [5.0, 30.0] {
        let (coarse, fine) = (beta_rk4(alpha, 4000), beta_rk4(alpha, 8000));
        let out = imp.simulate(&mut law, v, alpha, &settings()).unwrap();
        let ours = out.tangential_restitution.unwrap();
        let tol = 2.0 * (coarse - fine).abs() + 1e-8;
        assert!(
            (ours - fine).abs() <= tol,
            "α = {alpha}: library β = {ours}, RK4 {fine} (N = 8000), {coarse} (N = 4000), tol {tol:e}"
        );
        assert_eq!(out.slip_switches, 0, "α = {alpha}: the contact sticks");
        assert!(out.energy_error < 1e-8, "{}", out.energy_error);
    }
}

#[test]
fn grazing_frictionless_pair_rebounds_mirrored_about_the_turned_line_of_centres() {
    // Two smooth elastic spheres interact by a central conservative force: the
    // relative orbit is symmetric about its apse line, so the separation velocity
    // mirrors the approach velocity about the line of centres at separation,
    // whatever that line turned through. In the final line of centres e_n = 1,
    // e_t = −1 and the rebound angle equals the impact angle, exactly; in the
    // first-touch axes they would not (the check below shows the turn matters).
    let e_star = E_Y / (2.0 * (1.0 - NU * NU));
    let sphere = Body::solid_sphere(R, RHO).unwrap();
    let imp = ObliqueImpact {
        sphere,
        target: sphere,
        normal: NormalContact::ELASTIC,
        friction: None,
        sphere_spin: [0.0; 3],
        target_spin: [0.0; 3],
    };
    let mut law = ElasticContact::hertz(e_star, R / 2.0).unwrap();
    for &angle in &[80.0, 88.0, 89.5] {
        let out = imp.simulate(&mut law, 1.0, angle, &settings()).unwrap();
        assert!(out.normal_turn > 0.1, "{angle}: turn {}", out.normal_turn);
        assert_relative_eq!(out.normal_restitution, 1.0, max_relative = 1e-7);
        assert_relative_eq!(
            out.tangential_restitution.unwrap(),
            -1.0,
            max_relative = 1e-9
        );
        assert_relative_eq!(out.rebound_angle.unwrap(), angle, max_relative = 1e-9);
        // the first-touch axes: the relative velocity after, u = v_i − v_j
        let u_x = out.after.sphere.velocity[0] - out.after.target.velocity[0];
        let first_touch = -u_x / (angle.to_radians().cos());
        assert!(
            (first_touch - 1.0).abs() > 1e-2,
            "{angle}: the first-touch axes give {first_touch}"
        );
    }
}
