//! `tabor maugis-loss`: the Maugis-Dugdale adhesive loss W(Λ) (seed 000 eq. (5.43),
//! Fig. 5.2) as a tab-separated table.

use crate::args::Tolerance;
use crate::output::{message, number, print_json_array, stdout, Outcome, VERSION};
use serde::Serialize;
use tabor::maugis::units::{tabor_parameter_from_maugis, tabor_parameter_from_tabor_mu};
use tabor::maugis::{jkr_normalized_loss, loss_over_jkr_fast, normalized_loss, TaborCase};
use tabor::numerics::tolerance;
use tabor::restitution::Error;

/// Arguments of `tabor maugis-loss`.
#[derive(clap::Args)]
#[command(
    after_help = "Three ways to give the Tabor parameter, each repeatable and mixable:\n  \
--lambda            Willert's (2020) Λ = d_n/h (the column `lambda`)\n  \
--maugis-parameter  Maugis' λ = 2σ0 (R/(πΔγK²))^(1/3), K = 4E*/3; Λ = 0.6861 λ\n  \
--tabor-mu          Tabor's μ = (RΔγ²/(E*² z0³))^(1/3), through the Dugdale equivalence \
λ ≈ 1.157 μ (an approximation)\n\
The range --from/--to/--points is over Λ.\n\n\
Columns (tab-separated, written with the csv crate): lambda (Λ), case (1, 2 or 3), \
loss (|ΔU_kin| in units of F_n d_n), loss_over_jkr (|ΔU_kin|/|ΔU_JKR|), tabor_version; \
numbers in shortest round-trip form (they read back as the same f64).\n\
Examples:\n  tabor maugis-loss --lambda 0.3 --lambda 4\n  tabor maugis-loss --maugis-parameter 1\n  \
tabor maugis-loss --from 0.01 --to 100 --points 50 --log"
)]
pub struct Args {
    /// Willert's (2020) Tabor parameter Λ = d_n/h (repeatable)
    #[arg(long = "lambda", allow_hyphen_values = true)]
    lambdas: Vec<f64>,
    /// Maugis' parameter λ (repeatable); converted to Λ = 0.6861 λ
    #[arg(long = "maugis-parameter", allow_hyphen_values = true)]
    maugis_parameters: Vec<f64>,
    /// Tabor's μ (repeatable); converted to Λ through λ ≈ 1.157 μ
    #[arg(long = "tabor-mu", allow_hyphen_values = true)]
    tabor_mus: Vec<f64>,
    /// Start of a range of Λ
    #[arg(long, allow_hyphen_values = true, requires_all = ["to", "points"])]
    from: Option<f64>,
    /// End of a range of Λ
    #[arg(long, allow_hyphen_values = true, requires = "from")]
    to: Option<f64>,
    /// Number of points of the range (2 to 1e7)
    #[arg(long, requires = "from")]
    points: Option<usize>,
    /// Space the range logarithmically
    #[arg(long)]
    log: bool,
    /// Relative tolerance of the direct evaluation
    #[arg(long, default_value_t = Tolerance(tolerance::DEFAULT_TOLERANCE), allow_hyphen_values = true)]
    tolerance: Tolerance,
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

/// Where a value of Λ came from, to name the flag the user typed in an error.
#[derive(Clone, Copy)]
enum Origin {
    /// `--lambda` (or a point of the range: its ends are `--from`/`--to`).
    Flag(&'static str),
    /// Converted from `--maugis-parameter`/`--tabor-mu` with this value.
    Converted(&'static str, f64),
}

impl Origin {
    /// A library error on Λ, naming the flag it came from.
    fn message(self, e: Error) -> String {
        match (self, e) {
            (
                Origin::Flag(flag),
                Error::InvalidParameter {
                    parameter: "tabor_parameter",
                    value,
                    requirement,
                },
            ) => format!("invalid {flag} = {}: {requirement}", number(value)),
            (
                Origin::Converted(flag, given),
                Error::InvalidParameter {
                    parameter: "tabor_parameter",
                    value,
                    requirement,
                },
            ) => format!(
                "invalid {flag} = {}: gives Λ = {}, which {requirement}",
                number(given),
                number(value)
            ),
            (_, other) => message(other),
        }
    }
}

/// The values of Λ with their origin: first the explicit ones (`--lambda`,
/// `--maugis-parameter`, `--tabor-mu`, in this order), then the range; and how
/// many are explicit.
fn lambdas(args: &Args) -> Result<(Vec<(f64, Origin)>, usize), String> {
    let mut out: Vec<(f64, Origin)> = args
        .lambdas
        .iter()
        .map(|&l| (l, Origin::Flag("--lambda")))
        .collect();
    for &l in &args.maugis_parameters {
        let origin = Origin::Converted("--maugis-parameter", l);
        out.push((tabor_parameter_from_maugis(l).map_err(message)?, origin));
    }
    for &mu in &args.tabor_mus {
        let origin = Origin::Converted("--tabor-mu", mu);
        out.push((tabor_parameter_from_tabor_mu(mu).map_err(message)?, origin));
    }
    let explicit = out.len();
    if let (Some(from), Some(to), Some(points)) = (args.from, args.to, args.points) {
        if !(2..=MAX_POINTS).contains(&points) {
            return Err(format!(
                "invalid --points = {points}: must be at least 2 and at most {MAX_POINTS}"
            ));
        }
        if args.log && !(from > 0.0 && to > 0.0) {
            return Err(format!(
                "invalid range --from {from} --to {to}: --log needs positive ends"
            ));
        }
        for i in 0..points {
            let f = i as f64 / (points - 1) as f64;
            let origin = match i {
                0 => Origin::Flag("--from"),
                i if i + 1 == points => Origin::Flag("--to"),
                // between the ends: valid when both ends are
                _ => Origin::Flag("--from"),
            };
            out.push((
                if args.log {
                    from * (to / from).powf(f)
                } else {
                    from + (to - from) * f
                },
                origin,
            ));
        }
    }
    if out.is_empty() {
        return Err(
            "give at least one --lambda, --maugis-parameter or --tabor-mu, \
             or --from/--to/--points"
                .into(),
        );
    }
    Ok((out, explicit))
}

/// The method of a fast-tier row: the bound of
/// `tabor::maugis::FAST_TIER_RELATIVE_ERROR` (a test keeps the two equal).
const FAST_METHOD: &str = "fast tier (Chebyshev interpolant, relative error < 1e-10)";

fn row(args: &Args, (lambda, origin): (f64, Origin)) -> Result<Row, String> {
    Ok(if args.fast {
        let r = loss_over_jkr_fast(lambda).map_err(|e| origin.message(e))?;
        Row {
            lambda,
            case: TaborCase::of(lambda).number(),
            loss: r * jkr_normalized_loss(),
            loss_over_jkr: r,
            error_estimate: None,
            method: FAST_METHOD,
        }
    } else {
        let w = normalized_loss(lambda, args.tolerance.0).map_err(|e| origin.message(e))?;
        Row {
            lambda,
            case: w.case.number(),
            loss: w.loss,
            loss_over_jkr: w.loss_over_jkr,
            error_estimate: Some(w.error_estimate),
            method: w.method,
        }
    })
}

/// Runs `tabor maugis-loss`. The table is written row by row as it is computed,
/// so a reader that stops early (`| head`) ends the computation. Bad input still
/// prints nothing on stdout: the explicit values and the ends of the range (every
/// point of a range lies between its ends) are evaluated before the first line.
pub fn run(args: &Args) -> Outcome {
    let (lambdas, explicit) = lambdas(args)?;
    if !args.json {
        let mut checked = lambdas[..explicit].to_vec();
        checked.extend(lambdas[explicit..].first());
        checked.extend(lambdas[explicit..].last());
        for point in checked {
            row(args, point)?;
        }
    }
    if args.json {
        let rows = lambdas
            .iter()
            .map(|&point| row(args, point))
            .collect::<Result<Vec<_>, _>>()?;
        return print_json_array(&rows);
    }
    let mut table = csv::WriterBuilder::new()
        .delimiter(b'\t')
        .from_writer(stdout());
    table.write_record(["lambda", "case", "loss", "loss_over_jkr", "tabor_version"])?;
    for point in lambdas {
        let r = row(args, point)?;
        table.write_record([
            number(r.lambda),
            r.case.to_string(),
            number(r.loss),
            number(r.loss_over_jkr),
            VERSION.to_string(),
        ])?;
    }
    table.flush()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::FAST_METHOD;

    #[test]
    fn the_fast_method_states_the_library_bound() {
        let bound = format!("< {:e})", tabor::maugis::FAST_TIER_RELATIVE_ERROR);
        assert!(FAST_METHOD.ends_with(&bound), "{FAST_METHOD} vs {bound}");
    }
}
