//! Shared by the integration tests: a classical RK4 integrator and the coupled
//! JKR + Kuwabara-Kono contact of the bundled polymer grains, written out in SI
//! (independent of tabor's force laws); the effective quantities and the silica
//! pair of the combination tests (`combinations.rs`, `combinations_bundled.rs`);
//! the random scenes of the combination property tests and the properties every
//! outcome has (`combination_properties.rs`, `combination_regressions.rs`); the
//! kinetic energies of the oblique tests' energy bounds.
#![allow(dead_code)]

use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use std::f64::consts::PI;
use tabor_scene::{Format, Outcome, Scene, SceneError};

/// Two silica microspheres (R = 1 µm) at accuracy 1e-10: the pair of the
/// damping tests (`damping.rs`, `damped_oblique.rs`), without interactions.
pub const SILICA: &str = r#"
accuracy = 1e-10
[sphere]
radius = 1e-6
density = 2650
youngs_modulus = 54e9
poisson_ratio = 0.17
[target]
radius = 1e-6
density = 2650
youngs_modulus = 54e9
poisson_ratio = 0.17
"#;

/// The silica pair ([`SILICA`]) with the TOML `extra` after it.
pub fn silica_scene(extra: &str) -> Scene {
    Scene::from_str(&format!("{SILICA}{extra}"), Format::Toml).unwrap()
}

/// One classical Runge-Kutta step of ẍ = acc(x, ẋ).
pub fn rk4(x: f64, u: f64, h: f64, acc: &dyn Fn(f64, f64) -> f64) -> (f64, f64) {
    let k1 = (u, acc(x, u));
    let k2 = (
        u + 0.5 * h * k1.1,
        acc(x + 0.5 * h * k1.0, u + 0.5 * h * k1.1),
    );
    let k3 = (
        u + 0.5 * h * k2.1,
        acc(x + 0.5 * h * k2.0, u + 0.5 * h * k2.1),
    );
    let k4 = (u + h * k3.1, acc(x + h * k3.0, u + h * k3.1));
    (
        x + h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0),
        u + h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1),
    )
}

/// Integrates ẍ = acc(x, ẋ) from (0, v0) with `steps` steps per `time_scale` until
/// `end(x, ẋ)` (positive while in contact) falls to 0 while ẋ < 0; the last step is
/// shortened by bisection to land on the end. Returns the rebound speed, or 0 when
/// ẋ turns positive again (caught: sticks).
pub fn rebound(
    v0: f64,
    time_scale: f64,
    steps: usize,
    acc: &dyn Fn(f64, f64) -> f64,
    end: &dyn Fn(f64, f64) -> f64,
) -> f64 {
    let h = time_scale / steps as f64;
    let (mut x, mut u) = (0.0, v0);
    let mut turned = false;
    for _ in 0..100 * steps {
        let (xn, un) = rk4(x, u, h, acc);
        if un < 0.0 {
            turned = true;
        }
        if turned && un > 0.0 {
            return 0.0;
        }
        if turned && end(xn, un) <= 0.0 {
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                let (xm, um) = rk4(x, u, mid, acc);
                if end(xm, um) > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return -rk4(x, u, hi, acc).1;
        }
        (x, u) = (xn, un);
    }
    panic!("no end of contact");
}

/// Two 5 µm polymer grains (E = 2 MPa, ν = 0.49, ρ = 970 kg/m³, Δγ = 0.04 J/m²,
/// the bundled `polymer_grains_viscoadhesive.toml`) with shear viscosity `eta`
/// (Pa s) on both: JKR (fixed grip) + the Kuwabara-Kono force 2 η_c a ḋ with the
/// JKR contact radius. JKR written out: d(a) = a²/R − √(2πΔγa/E*),
/// F(a) = 4E*a³/(3R) − √(8πΔγE*a³), snap-off at dd/da = 0.
pub struct Grains {
    /// Effective radius R (m).
    pub r: f64,
    /// Effective modulus E* (Pa).
    pub e: f64,
    /// Effective mass m (kg).
    pub m: f64,
    /// Work of adhesion Δγ (J/m²).
    pub dg: f64,
    /// η_c = E* τ with τ = 4η/M (Pa s).
    pub eta_c: f64,
    /// The JKR snap-off radius a_c and depth d_c.
    pub a_c: f64,
    pub d_c: f64,
}

impl Grains {
    pub fn new(eta: f64) -> Self {
        let (r, dg) = (2.5e-6, 0.04);
        let m_body = 2e6 / (1.0 - 0.49 * 0.49);
        let e = m_body / 2.0;
        let tau = 4.0 * eta / m_body;
        let m = 4.0 / 3.0 * PI * 5e-6f64.powi(3) * 970.0 / 2.0;
        let a_c = (PI * dg * r * r / (8.0 * e)).cbrt();
        let mut g = Grains {
            r,
            e,
            m,
            dg,
            eta_c: e * tau,
            a_c,
            d_c: 0.0,
        };
        g.d_c = g.d_of(a_c);
        g
    }

    pub fn d_of(&self, a: f64) -> f64 {
        a * a / self.r - (2.0 * PI * self.dg * a / self.e).sqrt()
    }

    pub fn f_of(&self, a: f64) -> f64 {
        4.0 * self.e * a.powi(3) / (3.0 * self.r) - (8.0 * PI * self.dg * self.e * a.powi(3)).sqrt()
    }

    /// The contact radius on the stable branch a ≥ a_c, where d(a) increases:
    /// bisection.
    pub fn a_of(&self, d: f64) -> f64 {
        let a_c = self.a_c;
        let (mut lo, mut hi) = (a_c, a_c.max((self.r * d.abs()).sqrt()) * 4.0 + a_c);
        while self.d_of(hi) < d {
            hi *= 2.0;
        }
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if self.d_of(mid) < d {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// d̈ = −(F(a) + 2 η_c a ḋ)/m.
    pub fn acc(&self, d: f64, u: f64) -> f64 {
        let a = self.a_of(d.max(self.d_c));
        -(self.f_of(a) + 2.0 * self.eta_c * a * u) / self.m
    }

    /// Positive while in contact: d − d_c.
    pub fn end(&self, d: f64, _u: f64) -> f64 {
        d - self.d_c
    }

    /// The Hertz contact time of the contact at `v0`, 2.87 (m²/(R E*² v0))^(1/5) (s).
    pub fn time_scale(&self, v0: f64) -> f64 {
        2.87 * (self.m * self.m / (self.r * self.e * self.e * v0)).powf(0.2)
    }

    /// The rebound speed at `v0` (0 when the grains stick), `steps` RK4 steps per
    /// contact time.
    pub fn rebound(&self, v0: f64, steps: usize) -> f64 {
        rebound(
            v0,
            self.time_scale(v0),
            steps,
            &|d, u| self.acc(d, u),
            &|d, u| self.end(d, u),
        )
    }
}

// ------------------------------------------------- the combination tests' scenes

/// 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2, written out here.
pub fn e_star(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2)
}

pub fn mass(radius: f64, density: f64) -> f64 {
    4.0 / 3.0 * PI * radius.powi(3) * density
}

/// Mass and moment of inertia (2/5 m r²) of a solid sphere.
pub fn solid_sphere(radius: f64, density: f64) -> (f64, f64) {
    let m = mass(radius, density);
    (m, 0.4 * m * radius * radius)
}

/// The kinetic energy `½ m |v|² + ½ I |ω|²` of a body (the oblique tests' bounds,
/// from the reported motion).
pub fn kinetic_energy(mass: f64, inertia: f64, velocity: &[f64; 3], spin: &[f64; 3]) -> f64 {
    let squared = |v: &[f64; 3]| v.iter().map(|x| x * x).sum::<f64>();
    0.5 * mass * squared(velocity) + 0.5 * inertia * squared(spin)
}

pub fn scene(text: &str) -> Scene {
    Scene::from_str(text, Format::Toml).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

pub fn silica_e() -> f64 {
    e_star(54e9, 0.17, 54e9, 0.17)
}

pub fn silica_m() -> f64 {
    mass(1e-6, 2650.0) / 2.0
}

// -------------------------------------------- the scenes of the property tests

/// A random scene as TOML pieces.
#[derive(Clone, Debug)]
pub struct Spec {
    pub radius: f64,
    pub density: f64,
    pub modulus: f64,
    pub poisson: f64,
    pub target_sphere: bool,
    pub target_modulus: f64,
    pub target_poisson: f64,
    pub work_of_adhesion: Option<f64>,
    pub range: Option<f64>,
    pub load_controlled: bool,
    pub yield_stress: Option<f64>,
    pub plastic_model: &'static str,
    pub superposition: bool,
    pub sphere_viscosity: Option<f64>,
    pub target_viscosity: Option<f64>,
    pub accuracy: f64,
}

impl Spec {
    pub fn toml(&self) -> String {
        let mut s = format!(
            "accuracy = {:e}\n[sphere]\nradius = {:e}\ndensity = {:e}\nyoungs_modulus = {:e}\npoisson_ratio = {}\n",
            self.accuracy, self.radius, self.density, self.modulus, self.poisson
        );
        if let Some(eta) = self.sphere_viscosity {
            s += &format!("viscosity = {eta:e}\n");
        }
        s += &format!(
            "[target]\nyoungs_modulus = {:e}\npoisson_ratio = {}\ndensity = {:e}\n",
            self.target_modulus, self.target_poisson, self.density
        );
        if self.target_sphere {
            s += &format!("radius = {:e}\n", self.radius);
        }
        if let Some(sy) = self.yield_stress {
            s += &format!("yield_stress = {sy:e}\n");
        }
        if let Some(eta) = self.target_viscosity {
            s += &format!("viscosity = {eta:e}\n");
        }
        if let Some(w) = self.work_of_adhesion {
            s += &format!("[adhesion]\nwork_of_adhesion = {w:e}\n");
            if let Some(h) = self.range {
                s += &format!("range = {h:e}\n");
            } else if self.load_controlled {
                s += "separation = \"load-controlled\"\n";
            }
        }
        if self.yield_stress.is_some() {
            s += &format!("[plasticity]\nmodel = \"{}\"\n", self.plastic_model);
            if self.superposition {
                s += "adhesive_model = \"superposition\"\n";
            }
        }
        s
    }

    pub fn scene(&self) -> Result<Scene, SceneError> {
        Scene::from_str(&self.toml(), Format::Toml)
    }

    /// Whether contact mechanics is small-strain at `speed`: the Hertz overlap
    /// d_max = (15 m v²/(16 E* √R))^(2/5) of seed 000 (5.8) at most R, with E*, R
    /// and m written out here.
    pub fn small_strain(&self, speed: f64) -> bool {
        let e = 1.0
            / ((1.0 - self.poisson * self.poisson) / self.modulus
                + (1.0 - self.target_poisson * self.target_poisson) / self.target_modulus);
        let r = if self.target_sphere {
            self.radius / 2.0
        } else {
            self.radius
        };
        let m_sphere = 4.0 / 3.0 * std::f64::consts::PI * self.radius.powi(3) * self.density;
        let m = if self.target_sphere {
            m_sphere / 2.0
        } else {
            m_sphere
        };
        let d_max = (15.0 * m * speed * speed / (16.0 * e * r.sqrt())).powf(0.4);
        d_max <= r
    }
}

/// The properties every outcome has: ε ∈ [0, 1], the loss at most the kinetic
/// energy, `sticks` ⇔ v < v_stick (or at every speed up to the validity limit),
/// and the shares of a sum adding up to the total.
/// A sticking velocity that could not be found fails the property.
pub fn outcome_is_consistent(o: &Outcome, speed: f64) -> Result<(), TestCaseError> {
    prop_assert!((0.0..=1.0).contains(&o.restitution), "{}", o.restitution);
    prop_assert!(o.energy_loss <= o.kinetic_energy * (1.0 + 1e-12));
    prop_assert!(
        !o.warnings
            .iter()
            .any(|w| w.code == "sticking-velocity-unknown"),
        "{:?}",
        o.warnings
    );
    let up_to_limit = o.warnings.iter().any(|w| w.code == "sticks-up-to-limit");
    match o.sticking_velocity {
        None if up_to_limit => prop_assert!(o.sticks, "sticks at every speed, yet rebounds"),
        None => prop_assert!(!o.sticks),
        Some(vc) => {
            // where ε(v) is not monotone (a warning says so), the bodies may rebound in
            // a window below v_c; above v_c they never stick
            let not_monotone = o
                .warnings
                .iter()
                .any(|w| w.code == "restitution-not-monotone");
            if (speed / vc - 1.0).abs() > 1e-6 && !(not_monotone && speed < vc) {
                prop_assert_eq!(o.sticks, speed < vc, "v = {}, v_c = {}", speed, vc);
            }
        }
    }
    // the shares of a sum add up to the total loss, sticking included
    if o.effects
        .iter()
        .filter(|e| e.used)
        .all(|e| e.energy_loss.is_some())
    {
        let sum: f64 = o.effects.iter().filter_map(|e| e.energy_loss).sum();
        prop_assert!(
            (sum - o.energy_loss).abs() <= 1e-9 * o.kinetic_energy,
            "shares {} vs total {}",
            sum,
            o.energy_loss
        );
    }
    Ok(())
}

/// The jump of 1 − ε² (the loss over the kinetic energy) across x, by `eps_at`
/// (ε and the error estimate of 1 − ε²), less the two error estimates.
pub fn jump(x: f64, eps_at: &dyn Fn(f64) -> Option<(f64, f64)>) -> Option<f64> {
    let (lo, e_lo) = eps_at(x * (1.0 - 1e-9))?;
    let (hi, e_hi) = eps_at(x * (1.0 + 1e-9))?;
    Some(((1.0 - lo * lo) - (1.0 - hi * hi)).abs() - e_lo - e_hi)
}
