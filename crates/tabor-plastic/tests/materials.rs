#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Seed 001's fitted model, and the published comparison cases (seed 000 Table 5.2,
//! seed 001 Table 3: alumina spheres on steel and on aluminium) through every model.

use tabor_dynamics::SimulationSettings;
use tabor_jkr::JkrSphere;
use tabor_plastic::materials::*;
use tabor_plastic::{
    AdhesiveInterpolationImpact, AdhesivePlasticContact, Clamping, DimensionlessFit, Interpolation,
    JacksonGreen, PlasticContact, PlasticImpact, Superposition, Thornton,
};
use tabor_restitution::{impact, ImpactModel};

#[test]
fn seed_001_formula_and_yield_velocity() {
    // Eq. (19) written out, eq. (18) rebuilt from (15)-(17): rho v_y² = c (σ/σ0)^4.5
    // (E/E0)^-3.5 with c = 0.05 Pa, σ0 = 100 MPa, E0 = 100 GPa. 1e-3 relative for
    // v_y (15.81 is rounded), 1e-13 for e.
    let (e, s, rho, m) = (1.4e11, 1.03e9, 3958.226, 2.5e-4);
    let fit = DimensionlessFit::new(e, s, rho, m).unwrap();
    let v_y = (0.05 * (s / 1e8).powf(4.5) * (e / 1e11).powf(-3.5) / rho).sqrt();
    assert!(((fit.yield_velocity() - v_y) / v_y).abs() < 1e-3);
    for &v in &[0.5, 1.0, 3.0] {
        let expected = 1.16 + 0.253 * (s / e).ln() + 0.056 * (e / (rho * v * v)).ln();
        let got = fit.restitution(v).unwrap();
        assert!(v > fit.yield_velocity());
        assert!(
            (got.restitution - expected).abs() < 1e-13,
            "{got:?} vs {expected}"
        );
        assert_eq!(got.clamping, Clamping::None);
        // and through the core's (5.37)
        assert!((impact(&fit, v).unwrap().restitution - expected).abs() < 1e-12);
    }
    // e = 1 below v_y
    assert_eq!(
        fit.restitution(0.99 * fit.yield_velocity())
            .unwrap()
            .restitution,
        1.0
    );
    assert_eq!(
        impact(&fit, 0.5 * fit.yield_velocity())
            .unwrap()
            .restitution,
        1.0
    );
}

#[test]
fn seed_001_clamps_and_says_so() {
    let fit = DimensionlessFit::new(1.4e11, 1.03e9, 3958.226, 2.5e-4).unwrap();
    // Just above v_y the fit exceeds 1 for this material (3 % at v_y).
    let just_above = fit.restitution(1.0001 * fit.yield_velocity()).unwrap();
    assert!(just_above.formula_value > 1.0);
    assert_eq!(just_above.clamping, Clamping::ToOne);
    assert_eq!(just_above.restitution, 1.0);
    // At absurd speed it goes negative: clamped to 0 (sticking).
    let fast = fit.restitution(1e9).unwrap();
    assert_eq!(fast.clamping, Clamping::ToZero);
    assert_eq!(fast.restitution, 0.0);
    assert!(impact(&fit, 1e9).unwrap().sticks);
}

struct Case {
    name: &'static str,
    modulus: f64,
    yield_stress: f64,
    poisson_ratio: f64,
    density: f64,
}

fn cases() -> Vec<Case> {
    let rho_000 = SPHERE_MASS_SECTION_5_5_2
        / (4.0 / 3.0 * std::f64::consts::PI * SPHERE_RADIUS_SECTION_5_5_2.powi(3));
    vec![
        Case {
            name: "Table 5.2 alumina/steel",
            modulus: ALUMINA_TABLE_5_2
                .effective_modulus_with(&STEEL_TABLE_5_2)
                .unwrap(),
            yield_stress: STEEL_TABLE_5_2.yield_stress.unwrap(),
            poisson_ratio: STEEL_TABLE_5_2.poisson_ratio,
            density: rho_000,
        },
        Case {
            name: "Table 5.2 alumina/aluminium",
            modulus: ALUMINA_TABLE_5_2
                .effective_modulus_with(&ALUMINIUM_TABLE_5_2)
                .unwrap(),
            yield_stress: ALUMINIUM_TABLE_5_2.yield_stress.unwrap(),
            poisson_ratio: ALUMINIUM_TABLE_5_2.poisson_ratio,
            density: rho_000,
        },
        Case {
            name: "Table 3 alumina/steel",
            modulus: ALUMINA_TABLE_3
                .effective_modulus_with(&STEEL_TABLE_3)
                .unwrap(),
            yield_stress: STEEL_TABLE_3.yield_stress.unwrap(),
            poisson_ratio: STEEL_TABLE_3.poisson_ratio,
            density: ALUMINA_TABLE_3.density.unwrap(),
        },
        Case {
            name: "Table 3 alumina/aluminium",
            modulus: ALUMINA_TABLE_3
                .effective_modulus_with(&ALUMINIUM_TABLE_3)
                .unwrap(),
            yield_stress: ALUMINIUM_TABLE_3.yield_stress.unwrap(),
            poisson_ratio: ALUMINIUM_TABLE_3.poisson_ratio,
            density: ALUMINA_TABLE_3.density.unwrap(),
        },
    ]
}

#[test]
fn published_cases_run_through_every_model() {
    // The sphere of seed 000 section 5.5.2: R = 2.5 mm, m = 0.25 g, on a plate
    // (effective radius R, reduced mass m). Work of adhesion 0.5 J/m² for the
    // adhesive models (no value in the seeds; adhesion is negligible at mm scale).
    let (r, m, dg) = (SPHERE_RADIUS_SECTION_5_5_2, SPHERE_MASS_SECTION_5_5_2, 0.5);
    for case in cases() {
        let contact = PlasticContact::new(case.modulus, r, case.yield_stress).unwrap();
        let v_y = contact.yield_velocity(m).unwrap();
        let thornton = PlasticImpact::new(contact, Thornton, m).unwrap();
        let interpolation = PlasticImpact::new(contact, Interpolation::default(), m).unwrap();
        let jg = PlasticContact::new(case.modulus, r, case.yield_stress)
            .and_then(|contact| JacksonGreen::new(contact, case.poisson_ratio))
            .unwrap()
            .impact(m, SimulationSettings::default())
            .unwrap();
        let fit = DimensionlessFit::new(case.modulus, case.yield_stress, case.density, m).unwrap();
        let sphere = JkrSphere::new(case.modulus, r, dg).unwrap();
        let sup = Superposition::new(interpolation.clone(), sphere).unwrap();
        let adh = AdhesiveInterpolationImpact::new(
            AdhesivePlasticContact::from_yield_stress(
                JkrSphere::new(case.modulus, r, dg).unwrap(),
                case.yield_stress,
            )
            .unwrap(),
            m,
        )
        .unwrap();
        eprintln!(
            "{}: E* = {:.4e} Pa, v_Y = {:.4} m/s, v*_Y(JG) = {:.4} m/s, v_y(fit) = {:.4} m/s, Phi = {:.3e}",
            case.name, case.modulus, v_y, jg.yield_velocity(), fit.yield_velocity(),
            adh.model().adhesion_parameter()
        );
        let models: Vec<(&str, &dyn ImpactModel)> = vec![
            ("thornton", &thornton),
            ("interpolation", &interpolation),
            ("jackson-green", &jg),
            ("dimensionless-fit", &fit),
            ("superposition", &sup),
            ("adhesive-interpolation", &adh),
        ];
        for &v0 in &[0.12, 0.5, 1.0, 3.0, 6.0] {
            let mut line = format!("  v0 = {v0:>4} m/s:");
            for (name, model) in &models {
                let e = impact(*model, v0).unwrap().restitution;
                assert!(e > 0.0 && e <= 1.0, "{name} at {v0}: {e}");
                line += &format!(" {name} {e:.4}");
            }
            eprintln!("{line}");
        }
        // Seed 000 Fig. 5.17-5.19: Thornton lowest of the non-adhesive models at 6 m/s.
        let e_t = impact(&thornton, 6.0).unwrap().restitution;
        let e_i = impact(&interpolation, 6.0).unwrap().restitution;
        let e_jg = impact(&jg, 6.0).unwrap().restitution;
        assert!(e_t < e_i && e_t < e_jg);
    }
}

#[test]
fn seed_000_section_5_5_2_numbers() {
    // "In der Theorie ergibt sich eine kritische Geschwindigkeit von ungefähr 0,05 m/s"
    // (aluminium plate); steel: "v0 = 0.12 m/s ist praktisch ideal-elastisch",
    // "bei etwa dem Fünfzigfachen ... fällt die Stoßzahl auf 0,7" (experiment, read
    // off Fig. 5.18; the seed calls the agreement of the interpolation and FEM-based
    // models "good"). Observed here: JG 0.646, interpolation 0.596, seed-001 fit 0.690;
    // tolerance 0.11 (a qualitative statement about a plot of measurements).
    let c = &cases();
    let (r, m) = (SPHERE_RADIUS_SECTION_5_5_2, SPHERE_MASS_SECTION_5_5_2);
    let al = PlasticContact::new(c[1].modulus, r, c[1].yield_stress).unwrap();
    let v_al = al.yield_velocity(m).unwrap();
    assert!((v_al - 0.05).abs() < 0.005, "{v_al}");
    let steel = PlasticContact::new(c[0].modulus, r, c[0].yield_stress).unwrap();
    let interp = PlasticImpact::new(steel, Interpolation::default(), m).unwrap();
    assert!(impact(&interp, 0.12).unwrap().restitution > 0.98);
    let jg = PlasticContact::new(c[0].modulus, r, c[0].yield_stress)
        .and_then(|contact| JacksonGreen::new(contact, c[0].poisson_ratio))
        .unwrap()
        .impact(m, SimulationSettings::default())
        .unwrap();
    for model in [&interp as &dyn ImpactModel, &jg] {
        let e = impact(model, 6.0).unwrap().restitution;
        assert!((e - 0.7).abs() < 0.11, "{}: {e}", model.name());
    }
}
