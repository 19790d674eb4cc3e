//! Scenes: effect selection, the bundled scenes against the model crates called
//! directly, the silica sticking velocities, sweeps, and parse errors.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use approx::assert_relative_eq;
use std::path::PathBuf;
use tabor_jkr::{GradedSphere, JkrImpact, JkrSphere, SeparationRule};
use tabor_maugis::{MaugisContact, MaugisDugdaleImpact};
use tabor_plastic::{Interpolation, PlasticContact, PlasticImpact};
use tabor_restitution::{impact, sticking_velocity, ElasticMaterial, ImpactModel};
use tabor_scene::{spaced, sweep, ElasticSphere, Format, Scene, SceneBuilder, SweepParameter};
use tabor_visco::models::KelvinVoigtSphere;
use tabor_visco::SphereModel;

/// 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2, written out here (not the library's).
fn e_star(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2)
}

fn sphere_mass(radius: f64, density: f64) -> f64 {
    4.0 / 3.0 * std::f64::consts::PI * radius.powi(3) * density
}

fn scenes_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes")
}

fn load_scene(name: &str) -> Scene {
    Scene::from_path(&scenes_dir().join(name)).unwrap()
}

fn silica(rule: SeparationRule) -> Scene {
    SceneBuilder::new()
        .sphere(ElasticSphere {
            radius: 1e-6,
            density: 2650.0,
            material: ElasticMaterial::new(54e9, 0.17).unwrap(),
        })
        .target_sphere(ElasticSphere {
            radius: 1e-6,
            density: 2650.0,
            material: ElasticMaterial::new(54e9, 0.17).unwrap(),
        })
        .adhesion(0.05)
        .separation(rule)
        .speed(0.1)
        .build()
        .unwrap()
}

fn effect<'a>(o: &'a tabor_scene::Outcome, name: &str) -> &'a tabor_scene::Effect {
    o.effects.iter().find(|e| e.name == name).unwrap()
}

#[test]
fn silica_sticking_velocities_of_both_separation_rules() {
    let fixed = silica(SeparationRule::FixedGrip)
        .sticking_velocity()
        .unwrap()
        .unwrap();
    let load = silica(SeparationRule::LoadControlled)
        .sticking_velocity()
        .unwrap()
        .unwrap();
    // the figures: about 0.087 and 0.061 m/s
    assert!((fixed - 0.087).abs() < 0.001, "{fixed}");
    assert!((load - 0.061).abs() < 0.001, "{load}");
    // and the bundled file (fixed grip) says the same
    let bundled = load_scene("silica.toml")
        .sticking_velocity()
        .unwrap()
        .unwrap();
    assert_relative_eq!(bundled, fixed, max_relative = 1e-12);
}

#[test]
fn bundled_silica_equals_the_jkr_crate() {
    let scene = load_scene("silica.toml");
    let o = scene.outcome().unwrap();
    let e_star = 54e9 / (2.0 * (1.0 - 0.17f64 * 0.17));
    let m = 4.0 / 3.0 * std::f64::consts::PI * 1e-18 * 2650.0 / 2.0;
    let direct = JkrImpact::new(JkrSphere::new(e_star, 0.5e-6, 0.05).unwrap(), m).unwrap();
    let d = impact(&direct, 0.1).unwrap();
    assert_relative_eq!(o.restitution, d.restitution, max_relative = 1e-13);
    assert_relative_eq!(
        o.sticking_velocity.unwrap(),
        sticking_velocity(&direct, 1e-12).unwrap().speed,
        max_relative = 1e-10
    );
    assert!(effect(&o, "adhesion").used);
    assert!(!effect(&o, "plasticity").used);
    assert!(effect(&o, "plasticity").reason.contains("no yield_stress"));
}

#[test]
fn bundled_maugis_scene_equals_the_maugis_crate() {
    let scene = load_scene("silica_maugis.toml");
    let o = scene.outcome().unwrap();
    let lambda = o.tabor_parameter.unwrap();
    let e_star = 54e9 / (2.0 * (1.0 - 0.17f64 * 0.17));
    let m = scene.effective_mass;
    let direct = MaugisDugdaleImpact::new(
        MaugisContact::from_range(JkrSphere::new(e_star, 0.5e-6, 0.05).unwrap(), 0.3e-9).unwrap(),
        m,
    )
    .unwrap();
    assert_relative_eq!(direct.tabor_parameter(), lambda, max_relative = 1e-14);
    let d = impact(&direct, 0.05).unwrap();
    assert_relative_eq!(o.restitution, d.restitution, max_relative = 1e-12);
    assert!(o.branch.contains("case"), "{}", o.branch);
}

#[test]
fn bundled_plastic_scene_equals_the_plastic_crate() {
    let scene = load_scene("alumina_on_steel.toml");
    let o = scene.outcome().unwrap();
    assert!(effect(&o, "plasticity").used, "{:?}", o.effects);
    assert!(!effect(&o, "adhesion").used);
    assert!(effect(&o, "adhesion").reason.contains("no [adhesion]"));
    let e_star = scene.effective_modulus;
    let direct = PlasticImpact::new(
        PlasticContact::new(e_star, 2.5e-3, 1.03e9).unwrap(),
        Interpolation::default(),
        0.25e-3,
    )
    .unwrap();
    let d = impact(&direct, 1.0).unwrap();
    assert_relative_eq!(o.restitution, d.restitution, max_relative = 1e-12);
    // below the yield onset the plasticity is skipped with its reason
    let slow = scene.outcome_at(0.5 * direct.yield_velocity()).unwrap();
    let p = effect(&slow, "plasticity");
    assert!(
        !p.used && p.reason.contains("does not exceed"),
        "{}",
        p.reason
    );
    assert_eq!(slow.restitution, 1.0);
}

#[test]
fn bundled_aluminium_scene_equals_the_plastic_crate() {
    let scene = load_scene("alumina_on_aluminium.toml");
    let o = scene.outcome().unwrap();
    let direct = PlasticImpact::new(
        PlasticContact::new(e_star(360e9, 0.23, 70e9, 0.345), 2.5e-3, 0.38e9).unwrap(),
        Interpolation::default(),
        0.25e-3,
    )
    .unwrap();
    let d = impact(&direct, 1.0).unwrap();
    assert_relative_eq!(o.restitution, d.restitution, max_relative = 1e-12);
    assert!(effect(&o, "plasticity").used);
    assert_eq!(o.sticking_velocity, None);
}

#[test]
fn bundled_ice_scene_equals_the_jkr_crate() {
    let scene = load_scene("ice_grains.toml");
    let o = scene.outcome().unwrap();
    let m = sphere_mass(1e-6, 1000.0) / 2.0;
    let direct = JkrImpact::new(
        JkrSphere::new(e_star(7e9, 0.25, 7e9, 0.25), 0.5e-6, 0.38).unwrap(),
        m,
    )
    .unwrap();
    let d = impact(&direct, 0.5).unwrap();
    assert!(o.sticks && d.sticks);
    assert_eq!(o.restitution, d.restitution);
    assert_relative_eq!(
        o.sticking_velocity.unwrap(),
        sticking_velocity(&direct, 1e-12).unwrap().speed,
        max_relative = 1e-10
    );
    // Above the sticking velocity both rebound alike.
    let v = 2.0 * o.sticking_velocity.unwrap();
    assert_relative_eq!(
        scene.outcome_at(v).unwrap().restitution,
        impact(&direct, v).unwrap().restitution,
        max_relative = 1e-12
    );
    // The bodies stick: the JKR loss exceeds the kinetic energy, all of which is
    // lost; the one effect's share is all of it (the shares add up to the total,
    // issue 22 item 4; before, the share was the JKR loss, above the total).
    let a = effect(&o, "adhesion");
    assert!(a.used);
    assert!(direct.energy_loss(0.5).unwrap().joules > o.kinetic_energy);
    assert_relative_eq!(o.energy_loss, o.kinetic_energy, max_relative = 1e-15);
    assert_relative_eq!(
        a.energy_loss.unwrap(),
        o.kinetic_energy,
        max_relative = 1e-15
    );
}

#[test]
fn bundled_viscoelastic_scene_equals_the_visco_crate() {
    let scene = load_scene("rubber_viscoelastic.toml");
    let o = scene.outcome().unwrap();
    // Viscous rubber (Kelvin-Voigt) on elastic steel: a standard medium, whose
    // parameters follow here from its limits rather than from the library's
    // series-to-parallel algebra: relaxed G∞ = E*/4 (both springs in series),
    // instantaneous G∞ + G1 = steel's M/4 (the dashpot is rigid at s → ∞), and the
    // relaxation time η_a/(G_a + G_b) of the series element (its pole).
    let e = e_star(210e9, 0.3, 5e6, 0.5);
    let (g_rubber, g_steel) = (5e6 / (1.0 - 0.25) / 4.0, 210e9 / (1.0 - 0.09) / 4.0);
    let relaxed = e / 4.0;
    let branch = g_steel - relaxed;
    let tau = 50.0 / (g_rubber + g_steel);
    let direct = tabor_visco::contact::StandardMediumSphere::new(
        relaxed,
        branch,
        branch * tau,
        5e-3,
        sphere_mass(5e-3, 7850.0),
    )
    .unwrap();
    let d = impact(&direct, 1.0).unwrap();
    assert_relative_eq!(o.restitution, d.restitution, max_relative = 1e-9);
    assert_eq!(o.combination.rule, tabor_scene::Rule::Single);
    // steel is 3e4 times stiffer than rubber: close to the Kelvin-Voigt half-space
    // with G = E*/4 that a rigid ball would see
    let kv = KelvinVoigtSphere::new(
        e / 4.0,
        50.0,
        5e-3,
        sphere_mass(5e-3, 7850.0),
        SphereModel::Rigorous,
    )
    .unwrap();
    let k = impact(&kv, 1.0).unwrap();
    assert!(
        (o.restitution - k.restitution).abs() < 1e-3,
        "{} vs {}",
        o.restitution,
        k.restitution
    );
    assert!(effect(&o, "viscoelasticity").used);
    assert!(!effect(&o, "adhesion").used && !effect(&o, "plasticity").used);
    // 1 m/s on rubber is not small against its wave speed: (5.4) warns.
    assert!(
        o.warnings.iter().any(|w| w.code == "quasi-static"),
        "{:?}",
        o.warnings
    );
}

#[test]
fn bundled_graded_scene_equals_the_jkr_crate() {
    let scene = load_scene("graded_adhesive.toml");
    let o = scene.outcome().unwrap();
    let direct = JkrImpact::new(
        GradedSphere::new(1e12, 0.5, 10e-6, 0.1).unwrap(),
        sphere_mass(10e-6, 2500.0),
    )
    .unwrap();
    let d = impact(&direct, 0.3).unwrap();
    assert_relative_eq!(o.restitution, d.restitution, max_relative = 1e-12);
    assert_relative_eq!(
        o.sticking_velocity.unwrap(),
        sticking_velocity(&direct, 1e-12).unwrap().speed,
        max_relative = 1e-10
    );
}

#[test]
fn every_bundled_scene_runs() {
    let mut n = 0;
    for entry in std::fs::read_dir(scenes_dir()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("toml") {
            continue;
        }
        let scene = Scene::from_path(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let o = scene
            .outcome()
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!((0.0..=1.0).contains(&o.restitution), "{}", path.display());
        // an effect beyond elasticity, or friction (an oblique scene's own effect)
        assert!(
            o.effects.iter().any(|e| e.name != "elasticity" && e.used)
                || scene.friction().unwrap().is_some(),
            "{}: {:?}",
            path.display(),
            o.effects
        );
        n += 1;
    }
    assert!(n >= 6);
}

#[test]
fn jkr_closed_form_only_when_the_difference_is_below_the_accuracy() {
    // at Λ = 1e4 the Maugis-Dugdale loss differs from JKR by about 4.6e-5
    let base = || {
        SceneBuilder::new()
            .sphere(ElasticSphere {
                radius: 1e-6,
                density: 2650.0,
                material: ElasticMaterial::new(54e9, 0.17).unwrap(),
            })
            .target_sphere(ElasticSphere {
                radius: 1e-6,
                density: 2650.0,
                material: ElasticMaterial::new(54e9, 0.17).unwrap(),
            })
            .adhesion(0.05)
            .tabor_parameter(1e4)
            .speed(0.2)
    };
    let coarse = base().accuracy(1e-4).build().unwrap().outcome().unwrap();
    let fine = base().accuracy(1e-6).build().unwrap().outcome().unwrap();
    assert!(coarse.model.contains("JKR"), "{}", coarse.model);
    assert!(effect(&coarse, "adhesion")
        .reason
        .contains("JKR closed form"));
    assert!(fine.model.contains("Maugis"), "{}", fine.model);
    // Either way the result is the Maugis-Dugdale one within the requested accuracy.
    let md = MaugisDugdaleImpact::new(
        MaugisContact::new(
            JkrSphere::new(e_star(54e9, 0.17, 54e9, 0.17), 0.5e-6, 0.05).unwrap(),
            1e4,
        )
        .unwrap(),
        sphere_mass(1e-6, 2650.0) / 2.0,
    )
    .unwrap();
    let md_loss = impact(&md, 0.2).unwrap().energy_loss;
    assert!((coarse.energy_loss / md_loss - 1.0).abs() < 1e-4);
    assert!((fine.energy_loss / md_loss - 1.0).abs() < 1e-6);
    // The stand-in is the fixed-grip JKR (the Maugis-Dugdale limit); its sticking
    // velocity is Maugis-Dugdale's.
    assert!(coarse.model.contains("JKR"), "{}", coarse.model);
    assert_relative_eq!(
        coarse.sticking_velocity.unwrap(),
        sticking_velocity(&md, 1e-12).unwrap().speed,
        max_relative = 1e-4
    );
    // The load-controlled rule together with a range is refused (it was silently
    // ignored): Maugis-Dugdale has its own snap-off.
    let e = base()
        .separation(SeparationRule::LoadControlled)
        .accuracy(1e-4)
        .build()
        .unwrap_err();
    assert_eq!(e.field.as_deref(), Some("adhesion.separation"), "{e}");
    // and Λ ≤ Λ1 uses the case-1 closed form
    let small = base()
        .tabor_parameter(0.3)
        .build()
        .unwrap()
        .outcome()
        .unwrap();
    assert!(
        small.branch.contains("closed form (5.44)"),
        "{}",
        small.branch
    );
}

#[test]
fn negligible_adhesion_is_skipped() {
    // a millimetre steel ball at 1 m/s: the adhesive loss is far below 1e-10 of
    // the kinetic energy
    let scene = SceneBuilder::new()
        .sphere(ElasticSphere {
            radius: 1e-3,
            density: 7850.0,
            material: ElasticMaterial::new(210e9, 0.3).unwrap(),
        })
        .target_half_space(ElasticMaterial::new(210e9, 0.3).unwrap(), Some(7850.0))
        .adhesion(1e-6)
        .speed(1.0)
        .build()
        .unwrap();
    let o = scene.outcome().unwrap();
    let a = effect(&o, "adhesion");
    assert!(
        !a.used && a.reason.contains("below the requested accuracy"),
        "{}",
        a.reason
    );
    assert_eq!(o.restitution, 1.0);
}

#[test]
fn sweeps_are_identical_with_one_and_two_threads() {
    let scene = load_scene("silica.toml");
    let speeds = spaced(0.05, 1.0, 40, true).unwrap();
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| sweep(&scene, SweepParameter::Speed, &speeds, || {}))
    };
    let one: Vec<f64> = run(1).into_iter().map(|r| r.unwrap().restitution).collect();
    let two: Vec<f64> = run(2).into_iter().map(|r| r.unwrap().restitution).collect();
    assert_eq!(one, two);
    assert!(one[0] == 0.0 && one[39] > 0.9);
    // A numerical model (Maugis-Dugdale case 3 by quadrature), swept over Λ: the
    // results are bit-identical too, in the order of the values.
    let lambdas = spaced(0.7, 50.0, 12, true).unwrap();
    let scene = load_scene("silica_maugis.toml");
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| sweep(&scene, SweepParameter::TaborParameter, &lambdas, || {}))
    };
    let one: Vec<_> = run(1).into_iter().map(|r| r.unwrap()).collect();
    let two: Vec<_> = run(2).into_iter().map(|r| r.unwrap()).collect();
    assert_eq!(one, two);
    for (o, &l) in one.iter().zip(&lambdas) {
        assert_eq!(o.tabor_parameter, Some(l));
        assert!(o.branch.contains("case 3"), "{}", o.branch);
    }
}

#[test]
fn tabor_mu_is_converted_to_the_seeds_lambda() {
    // Λ = 0.6861 λ and λ ≈ 1.157 μ (maugis-dugdale.md): μ = 1 is Λ ≈ 0.7938.
    let text = std::fs::read_to_string(scenes_dir().join("silica_maugis.toml"))
        .unwrap()
        .replace("range = 0.3e-9           # m", "tabor_mu = 1.0");
    let scene = Scene::from_str(&text, Format::Toml).unwrap();
    let lambda = scene.tabor_parameter().unwrap();
    assert!((lambda - 0.686_108_5 * 1.157).abs() < 1e-6, "{lambda}");
    let both = text.replace("tabor_mu = 1.0", "tabor_mu = 1.0\nrange = 1e-9");
    let e = Scene::from_str(&both, Format::Toml).unwrap_err();
    assert!(e.to_string().contains("at most one"), "{e}");
}

#[test]
fn simulation_agrees_with_the_analytic_outcome() {
    let scene = load_scene("silica.toml");
    let (sim, o) = scene
        .simulate(0.2, &tabor_dynamics::SimulationSettings::default())
        .unwrap();
    assert_relative_eq!(sim.restitution, o.restitution, max_relative = 1e-6);
    let scene = load_scene("alumina_on_steel.toml");
    let (sim, o) = scene
        .simulate(1.0, &tabor_dynamics::SimulationSettings::default())
        .unwrap();
    assert_relative_eq!(sim.restitution, o.restitution, max_relative = 1e-6);
}

#[test]
fn parse_errors_are_one_line_with_position_and_field() {
    let good = std::fs::read_to_string(scenes_dir().join("silica.toml")).unwrap();
    let cases = [
        (
            good.replace("radius = 1e-6            # m", "radus = 1e-6"),
            "radus",
        ),
        (
            good.replace(
                "density = 2650           # kg/m³",
                "density = \"2650 kg/m3\"",
            ),
            "sphere.density",
        ),
        (
            good.replace("youngs_modulus = 54e9    # Pa", ""),
            "youngs_modulus",
        ),
        (good.replace("[impact]", "[impact"), "line"),
        (
            good.replace("radius = 1e-6            # m", "radius = -1e-6"),
            "sphere.radius",
        ),
        (
            good.replace("separation = \"fixed-grip\"", "separation = \"sticky\""),
            "adhesion.separation",
        ),
    ];
    for (text, needle) in cases {
        let e = Scene::from_str(&text, Format::Toml).unwrap_err();
        let msg = e.to_string();
        assert_eq!(msg.lines().count(), 1, "{msg}");
        assert!(msg.contains(needle), "{needle}: {msg}");
        assert!(e.line.is_some(), "{msg}");
    }
    let e = Scene::from_str("{\"sphere\": {\"radius\": 1e-6,}", Format::Json).unwrap_err();
    assert!(e.line.is_some() && e.to_string().lines().count() == 1);
    let e = Scene::from_str("{\"sphere\": {\"radius\": true}}", Format::Json).unwrap_err();
    assert!(e.to_string().contains("sphere.radius"), "{e}");
}

#[test]
fn json_scenes_read_like_toml() {
    // The same keys in JSON (`.json`): the bundled silica scene written out as JSON
    // reads back to the same scene and outcome.
    let toml_scene = load_scene("silica_maugis.toml");
    let text = serde_json::to_string_pretty(toml_scene.data()).unwrap();
    let dir = std::env::temp_dir().join(format!("tabor-scene-json-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("silica_maugis.json");
    std::fs::write(&path, text).unwrap();
    let json_scene = Scene::from_path(&path).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(json_scene.data(), toml_scene.data());
    assert_eq!(json_scene.outcome().unwrap(), toml_scene.outcome().unwrap());
}
