//! # tabor-dynamics (work in progress)
