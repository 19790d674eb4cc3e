//! The per-contact state of the time-stepped friction models ([`ContactHistory`],
//! what a DEM engine keeps per pair) and the turning of a stored vector into the
//! current tangent plane; shared by [`crate::step`] and the micro-slip form.

use nalgebra::Vector3;

/// The history of one contact, carried from step to step: zero when the contact
/// forms, discarded when it breaks. `#[repr(C)]` and all doubles, so that a DEM
/// engine can keep it in its per-pair history arrays (13 doubles; LAMMPS's own
/// `pair granular` keeps 3 (+1 for `mindlin_rescale`) + 3 + 3).
///
/// When the roles of `i` and `j` are swapped (LAMMPS `newton` bookkeeping), the
/// vectors change sign and the scalars do not (LAMMPS's
/// `transfer_history_factor`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactHistory {
    /// Accumulated tangential displacement ξ (m), in the tangent plane; for
    /// `mindlin_deresiewicz` the elastic tangential force `T` (N; the force on
    /// body `i` is `−T`), Thornton (1991)'s incremental state
    /// (`crate::micro_slip` docs).
    pub tangential: [f64; 3],
    /// `mindlin_rescale`: the contact radius of the last update (m);
    /// `mindlin_deresiewicz`: the Coulomb limit `μ F_n0` of the last update (N).
    pub tangential_contact_radius: f64,
    /// Accumulated rolling displacement (m), in the tangent plane.
    pub rolling: [f64; 3],
    /// Accumulated twist angle (rad).
    pub twisting: f64,
    /// `mindlin_deresiewicz`: the turning point `T*` (N), the force at the last
    /// reversal of the loading (its direction the axis of the loop); zero while
    /// loading. Mindlin & Deresiewicz (1953), Thornton (1991).
    pub micro_slip_turning: [f64; 3],
    /// `mindlin_deresiewicz`: the turning point `T**` (N) of reloading, the
    /// component along `T*` of the force at the reversal of an unloading.
    pub micro_slip_reversal: f64,
    /// `mindlin_deresiewicz`: 0 loading, 1 unloading from `T*`, 2 reloading from
    /// `T**` (Thornton 1991).
    pub micro_slip_mode: f64,
    /// `mindlin_deresiewicz`: the no-slip stiffness `k_t a` of the last update (N/m).
    pub micro_slip_spring: f64,
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
