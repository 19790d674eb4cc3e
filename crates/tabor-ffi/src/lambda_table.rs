//! The data of the per-contact-Λ table (`lambda.rs` builds and evaluates it):
//! kept apart so that a contact law can hold the table without the law and the
//! table's builder importing each other.

use crate::table::Table;
use std::sync::{Arc, OnceLock};

/// One node of the grid: the normalized fixed-Λ branch.
#[derive(Debug)]
pub(crate) struct Node {
    pub(crate) table: Arc<Table>,
    /// d̂₀: the snap-off depth, the table origin.
    pub(crate) origin: f64,
    /// 1/L of the node's table coordinate s = √((d̂ − d̂₀)/L).
    pub(crate) inv_length: f64,
    /// u_k = d̂_j − d̂₀ (0 in case 3).
    pub(crate) kink: f64,
    /// U − u_k.
    pub(crate) span: f64,
    /// The most tensile force F̂ (≤ 0).
    pub(crate) pull_off: f64,
}

/// The table over Λ and the branch coordinate (see the module docs). Shared by
/// every contact of a pair of particle types; nodes are built once, on first use,
/// and kept (≈ 165 kB and 60-90 ms each).
#[derive(Debug)]
pub struct LambdaTable {
    pub(crate) k_min: i32,
    pub(crate) nodes: Vec<OnceLock<Node>>,
}
