//! `tabor maugis-loss`: the Maugis-Dugdale adhesive loss W(Λ) (seed 000 eq. (5.43),
//! Fig. 5.2) as a tab-separated table.

use serde::Serialize;
use tabor_maugis::{jkr_normalized_loss, loss_over_jkr_fast, normalized_loss, TaborCase};

/// Arguments of `tabor maugis-loss`.
#[derive(clap::Args)]
#[command(
    after_help = "Columns: lambda (the seed's Tabor parameter Λ = d_n/h), case (1, 2 or 3), \
loss (|ΔU_kin| in units of F_n d_n), loss_over_jkr (|ΔU_kin|/|ΔU_JKR|), all with 16 significant digits.\n\
Examples:\n  tabor maugis-loss --lambda 0.3 --lambda 4\n  tabor maugis-loss --from 0.01 --to 100 --points 50 --log"
)]
pub struct Args {
    /// A Tabor parameter Λ (repeatable)
    #[arg(long = "lambda", allow_negative_numbers = true)]
    lambdas: Vec<f64>,
    /// Start of a range of Λ
    #[arg(long, allow_negative_numbers = true, requires_all = ["to", "points"])]
    from: Option<f64>,
    /// End of a range of Λ
    #[arg(long, allow_negative_numbers = true, requires = "from")]
    to: Option<f64>,
    /// Number of points of the range (2 to 1e7)
    #[arg(long, requires = "from")]
    points: Option<usize>,
    /// Space the range logarithmically
    #[arg(long)]
    log: bool,
    /// Relative tolerance of the direct evaluation
    #[arg(long, default_value_t = 1e-12, allow_negative_numbers = true)]
    tolerance: f64,
    /// Use the precomputed fast tier (relative error < 1e-10) instead
    #[arg(long)]
    fast: bool,
    /// Print a JSON array instead of the table
    #[arg(long)]
    json: bool,
}

/// Most points of a range (bounds the table's memory and time).
const MAX_POINTS: usize = 10_000_000;

#[derive(Serialize)]
struct Row {
    lambda: f64,
    case: u8,
    loss: f64,
    loss_over_jkr: f64,
    error_estimate: Option<f64>,
    method: &'static str,
}

fn lambdas(args: &Args) -> Result<Vec<f64>, String> {
    let mut out = args.lambdas.clone();
    if let (Some(from), Some(to), Some(points)) = (args.from, args.to, args.points) {
        if !(2..=MAX_POINTS).contains(&points) {
            return Err(format!(
                "invalid points = {points}: must be at least 2 and at most {MAX_POINTS}"
            ));
        }
        if args.log && !(from > 0.0 && to > 0.0) {
            return Err(format!(
                "invalid range {from}..{to}: --log needs positive ends"
            ));
        }
        for i in 0..points {
            let f = i as f64 / (points - 1) as f64;
            out.push(if args.log {
                from * (to / from).powf(f)
            } else {
                from + (to - from) * f
            });
        }
    }
    if out.is_empty() {
        return Err("give at least one --lambda, or --from/--to/--points".into());
    }
    Ok(out)
}

/// Runs `tabor maugis-loss`.
pub fn run(args: &Args) -> Result<(), String> {
    let mut rows = Vec::new();
    for lambda in lambdas(args)? {
        let row = if args.fast {
            let r = loss_over_jkr_fast(lambda).map_err(|e| e.to_string())?;
            Row {
                lambda,
                case: TaborCase::of(lambda).number(),
                loss: r * jkr_normalized_loss(),
                loss_over_jkr: r,
                error_estimate: None,
                method: "fast tier (Chebyshev interpolant, relative error < 1e-10)",
            }
        } else {
            let w = normalized_loss(lambda, args.tolerance).map_err(|e| e.to_string())?;
            Row {
                lambda,
                case: w.case.number(),
                loss: w.loss,
                loss_over_jkr: w.loss_over_jkr,
                error_estimate: Some(w.error_estimate),
                method: w.method,
            }
        };
        rows.push(row);
    }
    if args.json {
        return crate::output::print_json(&rows);
    }
    println!("lambda\tcase\tloss\tloss_over_jkr");
    for r in rows {
        println!(
            "{:.15e}\t{}\t{:.15e}\t{:.15e}",
            r.lambda, r.case, r.loss, r.loss_over_jkr
        );
    }
    Ok(())
}
