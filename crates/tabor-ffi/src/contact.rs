//! A full granular contact behind the C ABI: a normal law ([`ContactLaw`]) plus
//! the friction, rolling and twisting resistance of `tabor-tangential` (LAMMPS's
//! `pair_style granular` sub-models `tangential`, `rolling`, `twisting`), stepped
//! once per contact and time step by [`ContactModel::step`].
//!
//! The normal law gives the normal force, its elastic part, the contact radius a
//! and the pull-off force, which are what the friction models take from a normal
//! model ([`tabor_tangential::NormalResponse`]): the Mindlin spring `8 G* a`, the
//! Coulomb limit `μ F_n0` with `F_n0 = |F_n,elastic + 2 F_pulloff|` for an adhesive
//! law (JKR: (3/2)πwR*, as LAMMPS's `jkr`; Maugis-Dugdale: the law's own pull-off
//! force) and `|F_n|` for Hertz, and the normal damping coefficient that the
//! tangential damping `x_γ,t` multiplies: `2E*A a` of the Kuwabara-Kono force (seed
//! 000 (5.66)) or the DEM damping law's (`ContactLaw::damping_coefficient`,
//! LAMMPS's `damp_prefactor`). The models themselves are `tabor_tangential::Friction::step`; this
//! module only converts between the C structs and them.

use crate::law::{ContactLaw, TaborHistory};
use nalgebra::Vector3;
use tabor_restitution::{validate, Error, Result};
use tabor_tangential::{
    ContactHistory, ContactKinematics, Friction, NormalResponse, Rolling, Tangential,
    TangentialModel, Twisting,
};

/// [`TaborFrictionParams::tangential_model`]: no friction (normal forces only).
pub const TABOR_TANGENTIAL_NONE: i32 = 0;
/// `tangential linear_history k_t x_γ,t μ` (k_t in N/m).
pub const TABOR_TANGENTIAL_LINEAR_HISTORY: i32 = 1;
/// `tangential mindlin k_t x_γ,t μ` (k_t = 8 G*, Pa: the spring is k_t a).
pub const TABOR_TANGENTIAL_MINDLIN: i32 = 2;
/// `tangential mindlin_rescale k_t x_γ,t μ`.
pub const TABOR_TANGENTIAL_MINDLIN_RESCALE: i32 = 3;
/// `tangential mindlin_deresiewicz k_t x_γ,t μ` (k_t = 8 G*, Pa): Mindlin-Deresiewicz
/// micro-slip on a compact spring bed of the method of dimensionality reduction
/// (`tabor_tangential::micro_slip`, `tabor_tangential::Friction::step`), not a
/// LAMMPS `pair granular` model.
pub const TABOR_TANGENTIAL_MINDLIN_DERESIEWICZ: i32 = 4;
/// [`TaborFrictionParams::rolling_model`]: none.
pub const TABOR_ROLLING_NONE: i32 = 0;
/// `rolling sds k_roll γ_roll μ_roll`.
pub const TABOR_ROLLING_SDS: i32 = 1;
/// [`TaborFrictionParams::twisting_model`]: none.
pub const TABOR_TWISTING_NONE: i32 = 0;
/// `twisting marshall`.
pub const TABOR_TWISTING_MARSHALL: i32 = 1;
/// `twisting sds k_twist γ_twist μ_twist`.
pub const TABOR_TWISTING_SDS: i32 = 2;

/// Number of doubles of the micro-slip bed of `mindlin_deresiewicz`
/// ([`TaborContactHistory::micro_slip`]; `tabor_tangential::micro_slip::BED_LEN`:
/// 5 + 2 × 32 springs).
pub const TABOR_MICRO_SLIP_LEN: usize = 69;

const _: () = assert!(TABOR_MICRO_SLIP_LEN == tabor_tangential::micro_slip::BED_LEN);

/// Number of doubles in a [`TaborContactHistory`].
pub const TABOR_CONTACT_HISTORY_LEN: usize = 10 + TABOR_MICRO_SLIP_LEN;

/// Number of leading doubles of a [`TaborContactHistory`] that a contact
/// without `mindlin_deresiewicz` uses (the rest, the micro-slip bed, stays zero):
/// an engine may keep only these for such contacts ([`ContactModel::history_len`]).
pub const TABOR_CONTACT_HISTORY_BASE_LEN: usize = 10;

/// Friction, rolling and twisting parameters, as LAMMPS's `pair_style granular`
/// names them (SI units).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TaborFrictionParams {
    /// One of `TABOR_TANGENTIAL_*`.
    pub tangential_model: i32,
    /// k_t: 8 G* (Pa) for the Mindlin models (LAMMPS `mindlin NULL` computes
    /// it from E and ν), the spring (N/m) for `linear_history`.
    pub tangential_stiffness: f64,
    /// x_γ,t: tangential damping as a multiple of the normal damping coefficient.
    pub tangential_damping: f64,
    /// Sliding friction coefficient μ.
    pub friction_coefficient: f64,
    /// One of `TABOR_ROLLING_*`.
    pub rolling_model: i32,
    /// k_roll (N/m).
    pub rolling_stiffness: f64,
    /// γ_roll (N s/m).
    pub rolling_damping: f64,
    /// μ_roll.
    pub rolling_coefficient: f64,
    /// One of `TABOR_TWISTING_*`.
    pub twisting_model: i32,
    /// k_twist (N m/rad), `sds` only.
    pub twisting_stiffness: f64,
    /// γ_twist (N m s/rad), `sds` only.
    pub twisting_damping: f64,
    /// μ_twist (m), `sds` only.
    pub twisting_coefficient: f64,
}

/// The state a contact carries from step to step: the normal law's
/// [`TaborHistory`] and the friction models' displacements
/// (`tabor_tangential::ContactHistory`). All doubles, zero for a new pair, reset
/// to zero when the contact breaks. The vectors are in the frame of the call:
/// body i first (swap i and j and they change sign).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TaborContactHistory {
    /// 1 from jump-in to snap-off (see [`TaborHistory::contact`]).
    pub contact: f64,
    /// The turning point (see [`TaborHistory::max_overlap`]) (m).
    pub max_overlap: f64,
    /// Accumulated tangential displacement (m); `mindlin_deresiewicz`: the
    /// elastic tangential force T of the bed (N, the force on body i is −T).
    pub tangential: [f64; 3],
    /// `mindlin_rescale`: the contact radius of the last update (m).
    pub tangential_contact_radius: f64,
    /// Accumulated rolling displacement (m).
    pub rolling: [f64; 3],
    /// Accumulated twist angle (rad).
    pub twisting: f64,
    /// `mindlin_deresiewicz`: the compact spring bed (`tabor_tangential::micro_slip`:
    /// the basis vector e₁ of the tangent plane, the node spacing, the last squared
    /// contact radius, and two components per spring in (e₁, n × e₁); swapping i
    /// and j changes the sign of e₁ and of every second component); zero for
    /// every other model.
    pub micro_slip: [f64; TABOR_MICRO_SLIP_LEN],
}

impl Default for TaborContactHistory {
    fn default() -> Self {
        TaborContactHistory {
            contact: 0.0,
            max_overlap: 0.0,
            tangential: [0.0; 3],
            tangential_contact_radius: 0.0,
            rolling: [0.0; 3],
            twisting: 0.0,
            micro_slip: [0.0; TABOR_MICRO_SLIP_LEN],
        }
    }
}

/// The geometry and motion of one contact at one time step (LAMMPS's
/// conventions: n from body j to body i).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TaborContactState {
    /// Unit normal from body j to body i, (x_i − x_j)/|x_i − x_j|.
    pub normal: [f64; 3],
    /// Overlap δ = R_i + R_j − |x_i − x_j| (m).
    pub overlap: f64,
    /// Radius of body i (m).
    pub radius_i: f64,
    /// Radius of body j (m); `+∞` (C `INFINITY`) for a flat wall: the effective
    /// radius is then R_i, the torque arm R_i and ω_j is ignored (LAMMPS
    /// `fix wall/gran`'s flat wall; `tabor_tangential::ContactKinematics`).
    pub radius_j: f64,
    /// v_i − v_j (m/s).
    pub relative_velocity: [f64; 3],
    /// ω_i (rad/s).
    pub angular_velocity_i: [f64; 3],
    /// ω_j (rad/s).
    pub angular_velocity_j: [f64; 3],
    /// The time step (s) over which the friction displacements advance.
    pub time_step: f64,
    /// 1: advance the friction displacements (a time step); 0: evaluate only
    /// (LAMMPS's setup force call and `single()`).
    pub update_history: i32,
    /// Effective mass m* = m_i m_j/(m_i + m_j) (kg; m_i for a wall): the DEM
    /// damping laws need it (`TABOR_DAMPING_*`), the others ignore it.
    pub effective_mass: f64,
}

/// The forces and torques of one contact at one step.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TaborContactForces {
    /// Force on body i (N): normal plus tangential; body j gets its negative.
    pub force: [f64; 3],
    /// Torque on body i (N m).
    pub torque_i: [f64; 3],
    /// Torque on body j (N m).
    pub torque_j: [f64; 3],
    /// The normal force (N, > 0 repulsive).
    pub normal_force: f64,
    /// The magnitude of the tangential force (N).
    pub tangential_force: f64,
    /// F_n0, the normal force of the Coulomb limits (N).
    pub critical_force: f64,
    /// Contact radius (m).
    pub contact_radius: f64,
    /// As [`crate::TaborForce::event`]: 1 jump-in, 2 snap-off.
    pub event: i32,
    /// 1 when the tangential force is at its Coulomb limit.
    pub sliding: i32,
}

/// A normal law with optional friction: what one pair of particle types uses.
#[derive(Clone, Debug)]
pub struct ContactModel {
    law: ContactLaw,
    friction: Option<Friction>,
}

/// The friction of `p`, `None` for `TABOR_TANGENTIAL_NONE` (then rolling and
/// twisting must be none too: they take their limit and, for `marshall`, their
/// coefficients from the tangential model, as in LAMMPS).
pub fn friction_from_params(p: &TaborFrictionParams) -> Result<Option<Friction>> {
    let model = match p.tangential_model {
        TABOR_TANGENTIAL_NONE => {
            if p.rolling_model != TABOR_ROLLING_NONE || p.twisting_model != TABOR_TWISTING_NONE {
                return Err(Error::invalid(
                    "tangential_model",
                    0.0,
                    "rolling and twisting resistance need a tangential model",
                ));
            }
            return Ok(None);
        }
        TABOR_TANGENTIAL_LINEAR_HISTORY => TangentialModel::LinearHistory,
        TABOR_TANGENTIAL_MINDLIN => TangentialModel::Mindlin,
        TABOR_TANGENTIAL_MINDLIN_RESCALE => TangentialModel::MindlinRescale,
        TABOR_TANGENTIAL_MINDLIN_DERESIEWICZ => TangentialModel::MindlinDeresiewicz,
        other => {
            return Err(Error::invalid(
                "tangential_model",
                f64::from(other),
                "must be one of TABOR_TANGENTIAL_NONE, _LINEAR_HISTORY, _MINDLIN, _MINDLIN_RESCALE, _MINDLIN_DERESIEWICZ",
            ))
        }
    };
    let mut friction = Friction::sliding(Tangential::new(
        model,
        p.tangential_stiffness,
        p.tangential_damping,
        p.friction_coefficient,
    )?);
    match p.rolling_model {
        TABOR_ROLLING_NONE => {}
        TABOR_ROLLING_SDS => {
            friction = friction.with_rolling(Rolling::sds(
                p.rolling_stiffness,
                p.rolling_damping,
                p.rolling_coefficient,
            )?)
        }
        other => {
            return Err(Error::invalid(
                "rolling_model",
                f64::from(other),
                "must be TABOR_ROLLING_NONE or TABOR_ROLLING_SDS",
            ))
        }
    }
    match p.twisting_model {
        TABOR_TWISTING_NONE => {}
        TABOR_TWISTING_MARSHALL => friction = friction.with_twisting(Twisting::Marshall),
        TABOR_TWISTING_SDS => {
            friction = friction.with_twisting(Twisting::sds(
                p.twisting_stiffness,
                p.twisting_damping,
                p.twisting_coefficient,
            )?)
        }
        other => {
            return Err(Error::invalid(
                "twisting_model",
                f64::from(other),
                "must be TABOR_TWISTING_NONE, _MARSHALL or _SDS",
            ))
        }
    }
    Ok(Some(friction))
}

fn vector(name: &'static str, v: [f64; 3]) -> Result<Vector3<f64>> {
    for x in v {
        validate::finite(name, x)?;
    }
    Ok(Vector3::from(v))
}

// The friction part of a TaborContactHistory is laid out as a ContactHistory
// (both `#[repr(C)]`, all doubles), after the two doubles of the normal law.
const FRICTION_OFFSET: usize = std::mem::offset_of!(TaborContactHistory, tangential);
const _: () = {
    use std::mem::{offset_of, size_of};
    assert!(FRICTION_OFFSET == 2 * size_of::<f64>());
    assert!(size_of::<TaborContactHistory>() == FRICTION_OFFSET + size_of::<ContactHistory>());
    assert!(offset_of!(ContactHistory, tangential) == 0);
    assert!(
        offset_of!(TaborContactHistory, tangential_contact_radius) - FRICTION_OFFSET
            == offset_of!(ContactHistory, tangential_contact_radius)
    );
    assert!(
        offset_of!(TaborContactHistory, rolling) - FRICTION_OFFSET
            == offset_of!(ContactHistory, rolling)
    );
    assert!(
        offset_of!(TaborContactHistory, twisting) - FRICTION_OFFSET
            == offset_of!(ContactHistory, twisting)
    );
    assert!(
        offset_of!(TaborContactHistory, micro_slip) - FRICTION_OFFSET
            == offset_of!(ContactHistory, micro_slip)
    );
};

/// The friction models' part of `history`, in place (no copy of the micro-slip
/// bed: it is most of the history).
fn friction_history(history: &mut TaborContactHistory) -> &mut ContactHistory {
    // SAFETY: the compile-time assertions above: from FRICTION_OFFSET on, a
    // TaborContactHistory has exactly the fields of a ContactHistory at the same
    // offsets (all f64: same alignment, every bit pattern valid); the pointer
    // comes from the whole `&mut TaborContactHistory`, whose borrow the result
    // keeps.
    unsafe {
        &mut *(history as *mut TaborContactHistory)
            .cast::<u8>()
            .add(FRICTION_OFFSET)
            .cast::<ContactHistory>()
    }
}

impl ContactModel {
    /// A normal law and its friction (`None`: normal forces only).
    pub fn new(law: ContactLaw, friction: Option<Friction>) -> Self {
        ContactModel { law, friction }
    }

    /// The normal law.
    pub fn law(&self) -> &ContactLaw {
        &self.law
    }

    /// The friction, if any.
    pub fn friction(&self) -> Option<&Friction> {
        self.friction.as_ref()
    }

    /// The leading doubles of a [`TaborContactHistory`] this model uses:
    /// [`TABOR_CONTACT_HISTORY_LEN`] with `mindlin_deresiewicz`, else
    /// [`TABOR_CONTACT_HISTORY_BASE_LEN`] (the micro-slip bed stays zero).
    pub fn history_len(&self) -> usize {
        match &self.friction {
            Some(f) if f.tangential.model == TangentialModel::MindlinDeresiewicz => {
                TABOR_CONTACT_HISTORY_LEN
            }
            _ => TABOR_CONTACT_HISTORY_BASE_LEN,
        }
    }

    /// One time step of one contact: the normal force from the law at the
    /// effective radius R_i R_j/(R_i + R_j) (R_i for a wall, R_j = +∞), then (while the contact lasts) the
    /// tangential force and the torques from `tabor_tangential::Friction::step`;
    /// `history` is advanced (the friction displacements only when
    /// `state.update_history` is 1) and zeroed when the contact breaks.
    ///
    /// Errors (history unchanged): non-finite inputs, radii not > 0, a normal not
    /// of unit length (within 1e-6).
    pub fn step(
        &self,
        state: &TaborContactState,
        history: &mut TaborContactHistory,
    ) -> Result<TaborContactForces> {
        let n = vector("normal", state.normal)?;
        if (n.norm_squared() - 1.0).abs() > 2e-6 {
            return Err(Error::invalid(
                "normal",
                n.norm(),
                "the normal must be a unit vector",
            ));
        }
        let ri = validate::positive("radius_i", state.radius_i)?;
        // +∞: a flat wall (R* = R_i); otherwise finite and > 0
        let rj = if state.radius_j == f64::INFINITY {
            f64::INFINITY
        } else {
            validate::positive("radius_j", state.radius_j)?
        };
        let v = vector("relative_velocity", state.relative_velocity)?;
        let wi = vector("angular_velocity_i", state.angular_velocity_i)?;
        let wj = vector("angular_velocity_j", state.angular_velocity_j)?;
        let dt = validate::non_negative("time_step", state.time_step)?;
        let effective_radius = if rj.is_infinite() {
            ri
        } else {
            ri * rj / (ri + rj)
        };
        let scales = self.law.scales(effective_radius)?;
        let mut normal = TaborHistory {
            contact: history.contact,
            max_overlap: history.max_overlap,
        };
        let f = self.law.evaluate_with_mass(
            &scales,
            state.overlap,
            -n.dot(&v),
            state.effective_mass,
            &mut normal,
        )?;
        let mut out = TaborContactForces {
            normal_force: f.force,
            contact_radius: f.contact_radius,
            event: f.event,
            ..TaborContactForces::default()
        };
        if normal.contact == 0.0 {
            *history = TaborContactHistory::default();
            return Ok(out);
        }
        let mut total = n * f.force;
        if let Some(friction) = &self.friction {
            let fh = friction_history(history);
            let kinematics = ContactKinematics {
                normal: n,
                overlap: state.overlap,
                radius_i: ri,
                radius_j: rj,
                relative_velocity: v,
                angular_velocity_i: wi,
                angular_velocity_j: wj,
            };
            let response = NormalResponse {
                contact_radius: f.contact_radius,
                elastic_force: f.elastic_force,
                total_force: f.force,
                pull_off_force: -self.law.pull_off_force_at(&scales),
                damping_coefficient: self
                    .law
                    .damping_coefficient(state.effective_mass, f.contact_radius),
            };
            let c = friction.step(&kinematics, &response, dt, state.update_history != 0, fh);
            total += c.tangential_force;
            out.torque_i = c.torque_i.into();
            out.torque_j = c.torque_j.into();
            out.tangential_force = c.tangential_force.norm();
            out.critical_force = c.critical_force;
            out.sliding = i32::from(c.sliding);
        }
        history.contact = normal.contact;
        history.max_overlap = normal.max_overlap;
        out.force = total.into();
        Ok(out)
    }
}
