//! The energy loss of every impact model, one call each, against the JKR fixed-grip
//! closed form (seed 000 eq. (5.36)) as the baseline of the run.
//!
//! Elastic adhesive models: two silica spheres of radius 1 µm (E* = 27.8 GPa,
//! R = 0.5 µm, Δγ = 0.05 J/m²); Maugis-Dugdale at Λ = 2 (case 3). Elasto-plastic
//! models: the alumina sphere on steel of seed 000 section 5.5.2 (Table 5.2) at
//! 1 m/s, adhesive variants with Δγ = 0.5 J/m². Viscoelastic: a rigid sphere on an
//! incompressible Kelvin-Voigt half-space (rigorous model, δ ≈ 0.1), the same ball
//! on a standard medium and on a Kelvin-Maxwell medium (MDR), and a flat punch of the
//! same mass and radius on the Kelvin-Voigt half-space. JKR variants: a power-law
//! profile (n = 4) and a graded medium (k = 0.5), both on the silica scales.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use tabor::jkr::{GradedSphere, JkrImpact, JkrSphere, PowerLawProfile, SeparationRule};
use tabor::maugis::{loss_over_jkr_fast, prepare_fast_tier, MaugisContact, MaugisDugdaleImpact};
use tabor::plastic::materials::{
    ALUMINA_TABLE_3, ALUMINA_TABLE_5_2, SPHERE_MASS_SECTION_5_5_2, SPHERE_RADIUS_SECTION_5_5_2,
    STEEL_TABLE_3, STEEL_TABLE_5_2,
};
use tabor::plastic::{
    AdhesiveInterpolationImpact, AdhesivePlasticContact, DimensionlessFit, Interpolation,
    JacksonGreen, PlasticContact, PlasticImpact, SimulationSettings, Superposition, Thornton,
};
use tabor::restitution::ImpactModel;
use tabor::visco::models::{KelvinVoigtFlatPunch, KelvinVoigtSphere, MaxwellBranchSphere};
use tabor::visco::SphereModel;

fn models(c: &mut Criterion) {
    prepare_fast_tier().unwrap();
    // silica pair
    let (e_star, r, dg, m) = (
        2.780_352_177_942_539e10,
        0.5e-6,
        0.05,
        5.550_147_021_341_967e-15,
    );
    let sphere = JkrSphere::new(e_star, r, dg).unwrap();
    let jkr = JkrImpact::new(sphere, m).unwrap();
    let jkr_load = jkr.clone().with_separation(SeparationRule::LoadControlled);
    let md = MaugisDugdaleImpact::new(
        MaugisContact::new(JkrSphere::new(e_star, r, dg).unwrap(), 2.0).unwrap(),
        m,
    )
    .unwrap();
    // f(r) = A r⁴ with the sphere's curvature at r = 20 nm; E(z) = c_N z^(1/2) with
    // E(10 nm) = E*
    let power_law = JkrImpact::new(
        PowerLawProfile::new(e_star, 4.0, 1.0 / (2.0 * r * 4e-16), dg).unwrap(),
        m,
    )
    .unwrap();
    let graded = JkrImpact::new(GradedSphere::new(e_star / 1e-4, 0.5, r, dg).unwrap(), m).unwrap();
    let v_silica = 0.2;

    // alumina on steel (seed 000 Table 5.2; seed 001 Table 3 for the fit)
    let (rp, mp) = (SPHERE_RADIUS_SECTION_5_5_2, SPHERE_MASS_SECTION_5_5_2);
    let ep = ALUMINA_TABLE_5_2
        .effective_modulus_with(&STEEL_TABLE_5_2)
        .unwrap();
    let sy = STEEL_TABLE_5_2.yield_stress.unwrap();
    let contact = PlasticContact::new(ep, rp, sy).unwrap();
    let thornton = PlasticImpact::new(contact, Thornton, mp).unwrap();
    let interpolation = PlasticImpact::new(contact, Interpolation::default(), mp).unwrap();
    let settings = SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::default()
    };
    let jackson_green = PlasticContact::new(ep, rp, sy)
        .and_then(|contact| JacksonGreen::new(contact, STEEL_TABLE_5_2.poisson_ratio))
        .unwrap()
        .impact(mp, settings)
        .unwrap();
    let fit = DimensionlessFit::new(
        ALUMINA_TABLE_3
            .effective_modulus_with(&STEEL_TABLE_3)
            .unwrap(),
        STEEL_TABLE_3.yield_stress.unwrap(),
        ALUMINA_TABLE_3.density.unwrap(),
        mp,
    )
    .unwrap();
    let superposition =
        Superposition::new(interpolation.clone(), JkrSphere::new(ep, rp, 0.5).unwrap()).unwrap();
    let adhesive = AdhesiveInterpolationImpact::new(
        AdhesivePlasticContact::from_yield_stress(JkrSphere::new(ep, rp, 0.5).unwrap(), sy)
            .unwrap(),
        mp,
    )
    .unwrap();
    let v_plastic = 1.0;

    // viscoelastic: rubber-like half-space, a 1 cm steel ball
    let visco = KelvinVoigtSphere::new(1e6, 30.0, 0.01, 0.033, SphereModel::Rigorous).unwrap();
    let flat_punch = KelvinVoigtFlatPunch::new(1e6, 30.0, 0.01, 0.033).unwrap();
    let standard = MaxwellBranchSphere::standard(1e6, 1e6, 30.0, 0.01, 0.033).unwrap();
    let kelvin_maxwell = MaxwellBranchSphere::kelvin_maxwell(1e6, 1e6, 30.0, 0.01, 0.033).unwrap();
    let v_visco = 0.5;

    let cases: Vec<(&str, &dyn ImpactModel, f64)> = vec![
        (
            "JKR load-controlled (quadrature, 1e-12)",
            &jkr_load,
            v_silica,
        ),
        ("Maugis-Dugdale direct (Λ = 2, 1e-12)", &md, v_silica),
        ("JKR power-law profile n = 4 (5.39)", &power_law, v_silica),
        ("JKR graded medium k = 0.5 (5.47)-(5.53)", &graded, v_silica),
        ("Thornton (closed form)", &thornton, v_plastic),
        ("interpolation (closed form)", &interpolation, v_plastic),
        (
            "superposition (interpolation + JKR)",
            &superposition,
            v_plastic,
        ),
        ("adhesive interpolation", &adhesive, v_plastic),
        ("Jackson-Green (simulated)", &jackson_green, v_plastic),
        ("seed-001 fit", &fit, v_plastic),
        ("Kelvin-Voigt sphere, rigorous", &visco, v_visco),
        (
            "Kelvin-Voigt flat punch (5.54)-(5.63)",
            &flat_punch,
            v_visco,
        ),
        ("standard-medium sphere (MDR)", &standard, v_visco),
        ("Kelvin-Maxwell sphere (MDR)", &kelvin_maxwell, v_visco),
    ];
    for (name, model, v) in &cases {
        let loss = model.energy_loss(*v).unwrap().joules;
        assert!(
            loss > 0.0 && loss < 0.5 * model.effective_mass() * v * v,
            "{name}"
        );
    }

    let mut group = c.benchmark_group("model_loss");
    group.bench_function("baseline: JKR fixed grip (closed form)", |b| {
        b.iter(|| jkr.energy_loss(black_box(v_silica)).unwrap().joules)
    });
    group.bench_function("Maugis-Dugdale fast tier (Λ = 2)", |b| {
        b.iter(|| loss_over_jkr_fast(black_box(2.0)).unwrap())
    });
    for (name, model, v) in cases {
        group.bench_function(name, |b| {
            b.iter(|| model.energy_loss(black_box(v)).unwrap().joules)
        });
    }
    group.finish();
}

criterion_group!(benches, models);
criterion_main!(benches);
