//! Instruction counts of the Maugis-Dugdale loss, for `valgrind --tool=callgrind`.
//!
//! Wall-clock benchmarks (`cargo bench --bench maugis`) are only comparable within
//! one run on a loaded machine; instruction counts are repeatable under load. This
//! program calls one tier `n` times; the cost of one call is the difference of two
//! counts over the difference of their `n` (which removes start-up and table
//! building):
//!
//! ```text
//! cargo build --release -p tabor-maugis --example icount
//! valgrind --tool=callgrind --callgrind-out-file=/dev/null \
//!     target/release/examples/icount fast 2 1000     # then with 2000
//! ```
//!
//! `TIER` is `direct` (`normalized_loss` at tolerance 1e-12; at Λ ≤ Λ1 this is
//! the case-1 closed form (5.44), the baseline of `benches/maugis.rs`) or `fast`
//! (`loss_over_jkr_fast`).

use std::hint::black_box;
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: icount direct|fast LAMBDA CALLS";
    let (Some(tier), Some(lambda), Some(calls)) = (args.get(1), args.get(2), args.get(3)) else {
        eprintln!("{usage}");
        return ExitCode::FAILURE;
    };
    let (Ok(lambda), Ok(calls)) = (lambda.parse::<f64>(), calls.parse::<usize>()) else {
        eprintln!("{usage}: LAMBDA is a number, CALLS a count");
        return ExitCode::FAILURE;
    };
    if let Err(e) = tabor_maugis::prepare_fast_tier() {
        eprintln!("fast tier: {e}");
        return ExitCode::FAILURE;
    }
    let mut sum = 0.0;
    for _ in 0..calls {
        let loss = match tier.as_str() {
            "direct" => tabor_maugis::normalized_loss(black_box(lambda), 1e-12).map(|w| w.loss),
            "fast" => tabor_maugis::loss_over_jkr_fast(black_box(lambda)),
            _ => {
                eprintln!("{usage}: unknown tier {tier:?}");
                return ExitCode::FAILURE;
            }
        };
        match loss {
            Ok(w) => sum += w,
            Err(e) => {
                eprintln!("{e}");
                return ExitCode::FAILURE;
            }
        }
    }
    // printed so the calls cannot be optimized away
    println!("{sum}");
    ExitCode::SUCCESS
}
