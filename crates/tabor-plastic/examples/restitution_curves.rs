//! Restitution against v0/v_Y for Thornton and the interpolation model (seed 000,
//! Fig. 5.17), tab-separated.
use tabor_plastic::{Interpolation, LoadingLaw, Thornton};

fn main() -> Result<(), tabor_plastic::Error> {
    let interpolation = Interpolation::default();
    println!("v0/v_Y\tthornton\tinterpolation\td_max/d_Y");
    for i in 0..=40 {
        let s = 10f64.powf(f64::from(i) * 0.1);
        println!(
            "{s:.4}\t{:.5}\t{:.5}\t{:.3}",
            Thornton.restitution(s)?,
            interpolation.restitution(s)?,
            interpolation.max_depth_ratio(s)?
        );
    }
    Ok(())
}
