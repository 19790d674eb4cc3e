//! A random sweep of the oblique impact (`Scene::oblique`), the one that found
//! stop 45's defects: scenes of every normal law, damping, tangential model,
//! rolling and twisting resistance, spin, speed and angle, each impact computed
//! at accuracy 1e-10 and 1e-8. It fails on an error other than the documented
//! refusals, a value that is not finite, a ledger off by more than 1e-3 of the
//! energy moved (the kinetic energy, or the sum of the mechanisms' works where a
//! slow adhesive capture converts many times it), or the two accuracies apart by
//! more than 1e-3 in e_n, e_t or the loss (of the energy moved). These bounds
//! are far above the accuracy on purpose: they catch a wrong branch of the
//! simulation (a frozen element: the ledger off by 4e-3, the accuracies 0.35
//! apart; a dropped effect: 2e-3 apart), not the slow convergence of an
//! accuracy of 1e-8 (up to 1.3e-4 in 1 200 impacts).
//!
//! Short in every run (`SHORT` cases); the long sweep is opt-in:
//! `cargo test --release -p tabor-scene --test oblique_sweep -- --ignored`
//! (`TABOR_SWEEP_CASES`, `TABOR_SWEEP_SEED`).
//!
//! Left out of the generator, with the open defect that fails them:
//! `mindlin_rescale` on Maugis-Dugdale (an element sticking into the snap-off
//! ends in "step size underflow": `tabor-tangential/README.md`, "Open").
//!
//! Open at stop 45: the long sweep (seed 1, 2 000 impacts) fails on case 207, a
//! damped Maugis-Dugdale impact (Λ = 0.36, 69.08°, a tangential dashpot) that
//! ends in "step size underflow" at its jump-in (`tabor-tangential/README.md`,
//! "Open").

#![allow(clippy::unwrap_used, clippy::expect_used)]

use proptest::prelude::RngExt;
use proptest::test_runner::{RngAlgorithm, TestRng};
use tabor_scene::{Format, Scene};

/// The cases of every run.
const SHORT: usize = 40;

/// proptest's seeded ChaCha generator (the same sweep on every machine), with
/// the draws the scenes need.
struct Random(TestRng);

impl Random {
    fn new(seed: u64) -> Self {
        let mut bytes = [0u8; 32];
        bytes[..8].copy_from_slice(&seed.to_le_bytes());
        Random(TestRng::from_seed(RngAlgorithm::ChaCha, &bytes))
    }
    fn unit(&mut self) -> f64 {
        self.0.random::<f64>()
    }
    fn between(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }
    fn log_between(&mut self, a: f64, b: f64) -> f64 {
        (a.ln() + (b.ln() - a.ln()) * self.unit()).exp()
    }
    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[((self.unit() * items.len() as f64) as usize).min(items.len() - 1)]
    }
}

/// One random scene (TOML), speed (m/s) and angle (degrees).
fn case(r: &mut Random) -> (String, f64, f64) {
    let radius = r.log_between(1e-7, 1e-2);
    let density = r.between(500.0, 9000.0);
    let modulus = r.log_between(1e6, 4e11);
    let poisson = r.between(0.1, 0.49);
    let body = format!(
        "radius = {radius:e}\ndensity = {density}\nyoungs_modulus = {modulus:e}\npoisson_ratio = {poisson}\n"
    );
    let flat = r.unit() < 0.4;
    let mut text = format!("name = \"sweep\"\n[sphere]\n{body}");
    text += &if flat {
        format!("[target]\nyoungs_modulus = {modulus:e}\npoisson_ratio = {poisson}\n")
    } else {
        format!("[target]\n{body}")
    };
    let adhesion = r.pick(&["none", "load-controlled", "fixed-grip", "maugis"]);
    if adhesion != "none" {
        text += &format!(
            "[adhesion]\nwork_of_adhesion = {:e}\n",
            r.log_between(1e-3, 0.5)
        );
        text += &if adhesion == "maugis" {
            format!("tabor_parameter = {}\n", r.log_between(0.1, 10.0))
        } else {
            format!("separation = \"{adhesion}\"\n")
        };
    }
    match r.pick(&[
        "none",
        "none",
        "tsuji",
        "coeff_restitution",
        "coeff_restitution",
    ]) {
        "tsuji" => {
            text += &format!(
                "[damping]\nmodel = \"tsuji\"\ncoefficient = {}\n",
                r.between(0.05, 1.0)
            )
        }
        "coeff_restitution" => {
            text += &format!(
                "[damping]\nmodel = \"coeff_restitution\"\nrestitution = {}\n",
                r.between(0.05, 0.99)
            )
        }
        _ => {}
    }
    let mut tangential = r.pick(&[
        "mindlin",
        "mindlin_rescale",
        "mindlin_deresiewicz",
        "linear_history",
    ]);
    if tangential == "mindlin_rescale" && adhesion == "maugis" {
        tangential = "mindlin";
    }
    text += &format!(
        "[friction]\ncoefficient = {}\ntangential = \"{tangential}\"\n",
        r.between(0.05, 1.0)
    );
    if tangential == "linear_history" {
        let shear = modulus / (2.0 * (2.0 - poisson));
        text += &format!(
            "tangential_stiffness = {:e}\n",
            8.0 * shear * radius * 1e-3 * r.log_between(0.1, 10.0)
        );
    }
    if r.unit() < 0.5 {
        text += &format!("tangential_damping = {}\n", r.between(0.0, 1.0));
    }
    if r.unit() < 0.3 {
        text += &format!(
            "rolling = {{ stiffness = {:e}, damping = 0.0, coefficient = {} }}\n",
            modulus * radius * 1e-3 * r.log_between(0.1, 10.0),
            r.between(0.01, 0.3)
        );
    }
    if r.unit() < 0.3 {
        text += "twisting = \"marshall\"\n";
    }
    if r.unit() < 0.3 {
        // out of the impact plane only without micro-slip: a history off its
        // line takes the 1024-node bed, seconds an impact
        let (x, y) = if tangential == "mindlin_deresiewicz" {
            (0.0, 0.0)
        } else {
            (r.between(-1.0, 1.0), r.between(-1.0, 1.0))
        };
        text += &format!(
            "[impact]\nsphere_spin = [{x:e}, {y:e}, {:e}]\n",
            r.between(-1.0, 1.0)
        );
    }
    let speed = r.log_between(1e-3, 10.0);
    let angle = r.between(0.0, 89.9);
    (text, speed, angle)
}

/// The documented refusals: a speed beyond the pair's small-strain limit, a
/// scene without a time-domain force law.
fn refused(message: &str) -> bool {
    message.contains("small-strain") || message.contains("no time-domain")
}

/// Runs `cases` impacts from `seed`; the failures, described.
fn sweep(seed: u64, cases: usize) -> Vec<String> {
    let mut r = Random::new(seed);
    let mut failures = Vec::new();
    for i in 0..cases {
        let (text, speed, angle) = case(&mut r);
        let at = |accuracy: &str| {
            Scene::from_str(&format!("accuracy = {accuracy}\n{text}"), Format::Toml)
                .expect("the generated scene parses")
                .oblique(speed, angle)
        };
        let describe = |what: String| format!("case {i} ({speed} m/s, {angle}°): {what}\n{text}");
        let fine = match at("1e-10") {
            Ok(o) => o,
            Err(e) if refused(&e.to_string()) => continue,
            Err(e) => {
                failures.push(describe(format!("error {e}")));
                continue;
            }
        };
        let l = &fine.losses;
        let finite = fine.normal_restitution.is_finite()
            && fine.energy_loss.is_finite()
            && fine.tangential_restitution.is_none_or(f64::is_finite)
            && l.by_mechanism().iter().all(|(_, x)| x.is_finite());
        if !finite {
            failures.push(describe(format!("not finite: {fine:?}")));
            continue;
        }
        // the energy the impact moves: a slow adhesive capture converts many
        // times its kinetic energy (rounding and the motion's error scale with it)
        let moved = l
            .by_mechanism()
            .iter()
            .map(|(_, x)| x.abs())
            .sum::<f64>()
            .max(fine.kinetic_energy);
        let ledger = fine.energy_error * fine.kinetic_energy / moved;
        if ledger > 1e-3 {
            failures.push(describe(format!(
                "ledger off by {ledger:e} of the energy moved"
            )));
        }
        let coarse = match at("1e-8") {
            Ok(o) => o,
            Err(e) => {
                failures.push(describe(format!("error at accuracy 1e-8: {e}")));
                continue;
            }
        };
        let apart = (coarse.normal_restitution - fine.normal_restitution)
            .abs()
            .max(
                (coarse.tangential_restitution.unwrap_or(0.0)
                    - fine.tangential_restitution.unwrap_or(0.0))
                .abs(),
            )
            .max((coarse.energy_loss - fine.energy_loss).abs() / moved);
        if apart > 1e-3 {
            failures.push(describe(format!(
                "accuracies 1e-8 and 1e-10 apart by {apart:e}"
            )));
        }
    }
    failures
}

#[test]
fn a_random_sweep_of_oblique_impacts_answers_consistently() {
    let failures = sweep(45, SHORT);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
#[ignore = "long: 2000 impacts at two accuracies (minutes); run with --ignored"]
fn a_long_random_sweep_of_oblique_impacts_answers_consistently() {
    let env = |name: &str, default: u64| {
        std::env::var(name)
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(default)
    };
    let failures = sweep(
        env("TABOR_SWEEP_SEED", 1),
        env("TABOR_SWEEP_CASES", 2000) as usize,
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
