//! Standard, Kelvin-Maxwell and compressible media: limits, the equivalent
//! Kelvin-Voigt approximation, and independent integrations of the seed's equations.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use tabor_numerics::ode::{solve_until_event, EventDirection, OdeTolerance};
use tabor_visco::{
    compressible_flat, kelvin_maxwell_sphere, kelvin_voigt_flat, kelvin_voigt_sphere,
    standard_flat, standard_sphere, SphereModel,
};

/// The third-order form (5.79) with (5.80), ended by (5.81): d̈ rising to 0. A
/// different formulation from the library's internal-variable form (5.76)-(5.77).
fn third_order(beta: f64, delta: f64) -> f64 {
    let a = 1.0 / (beta * delta);
    let b = 1.0 + 1.0 / beta;
    let sol = solve_until_event(
        |_t, y: &[f64; 3]| [y[1], y[2], -a * y[2] - b * y[1] - a * y[0]],
        |_t, y: &[f64; 3]| y[2],
        EventDirection::Rising,
        0.0,
        [0.0, 1.0, 0.0],
        1e5,
        OdeTolerance::new(1e-11, 1e-13).with_max_step(0.01),
    )
    .unwrap();
    assert!(sol.event_found);
    -sol.y[1]
}

#[test]
fn standard_flat_matches_third_order_form() {
    // Tolerance 1e-7 (both integrations at ≤ 1e-10).
    for &(b, d) in &[
        (1e-3, 0.1),
        (1e-2, 1.0),
        (0.1, 0.3),
        (1.0, 1.0),
        (0.3, 10.0),
        (1.0, 100.0),
    ] {
        let lib = standard_flat::restitution(b, d).unwrap();
        let ode = third_order(b, d);
        assert!((lib - ode).abs() < 1e-7, "β {b}, δ {d}: {lib} vs {ode}");
    }
}

#[test]
fn standard_flat_tends_to_kelvin_voigt_as_beta_vanishes() {
    // β → 0: (5.79) → ẍ + δẋ + x = 0, D = δ/2. The difference falls like β;
    // tolerance 2 β δ (observed ≈ 0.2-0.6 βδ).
    for &d in &[0.1, 0.5, 1.0, 3.0] {
        let kv = kelvin_voigt_flat::restitution(d / 2.0).unwrap();
        for &b in &[1e-3, 1e-4] {
            let e = standard_flat::restitution(b, d).unwrap();
            println!("δ {d}, β {b:e}: standard {e:.9}, Kelvin-Voigt {kv:.9}");
            assert!(
                (e - kv).abs() < 2.0 * b * d.max(1.0),
                "δ {d} β {b}: {e} vs {kv}"
            );
        }
    }
}

/// The equivalent Kelvin-Voigt approximation (5.83) against the exact solution on
/// the (β, δ) grid of the crate README.
#[test]
fn equivalent_kelvin_voigt_error_table() {
    let betas = [1e-3, 1e-2, 0.1, 1.0];
    let deltas = [1e-2, 0.1, 1.0, 10.0, 100.0];
    println!(
        "| β \\ δ | {} |",
        deltas.map(|d| format!("{d:e}")).join(" | ")
    );
    let mut max_all: f64 = 0.0;
    let mut max_small_delta: f64 = 0.0;
    for &b in &betas {
        let mut row = Vec::new();
        for &d in &deltas {
            let exact = standard_flat::restitution(b, d).unwrap();
            let approx = standard_flat::equivalent_restitution(b, d).unwrap();
            let err = approx - exact;
            row.push(format!("{exact:.4} / {approx:.4} ({err:+.1e})"));
            max_all = max_all.max(err.abs());
            if d <= 1.0 {
                max_small_delta = max_small_delta.max(err.abs());
            }
        }
        println!("| {b:e} | {} |", row.join(" | "));
    }
    println!("max |error| overall {max_all:.3e}, for δ <= 1: {max_small_delta:.3e}");
    // The seed: good agreement except for large δ with small β.
    // Observed: 0.090 (β = 1, δ = 1) for δ ≤ 1, 0.594 overall at β = 1e-3, δ = 100.
    assert!(max_small_delta < 0.1, "{max_small_delta}");
    assert!(max_all < 0.65, "{max_all}");
    let corner = standard_flat::restitution(1e-3, 100.0).unwrap()
        - standard_flat::equivalent_restitution(1e-3, 100.0).unwrap();
    assert!(
        (corner.abs() - max_all).abs() < 1e-12,
        "largest error not at small β, large δ"
    );
}

#[test]
fn standard_sphere_tends_to_rigorous_kelvin_voigt() {
    // β → 0 (the continuum MDR solution) against the rigorous Kelvin-Voigt sphere:
    // the difference is O(β) and the only error left (observed ε_std − ε_KV ≈
    // 0.028 β at δ = 0.1, 0.10 β at 0.3, 0.17 β at 1). Asserted: below 0.3 β and
    // falling by a factor 8-12 from β = 1e-3 to 1e-4.
    for &d in &[0.1, 0.3, 1.0] {
        let rig = kelvin_voigt_sphere::restitution(d, SphereModel::Rigorous).unwrap();
        let kk = kelvin_voigt_sphere::restitution(d, SphereModel::KuwabaraKono).unwrap();
        let e3 = standard_sphere::restitution(1e-3, d).unwrap();
        let e4 = standard_sphere::restitution(1e-4, d).unwrap();
        println!(
            "δ {d}: standard (β=1e-3) {e3:.9}, (β=1e-4) {e4:.9}, rigorous KV {rig:.9}, \
             Kuwabara-Kono {kk:.9}; differences {:.2e}, {:.2e}",
            e3 - rig,
            e4 - rig
        );
        assert!((e3 - rig).abs() < 0.3e-3, "δ {d}: {e3} vs {rig}");
        assert!((e4 - rig).abs() < 0.3e-4, "δ {d}: {e4} vs {rig}");
        let ratio = (e3 - rig) / (e4 - rig);
        assert!((8.0..12.0).contains(&ratio), "δ {d}: ratio {ratio}");
        // The MDR (elements leave contact where their line load vanishes, (5.89)) is
        // an independent path to the rigorous restitution law a² = R(d + τḋ): it must
        // single it out, not Kuwabara-Kono (gap 9e-3 ... 2.5e-2 here).
        assert!(
            (e4 - kk).abs() > 100.0 * (e4 - rig).abs(),
            "δ {d}: {e4}, KK {kk}"
        );
    }
}

#[test]
fn maxwell_branch_spheres_behave_as_the_seed_says() {
    // Standard medium: for large δ ε rises again (elastic at short times);
    // Kelvin-Maxwell: ε keeps falling to 0 (Figs. 5.13, 5.14).
    let b = 0.1;
    let s_mid = standard_sphere::restitution(b, 1.0).unwrap();
    let s_big = standard_sphere::restitution(b, 100.0).unwrap();
    assert!(s_big > s_mid, "standard: {s_mid} then {s_big}");
    let k_mid = kelvin_maxwell_sphere::restitution(b, 1.0).unwrap();
    let k_big = kelvin_maxwell_sphere::restitution(b, 100.0).unwrap();
    assert!(
        k_big < k_mid && k_big < 0.05,
        "Kelvin-Maxwell: {k_mid} then {k_big}"
    );
}

/// Γ(x) by the Lanczos approximation (g = 7, 9 terms; relative error below 1e-13
/// for x > 0), written out here so that the first-order constants below do not
/// come from the crate under test.
fn gamma(x: f64) -> f64 {
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        return std::f64::consts::PI / ((std::f64::consts::PI * x).sin() * gamma(1.0 - x));
    }
    let x = x - 1.0;
    let t = x + 7.5;
    let sum = C[0]
        + C[1..]
            .iter()
            .enumerate()
            .map(|(i, c)| c / (x + i as f64 + 1.0))
            .sum::<f64>();
    (2.0 * std::f64::consts::PI).sqrt() * t.powf(x + 0.5) * (-t).exp() * sum
}

fn beta_fn(a: f64, b: f64) -> f64 {
    gamma(a) * gamma(b) / gamma(a + b)
}

#[test]
fn sphere_and_flat_punch_agree_at_one_definition_of_delta() {
    // The two δ differ in definition: flat (5.79) δ_f = η √(8a/(m G∞)) = π τ_c/T_f,
    // sphere (5.90) δ_s = η (R v0/(m² G∞³))^(1/5) = k τ_c/T_s, with τ_c = η/G∞ the
    // creep time of the Kelvin-Voigt limit, T_f = π/ω0 (5.82) and T_s (5.12) the
    // elastic contact times at G∞ (Ẽ = 4G∞), k = (4/5) B(2/5, 1/2) (15/64)^(2/5)
    // = 1.647. The seed (after (5.90)): both "have the same meaning". Compared at
    // one definition, the flat punch's δ = π τ_c/T: δ_s = δ k/π.
    //
    // Independent value of the difference: the first-order losses, (5.61) as D → 0
    // (1 − ε_f ≈ π D = (π/2) δ) and (5.71) (1 − ε_s ≈ c δ_s, c = (32/5) B(3/5, 3/2)
    // (15/64)^(3/5)) give ε_f − ε_s ≈ (c k/π − π/2) δ = 0.2015 δ: the sphere loses
    // 12.8 % more. Asserted: (i) at δ = 1e-3 the gap is that first-order value to
    // 1 % (the remainder is O(δ) relative: observed 0.4 %); (ii) the remainder is
    // second order: it grows 8-12 times from δ = 1e-3 to 1e-2 (observed 10); (iii)
    // at the seed's δ = 0.1 the shape still matters little: the sphere below the
    // flat punch by less than the first-order gap 0.020 and by more than half of it
    // (observed 0.013, for β = 0.1 and 1e-3 alike).
    let pi = std::f64::consts::PI;
    let k = 0.8 * beta_fn(0.4, 0.5) * (15.0_f64 / 64.0).powf(0.4);
    let c = 6.4 * beta_fn(0.6, 1.5) * (15.0_f64 / 64.0).powf(0.6);
    let slope = c * k / pi - pi / 2.0;
    println!("k = {k:.6}, c = {c:.6}, first-order gap (ε_f − ε_s)/δ = {slope:.6}");
    // The gap over its first-order value.
    let ratio = |b: f64, d: f64| {
        let flat = standard_flat::restitution(b, d).unwrap();
        let sph = standard_sphere::restitution(b, d * k / pi).unwrap();
        let r = (flat - sph) / (slope * d);
        println!(
            "β {b}, δ {d}: flat {flat:.9}, sphere (δ_s = {:.5}) {sph:.9}, gap {:.4e}, \
             first order {:.4e}, ratio {r:.4}",
            d * k / pi,
            flat - sph,
            slope * d
        );
        r
    };
    let (r3, r2) = (ratio(0.05, 1e-3), ratio(0.05, 1e-2));
    assert!((r3 - 1.0).abs() < 0.01, "δ 1e-3: {r3}");
    let growth = (r2 - 1.0) / (r3 - 1.0);
    assert!((8.0..12.0).contains(&growth), "remainder growth {growth}");
    for b in [0.1, 1e-3] {
        let r1 = ratio(b, 0.1);
        assert!(r1 > 0.5 && r1 < 1.0, "β {b}, δ 0.1: {r1}");
    }
}

#[test]
fn compressible_tends_to_incompressible() {
    // ν → 1/2 with (5.100): the difference falls like 1 − 2ν (factor ≥ 50 over two
    // decades), and at ν = 0.4999 it is below 2e-4 (1 + D1²).
    for &d1 in &[0.1, 0.3, 1.0, 3.0] {
        let inc = kelvin_voigt_flat::restitution(d1).unwrap();
        let diffs: Vec<f64> = [0.49, 0.499, 0.4999]
            .iter()
            .map(|&nu| {
                let d2 = compressible_flat::bulk_damping_ratio_equal_viscosities(nu, d1).unwrap();
                (compressible_flat::restitution(nu, d1, d2).unwrap() - inc).abs()
            })
            .collect();
        println!("D1 {d1}: |ε(ν) − ε_inc| at ν = 0.49, 0.499, 0.4999: {diffs:?}");
        assert!(diffs[2] < diffs[0] / 50.0, "D1 {d1}: {diffs:?}");
        assert!(diffs[2] < 2e-4 * (1.0 + d1 * d1), "D1 {d1}: {diffs:?}");
    }
}

#[test]
fn incompressible_limit_has_the_smallest_restitution() {
    // Seed, Fig. 5.16: ε is smallest in the incompressible limit; "am stärksten ist der
    // Einfluss im Bereich mittlerer Dämpfungen, wo die relative Differenz zwischen der
    // Lösung für ν = 0,3 und dem inkompressiblen Grenzfall etwa 10 % beträgt". Read
    // as a difference in ε of about 0.1 (10 % of the scale of ε), it holds: the
    // difference ε(0.3) − ε(1/2) peaks at medium damping (D1 ≈ 0.3) at ≈ 0.10.
    // Read as a ratio (ε − ε_inc)/ε it does not: that grows with D1 (printed).
    let mut worst_ratio: f64 = 0.0;
    let (mut peak, mut peak_d1) = (0.0_f64, 0.0);
    for &d1 in &[0.01, 0.03, 0.1, 0.2, 0.3, 0.5, 1.0, 3.0, 10.0] {
        let inc = kelvin_voigt_flat::restitution(d1).unwrap();
        for &nu in &[0.0, 0.2, 0.3, 0.4, 0.45] {
            let d2 = compressible_flat::bulk_damping_ratio_equal_viscosities(nu, d1).unwrap();
            let e = compressible_flat::restitution(nu, d1, d2).unwrap();
            assert!(e > inc, "D1 {d1} ν {nu}: {e} <= {inc}");
            if nu == 0.3 {
                let rel = (e - inc) / e;
                println!(
                    "D1 {d1}: ν = 0.3 {e:.5}, incompressible {inc:.5}, difference {:.4}, \
                     (e − e_inc)/e = {rel:.3}",
                    e - inc
                );
                worst_ratio = worst_ratio.max(rel);
                if e - inc > peak {
                    (peak, peak_d1) = (e - inc, d1);
                }
            }
        }
    }
    println!(
        "ν = 0.3: largest difference {peak:.4} at D1 = {peak_d1}; largest ratio {worst_ratio:.3}"
    );
    assert!((0.1..=1.0).contains(&peak_d1), "peak at D1 = {peak_d1}");
    assert!((peak - 0.1).abs() < 0.02, "peak difference {peak}");
}
