//! The incremental Mindlin-Deresiewicz form of [`crate::Friction::step`] for
//! `tangential mindlin_deresiewicz`: the per-contact history a DEM engine can keep
//! (six doubles beside the tangential force), where the oblique impact
//! ([`crate::oblique`]) integrates the exact spring bed of the method of
//! dimensionality reduction.
//!
//! **The form** (Thornton 1991, Powder Technol. 65:153, eqs. for `θ`; Thornton &
//! Yin 1991; the no-slip rule of Thornton 1991 and Di Renzo & Di Maio 2005, Chem.
//! Eng. Sci. 60:1303): the elastic tangential force `T` (the force on body `i` is
//! `−T`) advances over a step by
//!
//! ```text
//! ΔT = k_t a θ Δs ± ΔL (1 − θ) ê,          L = μ F_n0 (the Coulomb limit)
//! ```
//!
//! with `Δs = v_tr dt` the step's tangential displacement, `ê` the axis of the
//! loading history and, by the state of that history (Mindlin & Deresiewicz 1953),
//!
//! | state | θ³ | sign |
//! |---|---|---|
//! | loading (virgin, or after the memory is wiped) | `1 − (T + ΔL)/L` | + |
//! | unloading from the turning point `T*` | `1 − (T* − T + 2ΔL)/(2L)` | − |
//! | reloading from the turning point `T**` | `1 − (T − T** + 2ΔL)/(2L)` | + |
//!
//! (`T`, `T*`, `T**` the components along `ê`), clamped to `0 ≤ θ ≤ 1`; the turning
//! points follow the limit (`T* += ΔL`, `T** −= ΔL`). Where the contact shrinks
//! (`a < a_old`), `T`, `T*` and `T**` are first scaled by `a/a_old`: the springs
//! leaving the contact take their share of the force (Thornton & Yin 1991's
//! unloading correction, the rule of LAMMPS's `mindlin_rescale`). Where the limit grows faster
//! than the stick force (`k_t a |Δs| ≤ ΔL`) nothing slips, `θ = 1` (Mindlin &
//! Deresiewicz: `|dT| ≤ μ dN`). Unloading that reaches `−T*`, and reloading that
//! reaches `T*`, wipe the memory (loading again); a reversal during reloading
//! starts a new unloading from the current force (the nested loop of the exact
//! theory is not kept). At `|T| = L` the contact slides and the memory is wiped.
//!
//! **Where it is the exact bed to first order.** For Hertz the limit density of the
//! MDR bed (`crate::oblique`, `q(x) = μ F_n0 · 3(a² − x²)/(4a³)`) gives each spring
//! a cap `φ (a² − x²)` with `φ = 3L/(4a³k')` constant; after monotonic loading the
//! bed sticks inside `x < b` and slips in the annulus, and `T/L = 1 − (b/a)³`.
//! A step then adds `k_t b Δs` from the stick zone and `ΔL (1 − b/a)` from the
//! annulus riding on its growing caps: the loading row with `θ = b/a`. The
//! unloading and reloading rows are the same argument for the reversed annulus
//! (half the force range, twice the limit). What the form does not know is the
//! profile of a history that is not one of these (a stick phase under growing
//! load, `k_t a|Δs| ≤ ΔL`, leaves the new edge springs strained less than a slip
//! annulus would): `θ` is inferred from `T` as if the profile were the monotonic
//! one, and a shrinking contact releases a uniform share `Δa/a` of the stick force
//! where the bed releases the strains its edge springs actually carry. The
//! resulting difference from the exact bed over Maw, Barber & Fawcett's range of
//! angles is measured in `tests/micro_slip_step.rs`: the tangential restitution
//! β differs by up to 0.16 at Ψ < 1.7 (the bed's no-slip limit −0.21, this form's
//! −0.36: the profile a stick phase leaves is not known to it), by less than 0.06
//! up to Ψ = 3.5, and by less than 3e-3 from Ψ = 5 to the gross-sliding line, where
//! both are exact (Coulomb). Without the unloading correction the small-Ψ gap is
//! 0.48 (β → −0.75). With adhesion (JKR, the Thornton-Yin limit) the gap is larger
//! where the contact sticks most (silica spheres at 0.3 m/s: β −0.08 against the
//! bed's +0.25 at 5°; `integrations/lammps/test_plugin_friction.py` prints it).
//!
//! **In three dimensions** the axis `ê` is the direction of `T` while loading and
//! of `T*` while unloading or reloading; the whole `Δs` (also its part across the
//! axis) meets the stiffness `k_t a θ`. The stored vectors are turned into the
//! current tangent plane every step, keeping their lengths (as LAMMPS turns its
//! stored displacement).

use crate::history::{rotate_into_plane, ContactHistory};
use nalgebra::Vector3;

/// `micro_slip_mode` of a contact loading (virgin, or with its memory wiped).
pub const LOADING: f64 = 0.0;
/// `micro_slip_mode` of a contact unloading from its turning point `T*`.
pub const UNLOADING: f64 = 1.0;
/// `micro_slip_mode` of a contact reloading from its turning point `T**`.
pub const RELOADING: f64 = 2.0;

/// `(1 − x)^(1/3)` clamped to `[0, 1]`: Thornton's θ from `x` (the used fraction
/// of the limit).
fn theta(x: f64) -> f64 {
    if x.is_nan() {
        return 0.0;
    }
    (1.0 - x).clamp(0.0, 1.0).cbrt()
}

fn unit(v: &Vector3<f64>) -> Option<Vector3<f64>> {
    let n = v.norm();
    (n > 0.0).then(|| v / n)
}

/// Advances the Mindlin-Deresiewicz history `h` by the step's tangential
/// displacement `ds` (m) in the plane normal to `n`, with the no-slip stiffness
/// `k0 = k_t a` (N/m) and the Coulomb limit `limit = μ F_n0` (N) of this step.
/// On return `h.tangential` holds the elastic force `T` (N; the force on body `i`
/// is `−T`), `|T| ≤ limit`; `h.tangential_contact_radius` holds `limit` (the next
/// step's `L_old`). Returns true when the contact slides (`|T| = L`).
/// Thornton (1991); module docs.
pub(crate) fn advance(
    h: &mut ContactHistory,
    n: &Vector3<f64>,
    ds: Vector3<f64>,
    k0: f64,
    limit: f64,
) -> bool {
    let limit = if limit.is_finite() {
        limit.max(0.0)
    } else {
        0.0
    };
    let old_limit = h.tangential_contact_radius;
    h.tangential_contact_radius = limit;
    if k0.is_nan() || k0 <= 0.0 || limit == 0.0 {
        // no contact area (the no-contact branch of Maugis-Dugdale) or no
        // limit: every spring of the bed is released
        wipe(h);
        h.tangential = [0.0; 3];
        h.micro_slip_spring = 0.0;
        return false;
    }
    let dl = limit - old_limit;
    let mut t = rotate_into_plane(Vector3::from(h.tangential), n);
    let mut star = rotate_into_plane(Vector3::from(h.micro_slip_turning), n);
    let old_k = h.micro_slip_spring;
    h.micro_slip_spring = k0;
    if k0 < old_k {
        // the contact shrinks: the springs leaving it take their share of the
        // force (Thornton & Yin 1991's unloading correction, LAMMPS's
        // mindlin_rescale), the turning points with it
        let r = k0 / old_k;
        t *= r;
        star *= r;
        h.micro_slip_reversal *= r;
    }
    let ds = ds - n * n.dot(&ds);
    let mut mode = h.micro_slip_mode;
    let stick = k0 * ds.norm() <= dl;
    if mode == LOADING {
        match unit(&t).or_else(|| unit(&ds)) {
            Some(e) if stick || ds.dot(&e) >= 0.0 || t.norm() == 0.0 => {
                t += loading_step(t.norm(), &e, ds, dl, k0, limit, stick);
            }
            Some(_) => {
                // a reversal: T* is the force reached
                star = t;
                mode = UNLOADING;
            }
            None => {}
        }
    }
    if mode != LOADING {
        let mut e = unit(&star).unwrap_or_else(Vector3::zeros);
        let p = ds.dot(&e);
        if !stick && mode == UNLOADING && p > 0.0 {
            h.micro_slip_reversal = t.dot(&e);
            mode = RELOADING;
        } else if !stick && mode == RELOADING && p < 0.0 {
            // a reversal while reloading: a new unloading from here (on the
            // force's own axis; the outer loop is forgotten)
            star = t;
            e = unit(&star).unwrap_or_else(Vector3::zeros);
            mode = UNLOADING;
        }
        let top = star.norm();
        let along = t.dot(&e);
        if stick {
            t += ds * k0;
        } else if mode == UNLOADING {
            let th = theta((top - along + 2.0 * dl) / (2.0 * limit));
            t += ds * (k0 * th) - e * (dl * (1.0 - th));
        } else {
            let th = theta((along - h.micro_slip_reversal + 2.0 * dl) / (2.0 * limit));
            t += ds * (k0 * th) + e * (dl * (1.0 - th));
        }
        // the turning points follow the limit
        let top = top + dl;
        h.micro_slip_reversal -= dl;
        let along = t.dot(&e);
        if top <= 0.0 || (mode == UNLOADING && along <= -top) || (mode == RELOADING && along >= top)
        {
            mode = LOADING;
        }
        star = e * top.max(0.0);
    }
    let size = t.norm();
    let sliding = size >= limit;
    if sliding {
        t *= limit / size;
        mode = LOADING;
    }
    h.tangential = t.into();
    if mode == LOADING {
        wipe(h);
    } else {
        h.micro_slip_mode = mode;
        h.micro_slip_turning = star.into();
    }
    sliding
}

/// The loading row: `k_t a θ Δs + ΔL (1 − θ) ê` with `θ³ = 1 − (T + ΔL)/L`, or
/// `k_t a Δs` where nothing slips (`stick`).
fn loading_step(
    along: f64,
    e: &Vector3<f64>,
    ds: Vector3<f64>,
    dl: f64,
    k0: f64,
    limit: f64,
    stick: bool,
) -> Vector3<f64> {
    if stick {
        return ds * k0;
    }
    let th = theta((along + dl) / limit);
    ds * (k0 * th) + e * (dl * (1.0 - th))
}

/// Forgets the turning points (loading).
fn wipe(h: &mut ContactHistory) {
    h.micro_slip_mode = LOADING;
    h.micro_slip_turning = [0.0; 3];
    h.micro_slip_reversal = 0.0;
}
