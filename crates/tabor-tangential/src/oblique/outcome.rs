//! What an oblique impact answers: the motion after it ([`AfterImpact`]) and the
//! outcome ([`ObliqueOutcome`]), assembled from the final state.

use super::energy::EnergyLosses;
use super::state::*;
use nalgebra::Vector3;
use serde::Serialize;
use tabor_dynamics::{BranchChange, ForceLaw};
use tabor_numerics::Cost;
use tabor_restitution::Result;

/// Velocity and angular velocity of one body after the impact.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BodyMotion {
    /// Velocity (m/s) in the centre-of-mass frame.
    pub velocity: [f64; 3],
    /// Angular velocity (rad/s).
    pub angular_velocity: [f64; 3],
}

/// The state of both bodies after the impact (or when they stick).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct AfterImpact {
    /// The sphere.
    pub sphere: BodyMotion,
    /// The target (zero for a flat).
    pub target: BodyMotion,
}

/// The result of one oblique impact.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ObliqueOutcome {
    /// The normal force law's name.
    pub law: String,
    /// Impact speed |v| (m/s).
    pub speed: f64,
    /// Impact angle α (degrees) between the relative velocity and the line of
    /// centres.
    pub angle: f64,
    /// Normal restitution `−u'_n / u_n` of the relative velocity, `u'_n` along
    /// the line of centres at separation (for a flat, the fixed normal); 0 when
    /// the bodies stick.
    pub normal_restitution: f64,
    /// Tangential restitution of the contact point, `−c'_y / c_y` with
    /// `c = u_t − (R_i ω_i + R_j ω_j) × n` (n the normal at first touch, and for
    /// `c'` the normal at separation, turned back onto it); `None`
    /// when the contact point does not slide before the impact (α = 0, no spin)
    /// or the bodies stick.
    pub tangential_restitution: Option<f64>,
    /// Rebound angle (degrees) between the relative velocity after the impact and
    /// the line of centres; `None` when the bodies stick.
    pub rebound_angle: Option<f64>,
    /// True when the bodies stay together (the normal law's decision).
    pub sticks: bool,
    /// The angle (degrees) through which the line of centres turned between
    /// first touch and the end (separation or sticking); 0 for a flat. The
    /// rebound quantities are read in the line of centres at the end, turned
    /// back onto the first-touch axes.
    pub normal_turn: f64,
    /// Velocities and spins after the impact (at the moment of sticking when they
    /// stick).
    pub after: AfterImpact,
    /// Kinetic energy before (translation in the CoM frame and rotation) (J).
    pub kinetic_energy: f64,
    /// Kinetic energy lost (J).
    pub energy_loss: f64,
    /// The loss by mechanism.
    pub losses: EnergyLosses,
    /// |ΔE_kin + Σ losses| / E_kin: the integration's energy error.
    pub energy_error: f64,
    /// Time from contact onset to the end (s).
    pub contact_time: f64,
    /// Stick ↔ slip switches of the tangential force.
    pub slip_switches: usize,
    /// Right-hand-side evaluations and steps.
    pub cost: Cost,
}

impl<'a> Setup<'a> {
    #[allow(clippy::too_many_arguments)]
    pub(super) fn outcome(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        onset: f64,
        decision: BranchChange,
        kinetic0: f64,
        angle: f64,
        cost: Cost,
        slip_switches: usize,
    ) -> Result<ObliqueOutcome> {
        let u = v3(y, U);
        let wi = v3(y, WI);
        let wj = if self.flat {
            Vector3::zeros()
        } else {
            v3(y, WJ)
        };
        let sticks = decision == BranchChange::Stick;
        let kinetic = self.kinetic(y);
        let mut losses = EnergyLosses {
            normal_adhesion: y[EN],
            normal_damping: y[EN + 1],
            sliding_friction: y[EN + 2],
            micro_slip: 0.0,
            tangential_damping: y[EN + 3],
            tangential_spring: y[EN + 4] - y[EN + 2] - y[EN + 3],
            rolling: y[EN + 5],
            twisting: y[EN + 6],
            torque_arm: y[EN + 7],
        };
        if self.imp.friction.is_none() {
            losses.tangential_spring = 0.0;
        }
        // the line of centres, overlap and rate at the end (the springs' store and
        // the frame of the rebound quantities below)
        let (n1, overlap, rate, _) = self.geometry(t, y);
        if let Some(bed) = &self.bed {
            // what is left in the springs (0 once the contact has broken)
            let a = if sticks || law.in_contact() {
                law.contact_radius(overlap, rate)?.max(0.0)
            } else {
                0.0
            };
            let stored = bed.borrow().stored_energy(a);
            losses.micro_slip = losses.tangential_spring - stored;
            losses.tangential_spring = stored;
        }
        let energy_loss = kinetic0 - kinetic;
        let energy_error = (energy_loss - losses.total()).abs() / kinetic0;
        let (fi, fj) = if self.m_j.is_infinite() {
            (1.0, 0.0)
        } else {
            (
                self.m_j / (self.m_i + self.m_j),
                self.m_i / (self.m_i + self.m_j),
            )
        };
        let n0 = -Vector3::x();
        // The rebound quantities are read in the frame of the line of centres at
        // the end: for a pair that line turns while the bodies roll round each
        // other (a grazing adhesive encounter turns it by tens of degrees), and the
        // first-touch axes would mistake the turn for a normal velocity that never
        // separated. The rotation taking the final normal onto the first one maps
        // the final motion into the first-touch axes; a flat never turns.
        let normal_turn = n1.dot(&n0).clamp(-1.0, 1.0).acos();
        let to_first = nalgebra::Rotation3::rotation_between(&n1, &n0)
            .unwrap_or_else(nalgebra::Rotation3::identity);
        let r_j = if self.flat {
            0.0
        } else {
            self.imp.target.radius
        };
        let contact_point = |u: &Vector3<f64>, wi: &Vector3<f64>, wj: &Vector3<f64>| {
            let ut = u - n0 * n0.dot(u);
            (ut - (wi * self.imp.sphere.radius + wj * r_j).cross(&n0))[1]
        };
        let wi0 = Vector3::from(self.imp.sphere_spin);
        let wj0 = if self.flat {
            Vector3::zeros()
        } else {
            Vector3::from(self.imp.target_spin)
        };
        let c0 = contact_point(&self.u0, &wi0, &wj0);
        let u_end = to_first * u;
        let c1 = contact_point(&u_end, &(to_first * wi), &(to_first * wj));
        Ok(ObliqueOutcome {
            law: law.name(),
            speed: self.v,
            angle,
            // bodies that stick do not rebound: no rebound quantities (the state
            // at the moment of sticking is in `after`)
            normal_restitution: if sticks { 0.0 } else { -u_end[0] / self.u0[0] },
            tangential_restitution: (c0 != 0.0 && !sticks).then(|| -c1 / c0),
            rebound_angle: (!sticks).then(|| u_end[1].atan2(-u_end[0]).to_degrees()),
            normal_turn: normal_turn.to_degrees(),
            sticks,
            after: AfterImpact {
                sphere: BodyMotion {
                    velocity: (u * fi).into(),
                    angular_velocity: wi.into(),
                },
                target: BodyMotion {
                    velocity: (-u * fj).into(),
                    angular_velocity: wj.into(),
                },
            },
            kinetic_energy: kinetic0,
            energy_loss,
            losses,
            energy_error,
            contact_time: t - onset,
            slip_switches,
            cost,
        })
    }
}

#[cfg(test)]
impl ObliqueOutcome {
    /// The outcome quantities two integrations of one impact are compared in
    /// (the tests of the reduced and polar states): e_n, e_t (0 where none),
    /// the rebound angle (0 where none) and the contact time, with their names.
    pub(super) fn compared(&self) -> [(&'static str, f64); 4] {
        [
            ("e_n", self.normal_restitution),
            ("e_t", self.tangential_restitution.unwrap_or(0.0)),
            ("rebound angle", self.rebound_angle.unwrap_or(0.0)),
            ("contact time", self.contact_time),
        ]
    }
}
