//! The bodies of an oblique impact, what the normal contact adds to its force
//! law, and the problem itself ([`ObliqueImpact`]).

use crate::model::Friction;
use serde::Serialize;
use tabor_restitution::{validate, Result};

/// A rigid body of the impact: a sphere, or a flat (infinite radius, mass and
/// moment of inertia).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Body {
    /// Radius (m); infinite for a flat.
    pub radius: f64,
    /// Mass (kg); infinite for a flat.
    pub mass: f64,
    /// Moment of inertia about the centre (kg m²); infinite for a flat.
    pub moment_of_inertia: f64,
}

impl Body {
    /// A homogeneous solid sphere: m = (4/3)πρR³, I = (2/5) m R².
    pub fn solid_sphere(radius: f64, density: f64) -> Result<Self> {
        let r = validate::positive("radius", radius)?;
        let rho = validate::positive("density", density)?;
        let mass = validate::positive("mass", 4.0 / 3.0 * std::f64::consts::PI * rho * r * r * r)?;
        Ok(Body {
            radius: r,
            mass,
            moment_of_inertia: 0.4 * mass * r * r,
        })
    }

    /// A sphere of given mass (kg) and moment of inertia (kg m²).
    pub fn sphere(radius: f64, mass: f64, moment_of_inertia: f64) -> Result<Self> {
        Ok(Body {
            radius: validate::positive("radius", radius)?,
            mass: validate::positive("mass", mass)?,
            moment_of_inertia: validate::positive("moment_of_inertia", moment_of_inertia)?,
        })
    }

    /// A fixed flat (a half-space that does not move).
    pub fn flat() -> Self {
        Body {
            radius: f64::INFINITY,
            mass: f64::INFINITY,
            moment_of_inertia: f64::INFINITY,
        }
    }

    /// True for a flat.
    pub fn is_flat(&self) -> bool {
        self.radius.is_infinite()
    }
}

/// What the normal contact adds to its force law for the friction models.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct NormalContact {
    /// The pull-off force magnitude (N) of a cohesive law (0 for Hertz); see
    /// [`crate::critical_force`].
    pub pull_off_force: f64,
    /// The coefficient `c` of the normal damping force `F_d = c a^β δ̇`
    /// ([`NormalContact::damping_exponent`] β): with β = 1 (Pa s) the viscous force
    /// (Kuwabara-Kono, seed 000 eq. (5.66): `c = 2 η_c`; LAMMPS `damping
    /// viscoelastic`: `c = η_n0 m_eff`); with β = 1/2 the Tsuji form of LAMMPS's
    /// `damping tsuji` and `coeff_restitution`, `c = α √(m_eff (4/3) E*)`
    /// (`tabor_viscoadhesive::NormalDamping`); 0 without damping. The normal
    /// damping coefficient of the friction models is `c a^β`
    /// ([`NormalContact::damping_at`]).
    pub damping: f64,
    /// The exponent β of the contact radius in `F_d = c a^β δ̇`, in (0, 1]: 1 for
    /// Kuwabara-Kono and `viscoelastic`, 1/2 for the Tsuji form.
    pub damping_exponent: f64,
}

impl NormalContact {
    /// No adhesion, no damping (Hertz).
    pub const ELASTIC: NormalContact = NormalContact {
        pull_off_force: 0.0,
        damping: 0.0,
        damping_exponent: 1.0,
    };

    /// The normal damping coefficient `c a^β` (N s/m) at contact radius `a` (m;
    /// 0 where a ≤ 0): the prefactor of LAMMPS's damping models (seed 000
    /// eq. (5.72) with β = 1/2 of the overlap for `viscoelastic`, 1/4 for Tsuji).
    pub fn damping_at(&self, a: f64) -> f64 {
        if a > 0.0 && self.damping != 0.0 {
            self.damping * a.powf(self.damping_exponent)
        } else {
            0.0
        }
    }

    /// Its rate `β c a^(β−1) ȧ` (N s/m per s) at contact radius `a` (m) changing at
    /// `a_dot` (m/s); 0 where a ≤ 0.
    pub fn damping_rate(&self, a: f64, a_dot: f64) -> f64 {
        if a > 0.0 && self.damping != 0.0 {
            self.damping_exponent * self.damping * a.powf(self.damping_exponent - 1.0) * a_dot
        } else {
            0.0
        }
    }
}

/// The oblique impact: two bodies, the normal contact's extras, the friction (none:
/// frictionless) and the initial spins.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ObliqueImpact {
    /// The moving sphere (body i of LAMMPS's pair).
    pub sphere: Body,
    /// The target: a sphere or a flat (body j).
    pub target: Body,
    /// Pull-off force and damping of the normal contact.
    pub normal: NormalContact,
    /// Friction, rolling and twisting (`None`: frictionless).
    pub friction: Option<Friction>,
    /// Initial angular velocity of the sphere (rad/s, in the frame of the module
    /// docs).
    pub sphere_spin: [f64; 3],
    /// Initial angular velocity of the target (rad/s; ignored for a flat).
    pub target_spin: [f64; 3],
}
