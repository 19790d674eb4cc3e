//! # tabor-penalty
//!
//! Penalty contact laws for multibody codes (work in progress).
