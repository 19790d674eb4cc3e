//! What a contact carries between time steps and what one evaluation returns
//! (re-exported from [`crate::law`]).

/// The state a contact carries from one time step to the next (one per pair of
/// particles in contact). `#[repr(C)]` and all doubles, so that a DEM engine can
/// store it in its per-atom partner arrays.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TaborHistory {
    /// 1 once the contact has formed (jump-in: δ ≥ 0 for Hertz and JKR, δ ≥ −h for
    /// Maugis-Dugdale, seed 000 (5.40)), 0 before and after snap-off. While it is 1
    /// the force follows the adhesive branch down to the snap-off overlap.
    pub contact: f64,
    /// The largest overlap reached since the contact formed (m): the turning point
    /// that separates loading from unloading on the branch (0 when not in contact).
    pub max_overlap: f64,
}

/// What happened to a contact in one evaluation.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TaborForce {
    /// Normal force (N), positive when repulsive: elastic-adhesive plus
    /// Kuwabara-Kono damping.
    pub force: f64,
    /// The elastic-adhesive part of `force` (N), without damping (what the Coulomb
    /// limit of friction is built from, LAMMPS's `Fne`).
    pub elastic_force: f64,
    /// Contact radius a (m) of the branch (0 without contact, and on the no-contact
    /// branch of Maugis-Dugdale).
    pub contact_radius: f64,
    /// 0: nothing happened; 1: the contact formed in this call (jump-in); 2: it broke
    /// (snap-off); 3: it formed and broke in the same call (never for a continuous
    /// trajectory).
    pub event: i32,
}
