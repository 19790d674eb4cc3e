//! Chung & Ooi (2011), "Benchmark tests for verifying discrete element modelling
//! codes at particle impact level", Granular Matter 13:643: the paper's Tests 1,
//! 2, 4, 5 and 7 through tabor's scenes (`examples/scenes/chung_ooi/`), with the
//! paper's materials and no fitted parameter, against closed forms, the paper's
//! figures, its finite-element solution (Test 5) and the measurements of Kharaz,
//! Gorham & Salman (2001), Powder Technol. 120:281 (Test 4).
//!
//! Every tolerance is the precision to which the reference is known: the reading
//! of a figure (stated in the reference files' headers), the scatter of a
//! measurement, or the integration's own accuracy against a closed form. The
//! table of `docs/validation/chung_ooi.md` lists the values.
//!
//! Definitions (`/work/shared/spec/tangential.md`): the paper's "tangential
//! coefficient of restitution" is the *centre*-velocity ratio v_t'/v_t, its
//! rebound angle the *contact point's* atan((v_t' + R ω')/v_n'); tabor's
//! `tangential_restitution` is the contact-point ratio −(v_t' + R ω')/(v_t + R ω).
//! In tabor's frame (`tabor_tangential::oblique`) the sphere's contact point
//! moves tangentially at `v_y + R ω_z`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use tabor_dynamics::SimulationSettings;
use tabor_scene::{Format, Scene};

fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/chung_ooi")
}

/// A scene of `examples/scenes/chung_ooi/`, its tangential model replaced by
/// `model` (the files say `mindlin_deresiewicz`).
fn scene(file: &str, model: &str) -> Scene {
    let text = std::fs::read_to_string(dir().join(file)).unwrap();
    let text = text.replace(
        "tangential = \"mindlin_deresiewicz\"",
        &format!("tangential = \"{model}\""),
    );
    Scene::from_str(&text, Format::Toml).unwrap()
}

/// Rows `(x, value)` of `series` and `quantity` in a reference CSV of
/// `examples/scenes/chung_ooi/` (columns series, quantity, x, value; `#` comments).
fn reference(file: &str, series: &str, quantity: &str) -> Vec<(f64, f64)> {
    let text = std::fs::read_to_string(dir().join(file)).unwrap();
    let rows: Vec<(f64, f64)> = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[0] == series && f[1] == quantity)
                .then(|| (f[2].parse().unwrap(), f[3].parse().unwrap()))
        })
        .collect();
    assert!(!rows.is_empty(), "{file}: no {series} {quantity}");
    rows
}

/// The paper's three Test 4 quantities of one impact: the centre ratio
/// v_t'/v_t, the angular velocity ω' (rad/s, the paper's sign: negative) and the
/// contact point's rebound angle (degrees).
#[derive(Clone, Copy, Debug)]
struct Rebound {
    centre_ratio: f64,
    spin: f64,
    rebound_angle: f64,
}

fn rebound(scene: &Scene, speed: f64, angle: f64) -> Rebound {
    let o = scene.oblique(speed, angle).unwrap();
    assert!(o.energy_error < 1e-6, "{angle}: {}", o.energy_error);
    let r = scene.sphere.radius.unwrap();
    let v = o.after.sphere.velocity;
    let w = o.after.sphere.angular_velocity[2];
    Rebound {
        centre_ratio: v[1] / (speed * angle.to_radians().sin()),
        spin: w,
        rebound_angle: ((v[1] + r * w) / -v[0]).atan().to_degrees(),
    }
}

/// `tolerance + |dq/dα| δα`: a reference point known to `tolerance` in value and
/// `delta_angle` (degrees) in angle, the slope of tabor's curve from ±0.5°.
fn allowed(
    scene: &Scene,
    speed: f64,
    angle: f64,
    q: fn(&Rebound) -> f64,
    tolerance: f64,
    delta_angle: f64,
) -> f64 {
    let lo = rebound(scene, speed, (angle - 0.5).max(0.1));
    let hi = rebound(scene, speed, (angle + 0.5).min(89.9));
    tolerance + (q(&hi) - q(&lo)).abs() * delta_angle
}

// ---------------------------------------------------------------- Tests 1, 2

/// Hertz's closed forms for a central elastic impact at relative speed `v` of
/// effective mass `m`, modulus `e_star` and radius `r`: the largest overlap
/// `(15 m v²/(16 E* √R))^(2/5)`, force `(4/3) E* √R δ^(3/2)` and contact time
/// `2 ∫₀¹ dx/√(1 − x^(5/2)) δ/v = (4/5) B(2/5, 1/2) δ/v` (Johnson 1985, §11.4),
/// B(2/5, 1/2) = Γ(2/5)Γ(1/2)/Γ(9/10) = 2.218159543757688 · 1.772453850905516 /
/// 1.068628702119319.
fn hertz(m: f64, e_star: f64, r: f64, v: f64) -> (f64, f64, f64) {
    let d = (15.0 * m * v * v / (16.0 * e_star * r.sqrt())).powf(0.4);
    let beta = 2.218_159_543_757_688 * 1.772_453_850_905_516 / 1.068_628_702_119_319;
    let f = 4.0 / 3.0 * e_star * r.sqrt() * d.powf(1.5);
    (d, f, 0.8 * beta * d / v)
}

/// Tests 1 and 2: the simulated central impact (tabor-dynamics through the
/// scene's Hertz law) gives Hertz's largest overlap, force and contact time to
/// 1e-6 (the integration at 1e-10), with e = 1; and the paper's force-overlap
/// curves (glass, Test 1; aluminium alloy, Test 2, the two curves its figures
/// draw) lie on the scene's force law within their reading, 2 % of the largest
/// force.
#[test]
fn tests_1_and_2_elastic_normal_impacts_are_hertz() {
    let settings = SimulationSettings::with_tolerance(1e-10).unwrap();
    let cases = [
        // file, R*, E*, m*
        (
            "test1_glass.toml",
            0.005,
            4.8e10 / (2.0 * 0.96),
            0.5,
            2800.0,
            0.010,
        ),
        (
            "test1_limestone.toml",
            0.005,
            2.0e10 / (2.0 * 0.9375),
            0.5,
            2500.0,
            0.010,
        ),
        ("test2_al_alloy.toml", 0.1, 7.0e10 / 0.91, 1.0, 2699.0, 0.1),
        (
            "test2_mg_alloy.toml",
            0.1,
            4.0e10 / (1.0 - 0.35 * 0.35),
            1.0,
            1800.0,
            0.1,
        ),
    ];
    for (file, r_star, e_star, mass_factor, rho, r) in cases {
        let s = scene(file, "mindlin_deresiewicz");
        let v = s.speed.unwrap();
        let m = mass_factor * rho * 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
        // the rigid plane is 10^6 times stiffer: E* within 1e-6 of the rigid limit
        let (d, f, t) = hertz(m, e_star, r_star, v);
        let (sim, _) = s.simulate(v, &settings).unwrap();
        eprintln!(
            "{file}: δ_max {:.6e} m (Hertz {d:.6e}), F_max {:.6e} N ({f:.6e}), t_c {:.6e} s ({t:.6e}), e {}",
            sim.max_overlap,
            sim.max_force,
            sim.contact_time.unwrap(),
            sim.restitution
        );
        assert!((sim.max_overlap / d - 1.0).abs() < 3e-6, "{file}");
        assert!((sim.max_force / f - 1.0).abs() < 3e-6, "{file}");
        assert!((sim.contact_time.unwrap() / t - 1.0).abs() < 3e-6, "{file}");
        assert!((sim.restitution - 1.0).abs() < 1e-6, "{file}");
    }
    // the paper's figures: force (kN) against overlap (μm), the loading curve
    let curves: [(&str, &[(f64, f64)]); 2] = [
        (
            "test1_glass.toml",
            &[
                (54.8, 0.968),
                (109.0, 2.70),
                (167.1, 5.07),
                (217.1, 7.52),
                (265.2, 10.18),
            ],
        ),
        (
            "test2_al_alloy.toml",
            &[
                (12.0, 1.303),
                (21.0, 3.10),
                (29.0, 4.97),
                (38.0, 7.57),
                (50.0, 11.33),
            ],
        ),
    ];
    for (file, points) in curves {
        let s = scene(file, "mindlin_deresiewicz");
        let v = s.speed.unwrap();
        let law = s.force_law(v).unwrap();
        let f_max = points.last().unwrap().1 * 1e3;
        for &(d_um, f_kn) in points {
            let f = law.force(d_um * 1e-6, v).unwrap();
            assert!(
                (f - f_kn * 1e3).abs() < 0.02 * f_max,
                "{file}: F({d_um} μm) = {f} N, the paper {f_kn} kN"
            );
        }
    }
}

// ------------------------------------------------------------------- Test 4

const TEST4: &str = "test4_reference.csv";
const KHARAZ: &str = "experiment";

fn centre(r: &Rebound) -> f64 {
    r.centre_ratio
}

fn spin(r: &Rebound) -> f64 {
    r.spin
}

fn angle_of(r: &Rebound) -> f64 {
    r.rebound_angle
}

/// Test 4's speed (m/s), friction coefficient and the sphere's radius (m).
const V4: f64 = 3.9;
const MU4: f64 = 0.092;
const R4: f64 = 2.5e-3;

/// The rigid-body rebound of a solid sphere sliding throughout the contact
/// (χ = 7/2, Coulomb impulse μ(1 + e_n) m v_n; Maw, Barber & Fawcett 1976's
/// large-Ψ line), with tabor's e_n = 1: the centre ratio 1 − μ(1 + e)/tan α,
/// the spin −(5/2) μ (1 + e) v_n/R and the contact point's rebound angle
/// atan((tan α − (7/2) μ (1 + e))/e). Exact for every Coulomb model where the
/// contact point slides throughout: tan α ≥ (7/2) μ (1 + e) (33° here).
fn sliding(alpha: f64) -> Rebound {
    let (e, tan) = (1.0, alpha.to_radians().tan());
    Rebound {
        centre_ratio: 1.0 - MU4 * (1.0 + e) / tan,
        spin: -2.5 * MU4 * (1.0 + e) * V4 * alpha.to_radians().cos() / R4,
        rebound_angle: ((tan - 3.5 * MU4 * (1.0 + e)) / e).atan().to_degrees(),
    }
}

/// True where the contact slides throughout, tan α ≥ (7/2) μ (1 + e).
fn slides_throughout(alpha: f64) -> bool {
    alpha.to_radians().tan() >= 3.5 * MU4 * 2.0
}

/// The experiment's error in `quantity`, from the points where every Coulomb
/// model is the closed form [`sliding`] (no model of the partial slip enters):
/// the largest deviation of the measurements from it. For the ratio that is an
/// error of the measured tangential velocity (m/s), `|Δ ratio| v sin α`, which
/// divides by `v sin α` again at each angle: the ratio is known less well where
/// v_t is small. It contains the scatter of the measurements, the reading of the
/// figure and the difference of Kharaz's e_n ≈ 0.98 from tabor's elastic 1.
fn experimental_error(quantity: &str, q: fn(&Rebound) -> f64) -> f64 {
    reference(TEST4, KHARAZ, quantity)
        .into_iter()
        .filter(|(alpha, _)| slides_throughout(*alpha))
        .map(|(alpha, measured)| {
            let d = (q(&sliding(alpha)) - measured).abs();
            if quantity == "tangential_restitution" {
                d * V4 * alpha.to_radians().sin()
            } else {
                d
            }
        })
        .fold(0.0, f64::max)
}

/// The three quantities of the paper's Test 4 figures.
#[allow(clippy::type_complexity)]
const QUANTITIES: [(&str, fn(&Rebound) -> f64); 3] = [
    ("tangential_restitution", centre),
    ("angular_velocity", spin),
    ("rebound_angle", angle_of),
];

/// Test 4 against the experiment at every measured angle: the centre ratio,
/// the spin and the contact point's rebound angle of tabor's Mindlin-Deresiewicz
/// micro-slip (`mindlin_deresiewicz`, Hertz) lie within the experiment's error
/// ([`experimental_error`]: 0.021 m/s in v_t', 37 rad/s, 2.7°) plus 0.5° of
/// impact angle (the figure's reading, 0.3°, and the angle's setting) times the
/// slope of tabor's curve there. No parameter is fitted: the paper's alumina,
/// μ = 0.092, 3.9 m/s.
///
/// LAMMPS's `mindlin` (no micro-slip) misses the experiment below 5°: the
/// contact sticks from first touch and its spring gives the tangential energy
/// back (centre ratio 1.00 at 2.2° and 4.2°, where Kharaz measured 0.80 and
/// 0.75); its points there are asserted to fall outside the same tolerance.
#[test]
fn test_4_micro_slip_follows_kharaz_at_every_measured_angle() {
    let s = scene("test4_alumina.toml", "mindlin_deresiewicz");
    let dalpha = 0.5;
    for (quantity, q) in QUANTITIES {
        let error = experimental_error(quantity, q);
        eprintln!("test 4 {quantity}: the experiment's error {error:.4}");
        for (alpha, measured) in reference(TEST4, KHARAZ, quantity) {
            let got = q(&rebound(&s, V4, alpha));
            let value_error = if quantity == "tangential_restitution" {
                error / (V4 * alpha.to_radians().sin())
            } else {
                error
            };
            let allowed = allowed(&s, V4, alpha, q, value_error, dalpha);
            eprintln!(
                "test 4 {quantity} {alpha:5.2}°: tabor {got:9.4}, Kharaz {measured:9.4}, |Δ| {:.4} ≤ {allowed:.4}",
                (got - measured).abs()
            );
            assert!(
                (got - measured).abs() <= allowed + 1e-9,
                "{quantity} at {alpha}°: tabor {got}, measured {measured}, allowed {allowed}"
            );
        }
    }
    let mindlin = scene("test4_alumina.toml", "mindlin");
    let error = experimental_error("tangential_restitution", centre);
    for (alpha, measured) in reference(TEST4, KHARAZ, "tangential_restitution") {
        if alpha < 5.0 {
            let got = centre(&rebound(&mindlin, V4, alpha));
            let value_error = error / (V4 * alpha.to_radians().sin());
            let allowed = allowed(&mindlin, V4, alpha, centre, value_error, dalpha);
            eprintln!("test 4 mindlin centre ratio {alpha}°: {got:.4} (Kharaz {measured}, ≤ {allowed:.4})");
            assert!(
                (got - measured).abs() > allowed && got > 0.99,
                "{alpha}: {got}"
            );
        }
    }
}

/// Test 4 against the paper's DEM solution (alumina and aluminium alloy) at 5°:
/// below the sliding line the paper's DEM is a tangential spring without
/// micro-slip: its ratio (0.948 alumina, 0.899 alloy, the paper's figures) is
/// tabor's `mindlin` (0.943, 0.902) and not micro-slip's (0.739, 0.704): asserted
/// within 0.05 of `mindlin` and more than 0.1 from `mindlin_deresiewicz`. (The
/// comparison of the paper's DEM curves on the sliding line is not here: their
/// digitization was not kept; there every Coulomb model is the closed form
/// [`sliding`], which the experiment's test checks.)
#[test]
fn test_4_the_papers_dem_is_a_no_slip_spring() {
    let v = V4;
    for (file, series) in [
        ("test4_alumina.toml", "paper_dem_alumina"),
        ("test4_al_alloy.toml", "paper_dem_al_alloy"),
    ] {
        let mds = scene(file, "mindlin_deresiewicz");
        let mindlin = scene(file, "mindlin");
        let (alpha, paper) = reference(TEST4, series, "tangential_restitution")[0];
        let no_slip = centre(&rebound(&mindlin, v, alpha));
        let micro = centre(&rebound(&mds, v, alpha));
        eprintln!(
            "test 4 {series} {alpha}°: paper {paper}, mindlin {no_slip:.4}, micro-slip {micro:.4}"
        );
        assert!((no_slip - paper).abs() < 0.05 && (micro - paper).abs() > 0.1);
    }
}

// ------------------------------------------------------------------- Test 5

const TEST5: &str = "test5_reference.csv";

/// Test 5's normalized rebound at `x = v_t/(μ v_n)`: the recoil
/// (v_t' + R ω')/(μ v_n') of the contact point and the spin R ω'/(μ v_n).
fn test5(scene: &Scene, x: f64) -> (f64, f64) {
    let (vn, mu) = (5.0, 0.3);
    let vt = x * mu * vn;
    let speed = vn.hypot(vt);
    let angle = vt.atan2(vn).to_degrees();
    let o = scene.oblique(speed, angle).unwrap();
    let r = scene.sphere.radius.unwrap();
    let v = o.after.sphere.velocity;
    let w = o.after.sphere.angular_velocity[2];
    ((v[1] + r * w) / (mu * -v[0]), r * w / (mu * vn))
}

/// The FEM curve's error as drawn (its own discretization and the reading of
/// the figure), from the points where the contact slides throughout (x ≥ 7,
/// tan α ≥ (7/2) μ (1 + e)): the largest deviation of the FEM's spin from the
/// exact rigid-body value −(5/2)(1 + e) = −5 (slope 0 there, so a pure error in
/// value; the FEM's recoil at x → 0, −0.03 where it must vanish, is within it).
fn fem_error() -> f64 {
    reference(TEST5, "fem", "spin")
        .into_iter()
        .filter(|(x, _)| *x >= 7.0)
        .map(|(_, fem)| (fem + 5.0).abs())
        .fold(0.0, f64::max)
}

/// Test 5 against the paper's finite-element solution (steel, ν = 0.3, elastic):
/// with micro-slip both quantities lie on the FEM curve within the FEM's error
/// ([`fem_error`], 0.06, the point that sets it within 10⁻⁹) plus 0.05 of x (the figure's reading) times the slope
/// of tabor's curve, at every FEM point with x ≥ 1.25; in partial slip the
/// contact point's recoil reverses (negative), as the FEM's does.
///
/// Below x = 1.25 the FEM and Maw, Barber & Fawcett's theory disagree: the FEM's
/// recoil is already negative at x = 0.59 and 0.88 (−0.03, −0.08), where MBF's
/// published curve (zero crossing at Ψ = κ x ≈ 0.85, x ≈ 1.03 for ν = 0.3) and
/// tabor (`crates/tabor-tangential/tests/micro_slip.rs` reproduces MBF's figure)
/// are still positive; tabor lies above the FEM there by 0.09, 0.10 and 0.15 at
/// x = 0.59, 0.88, 1.19 (allowed 0.062, 0.070, 0.079). Asserted: the disagreement has that
/// direction. `docs/validation/chung_ooi.md` discusses it.
///
/// LAMMPS's `mindlin` has the opposite sign of the FEM where the FEM's recoil is
/// clearly negative and x < 1.6 (the no-slip spring returns the contact point
/// forward), asserted. Above x ≈ 5.8 (gross sliding) the recoil is the
/// rigid-body line x − 7 and the spin −5 for every model.
#[test]
fn test_5_micro_slip_follows_the_papers_fem() {
    let mds = scene("test5_steel.toml", "mindlin_deresiewicz");
    let mindlin = scene("test5_steel.toml", "mindlin");
    let error = fem_error();
    let dx = 0.05;
    for (quantity, index) in [("recoil", 0usize), ("spin", 1)] {
        let pick = |s: &Scene, x: f64| {
            let r = test5(s, x);
            if index == 0 {
                r.0
            } else {
                r.1
            }
        };
        for (x, fem) in reference(TEST5, "fem", quantity) {
            let got = pick(&mds, x);
            let other = pick(&mindlin, x);
            let slope = (pick(&mds, x + 0.05) - pick(&mds, (x - 0.05).max(0.01))) / 0.1;
            let allowed = error + slope.abs() * dx;
            eprintln!(
                "test 5 {quantity} x = {x:5.2}: micro-slip {got:8.4}, mindlin {other:8.4}, FEM {fem:8.4}, |Δ| {:.4} ≤ {allowed:.4}",
                (got - fem).abs()
            );
            if index == 0 && x < 1.25 {
                assert!(got > fem, "x = {x}: {got} vs FEM {fem}");
            } else {
                assert!(
                    (got - fem).abs() <= allowed + 1e-9,
                    "{quantity} at x = {x}: {got} vs FEM {fem}, allowed {allowed}"
                );
            }
            if index == 0 && fem < -0.2 {
                assert!(got < 0.0, "x = {x}: {got}");
                if x < 1.6 {
                    assert!(other > 0.0, "x = {x}: mindlin {other}");
                }
            }
        }
    }
}

// ------------------------------------------------------------------- Test 7

/// Test 7: two identical spheres meeting head-on with equal and opposite spins
/// ω = (v_n/R) tan θ, θ from 5° to 85° (the paper's 0.175-22.9 rad/s): their
/// contact points move together, so no tangential force acts and the paper's
/// curves are the identity (ω' = ω) and zero (v_t' = 0). tabor, both models,
/// Al alloy and copper: exactly that, to 1e-9 of ωR (nothing approximates a
/// zero force here; the bound is the integration's rounding). With the spins in
/// the same sense (contact points opposing) the spin does change.
#[test]
fn test_7_matched_spins_exchange_nothing() {
    for file in ["test7_al_alloy.toml", "test7_copper.toml"] {
        let text = std::fs::read_to_string(dir().join(file)).unwrap();
        for model in ["mindlin_deresiewicz", "mindlin"] {
            for theta in [5.0f64, 20.0, 45.0, 70.0, 85.0] {
                let w = 0.2 / 0.1 * theta.to_radians().tan();
                let spins = format!(
                    "sphere_spin = [0.0, 0.0, {w}]\ntarget_spin = [0.0, 0.0, {}]",
                    -w
                );
                let t = text
                    .replace("tangential = \"mindlin_deresiewicz\"", &format!("tangential = \"{model}\""))
                    .replace(
                        "sphere_spin = [0.0, 0.0, 2.0]    # rad/s (the tests vary it)\ntarget_spin = [0.0, 0.0, -2.0]",
                        &spins,
                    );
                let s = Scene::from_str(&t, Format::Toml).unwrap();
                let o = s.oblique(0.4, 0.0).unwrap();
                let (v, spin) = (o.after.sphere.velocity, o.after.sphere.angular_velocity);
                let scale = w * 0.1;
                assert!(
                    v[1].abs() < 1e-9 * scale,
                    "{file} {model} {theta}: v_t' {}",
                    v[1]
                );
                assert!(
                    (spin[2] - w).abs() < 1e-9 * w,
                    "{file} {model} {theta}: {spin:?}"
                );
                let t_spin = o.after.target.angular_velocity[2];
                assert!((t_spin + w).abs() < 1e-9 * w, "{file} {model}: {t_spin}");
                // the same spins in the same sense: the contact points oppose,
                // friction acts and the spin changes (the test is not vacuous)
                let same = Scene::from_str(
                    &t.replace(&format!("{}]", -w), &format!("{w}]")),
                    Format::Toml,
                )
                .unwrap()
                .oblique(0.4, 0.0)
                .unwrap();
                let changed = same.after.sphere.angular_velocity[2];
                assert!(
                    (changed - w).abs() > 1e-3 * w,
                    "{file} {model} {theta}: {changed}"
                );
            }
        }
    }
}
