//! The checks at the C boundary (issue 33): every entry point refuses a
//! non-finite input, a history that no call of this ABI can have written, and an
//! output that is not finite, with [`crate::TABOR_ERR_INVALID`] and a message
//! naming the input and its value. Nothing here changes the contact arithmetic:
//! the checks run before it (inputs, history) and after it (outputs).
//!
//! A law is also probed when it is created ([`probe`]): its force at its own
//! reference radius, at overlaps from the snap-off overlap to 1 % of R*, at rest
//! and at an overlap rate of 1 m/s, must be finite; so absurd coefficients
//! (a damping time of 1e300 s, a Tabor parameter of 1e-300) are refused when the
//! law is built, not on the first contact.

use crate::contact::{ContactModel, TaborContactForces, TaborContactHistory, TaborContactState};
use crate::law::{ContactLaw, TaborForce, TaborHistory};
use crate::{TaborFrictionParams, TaborLawInfo, TaborLawParams};
use tabor_numerics::readable::plain;

/// Why a check failed: the message for `tabor_last_error`.
pub(crate) type Checked = Result<(), String>;

/// The overlap rate (m/s) at which [`probe`] evaluates a law's damping: an
/// impact speed typical of the DEM scenes this ABI serves.
pub(crate) const PROBE_RATE: f64 = 1.0;

fn finite(name: &str, value: f64) -> Checked {
    if value.is_finite() {
        Ok(())
    } else {
        Err(format!("invalid {name} = {}: must be finite", plain(value)))
    }
}

fn finite3(name: &str, v: [f64; 3]) -> Checked {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(format!(
            "invalid {name} = [{}, {}, {}]: every component must be finite",
            plain(v[0]),
            plain(v[1]),
            plain(v[2])
        ))
    }
}

/// Every double of a law's parameters is finite (the constructors check the
/// ranges).
pub(crate) fn law_params(p: &TaborLawParams) -> Checked {
    finite("effective_modulus", p.effective_modulus)?;
    finite("effective_radius", p.effective_radius)?;
    finite("work_of_adhesion", p.work_of_adhesion)?;
    finite("tabor_parameter", p.tabor_parameter)?;
    finite("damping_time", p.damping_time)?;
    finite("damping_value", p.damping_value)?;
    finite("dugdale_range", p.dugdale_range)?;
    finite("cohesive_stress", p.cohesive_stress)
}

/// Every double of the friction parameters is finite.
pub(crate) fn friction_params(f: &TaborFrictionParams) -> Checked {
    finite("tangential_stiffness", f.tangential_stiffness)?;
    finite("tangential_damping", f.tangential_damping)?;
    finite("friction_coefficient", f.friction_coefficient)?;
    finite("rolling_stiffness", f.rolling_stiffness)?;
    finite("rolling_damping", f.rolling_damping)?;
    finite("rolling_coefficient", f.rolling_coefficient)?;
    finite("twisting_stiffness", f.twisting_stiffness)?;
    finite("twisting_damping", f.twisting_damping)?;
    finite("twisting_coefficient", f.twisting_coefficient)
}

/// A new law answers finitely at its reference radius R*: at rest on the whole
/// branch from the snap-off overlap to δ = R*/100, and with the damping at an
/// overlap rate of [`PROBE_RATE`] (a DEM damping law with the mass of a sphere of
/// radius R* and density 1000 kg/m³). The message names the parameters that
/// produced a non-finite force.
pub(crate) fn probe(law: &ContactLaw, p: &TaborLawParams) -> Checked {
    let r = law.effective_radius();
    let s = law.scales(r).map_err(|e| e.to_string())?;
    let info = [
        law.snap_off_overlap_at(&s),
        law.jump_in_overlap_at(&s),
        law.interaction_range_at(&s),
        law.pull_off_force_at(&s),
    ];
    let mass = 1000.0 * 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
    let mass = if mass.is_finite() && mass > 0.0 {
        mass
    } else {
        1.0
    };
    let top = r / 100.0;
    let bottom = info[0].min(0.0);
    let overlaps = (0..=16).map(|i| bottom + (top - bottom) * f64::from(i) / 16.0);
    let law_is = || {
        format!(
            "effective_modulus = {}, effective_radius = {}, work_of_adhesion = {}, \
             tabor_parameter = {}, dugdale_range = {}, cohesive_stress = {}",
            plain(p.effective_modulus),
            plain(p.effective_radius),
            plain(p.work_of_adhesion),
            plain(p.tabor_parameter),
            plain(p.dugdale_range),
            plain(p.cohesive_stress)
        )
    };
    if let Some(bad) = info.iter().find(|x| !x.is_finite()) {
        return Err(format!(
            "invalid contact law: {} give a non-finite snap-off, jump-in, range or \
             pull-off ({}): out of the range the law can represent",
            law_is(),
            plain(*bad)
        ));
    }
    for d in overlaps {
        let mut h = TaborHistory {
            contact: 1.0,
            max_overlap: d.max(0.0),
        };
        let at_rest = law
            .evaluate_with_mass(&s, d, 0.0, mass, &mut h)
            .map_err(|e| {
                format!(
                    "invalid contact law: {} fail at overlap {} m: {e}",
                    law_is(),
                    plain(d)
                )
            })?;
        if !at_rest.elastic_force.is_finite() || !at_rest.contact_radius.is_finite() {
            return Err(format!(
                "invalid contact law: {} give a non-finite force ({} N) at overlap {} m: \
                 out of the range the law can represent",
                law_is(),
                plain(at_rest.elastic_force),
                plain(d)
            ));
        }
        let mut h = TaborHistory {
            contact: 1.0,
            max_overlap: d.max(0.0),
        };
        let moving = law
            .evaluate_with_mass(&s, d, PROBE_RATE, mass, &mut h)
            .map_err(|e| e.to_string())?;
        if !moving.force.is_finite() || !at_rest.force.is_finite() {
            let (name, value) = if p.damping_time != 0.0 {
                ("damping_time", p.damping_time)
            } else {
                ("damping_value", p.damping_value)
            };
            return Err(format!(
                "invalid {name} = {}: the damping force at overlap {} m and overlap rate \
                 {PROBE_RATE} m/s is not finite ({} N)",
                plain(value),
                plain(d),
                plain(moving.force)
            ));
        }
    }
    Ok(())
}

/// A history given to `tabor_law_evaluate*`: finite, `contact` 0 or 1.
pub(crate) fn law_history(h: &TaborHistory) -> Checked {
    flag_and_overlap(h.contact, h.max_overlap)
}

fn flag_and_overlap(contact: f64, max_overlap: f64) -> Checked {
    if contact != 0.0 && contact != 1.0 {
        return Err(format!(
            "invalid history contact = {}: must be 0 or 1 (zero-initialize a new pair's history)",
            plain(contact)
        ));
    }
    finite("history max_overlap", max_overlap)
}

/// A history given to `tabor_contact_step`: its first `len` doubles (those the
/// model uses) finite, `contact` 0 or 1.
pub(crate) fn contact_history(h: &TaborContactHistory, len: usize) -> Checked {
    flag_and_overlap(h.contact, h.max_overlap)?;
    let all = as_doubles(h);
    if let Some(i) = all.iter().take(len).position(|x| !x.is_finite()) {
        return Err(format!(
            "invalid history double {i} = {}: every value must be finite",
            plain(all[i])
        ));
    }
    // the micro-slip bed's header (tabor_tangential::micro_slip): the node
    // spacing and the last squared contact radius are >= 0 (a negative spacing
    // would never be coarsened to the contact's size)
    if len > crate::TABOR_CONTACT_HISTORY_BASE_LEN {
        for (k, name) in [(3, "node spacing"), (4, "last squared contact radius")] {
            let x = h.micro_slip[k];
            if x < 0.0 {
                return Err(format!(
                    "invalid history micro-slip {name} = {}: must be >= 0 (zero for a new contact)",
                    plain(x)
                ));
            }
        }
        // a step leaves a² <= (nodes - 1) Δz (the bed spans the contact)
        let (dz, a0_sq) = (h.micro_slip[3], h.micro_slip[4]);
        let nodes = (crate::TABOR_MICRO_SLIP_LEN - 5) / 2;
        if dz > 0.0 && a0_sq > nodes as f64 * dz {
            return Err(format!(
                "invalid history micro-slip last squared contact radius = {}: beyond the bed of \
                 node spacing {} ({nodes} nodes)",
                plain(a0_sq),
                plain(dz)
            ));
        }
    }
    Ok(())
}

/// The doubles of a contact history, in order.
pub(crate) fn as_doubles(h: &TaborContactHistory) -> &[f64] {
    // SAFETY: TaborContactHistory is #[repr(C)] and made of f64 fields and f64
    // arrays only (no padding), so it is TABOR_CONTACT_HISTORY_LEN contiguous f64
    unsafe {
        std::slice::from_raw_parts(
            (h as *const TaborContactHistory).cast::<f64>(),
            crate::TABOR_CONTACT_HISTORY_LEN,
        )
    }
}

/// The result of `tabor_law_evaluate*` is finite; else the message names the
/// input that made it so (the overlap for the elastic part, the overlap rate for
/// the damping).
pub(crate) fn force(o: &TaborForce, radius: f64, overlap: f64, rate: f64) -> Checked {
    if !o.elastic_force.is_finite() || !o.contact_radius.is_finite() {
        return Err(format!(
            "invalid overlap = {} m: the law gives a non-finite force ({} N) or contact \
             radius ({} m) at effective_radius = {} m",
            plain(overlap),
            plain(o.elastic_force),
            plain(o.contact_radius),
            plain(radius)
        ));
    }
    if !o.force.is_finite() {
        return Err(format!(
            "invalid overlap_rate = {} m/s: the damping force is not finite ({} N) at \
             overlap {} m",
            plain(rate),
            plain(o.force),
            plain(overlap)
        ));
    }
    Ok(())
}

/// The inputs of `tabor_contact_step` that the model does not check itself.
pub(crate) fn state(s: &TaborContactState) -> Checked {
    finite("overlap", s.overlap)?;
    finite3("relative_velocity", s.relative_velocity)?;
    finite3("angular_velocity_i", s.angular_velocity_i)?;
    finite3("angular_velocity_j", s.angular_velocity_j)?;
    finite("time_step", s.time_step)
}

/// The result and the new history of `tabor_contact_step` are finite; else the
/// message names the inputs that made them so.
pub(crate) fn forces(
    o: &TaborContactForces,
    s: &TaborContactState,
    h: &TaborContactHistory,
    model: &ContactModel,
) -> Checked {
    if !o.normal_force.is_finite() || !o.contact_radius.is_finite() {
        return Err(format!(
            "invalid overlap = {} m: the normal force ({} N) or the contact radius ({} m) \
             is not finite (radius_i = {} m, radius_j = {} m, effective_mass = {} kg)",
            plain(s.overlap),
            plain(o.normal_force),
            plain(o.contact_radius),
            plain(s.radius_i),
            plain(s.radius_j),
            plain(s.effective_mass)
        ));
    }
    let outputs = o
        .force
        .iter()
        .chain(&o.torque_i)
        .chain(&o.torque_j)
        .chain([&o.tangential_force, &o.critical_force]);
    let history = as_doubles(h).iter().take(model.history_len());
    if outputs.chain(history).all(|x| x.is_finite()) {
        return Ok(());
    }
    let v = s.relative_velocity;
    let (wi, wj) = (s.angular_velocity_i, s.angular_velocity_j);
    Err(format!(
        "invalid relative_velocity = [{}, {}, {}] m/s, angular_velocity_i = [{}, {}, {}], \
         angular_velocity_j = [{}, {}, {}] rad/s or time_step = {} s: the tangential, \
         rolling or twisting force, a torque or the history is not finite",
        plain(v[0]),
        plain(v[1]),
        plain(v[2]),
        plain(wi[0]),
        plain(wi[1]),
        plain(wi[2]),
        plain(wj[0]),
        plain(wj[1]),
        plain(wj[2]),
        plain(s.time_step)
    ))
}

/// A law's info is finite; else the message names the radius asked for.
pub(crate) fn info(i: &TaborLawInfo, radius: f64) -> Checked {
    let all = [
        i.jump_in_overlap,
        i.snap_off_overlap,
        i.interaction_range,
        i.pull_off_force,
        i.force_scale,
        i.table_force_error,
        i.table_force_relative_error,
    ];
    if all.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(format!(
            "invalid effective_radius = {} m: the law's scales are not finite there",
            plain(radius)
        ))
    }
}

/// The interaction range over radii is finite; else the message names them.
pub(crate) fn reach(reach: f64, r_min: f64, r_max: f64) -> Checked {
    if reach.is_finite() {
        Ok(())
    } else {
        Err(format!(
            "invalid r_max = {} m (r_min = {} m): the interaction range is not finite ({})",
            plain(r_max),
            plain(r_min),
            plain(reach)
        ))
    }
}

/// The doubles of a contact history, in order, writable.
pub(crate) fn as_doubles_mut(h: &mut TaborContactHistory) -> &mut [f64] {
    // SAFETY: as in `as_doubles`; the slice keeps the exclusive borrow of `h`
    unsafe {
        std::slice::from_raw_parts_mut(
            (h as *mut TaborContactHistory).cast::<f64>(),
            crate::TABOR_CONTACT_HISTORY_LEN,
        )
    }
}
