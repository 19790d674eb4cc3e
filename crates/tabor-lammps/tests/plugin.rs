#![allow(clippy::unwrap_used, clippy::expect_used)]
//! `export_plugin` (the fragment for `pair_style tabor`) against the scenes'
//! numbers computed here by hand: E* = E/(2(1 − ν²)) for two equal spheres, w, Λ,
//! the Kuwabara-Kono time A = 4η(1 − ν²)/E of two equal Kelvin-Voigt bodies, the
//! neighbor skin against the interaction range, and the refusals.

use std::f64::consts::PI;
use std::path::PathBuf;
use tabor_lammps::{export_plugin, plugin_load_command, ExportError, PluginModel};
use tabor_scene::Scene;

fn scene(path: &str) -> Scene {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    Scene::from_path(&root.join(path)).expect("scene")
}

const SO: &str = "/opt/taborplugin.so";

/// The numbers on the `pair_coeff` line of a fragment.
fn coeff_numbers(fragment: &str) -> (String, Vec<f64>) {
    let line = fragment
        .lines()
        .find(|l| l.starts_with("pair_coeff * * "))
        .expect("pair_coeff line");
    let words: Vec<&str> = line.split_whitespace().collect();
    let nums = words[4..]
        .iter()
        .filter(|w| **w != "damping")
        .map(|w| w.parse::<f64>().expect("number"))
        .collect();
    (words[3].to_string(), nums)
}

#[test]
fn maugis_fragment_carries_the_scene_numbers() {
    let x = export_plugin(
        &scene("integrations/lammps/scenes/maugis_case2.toml"),
        SO,
        None,
    )
    .expect("export");
    let f = x.fragment();
    // silica: E = 54 GPa, ν = 0.17, two equal spheres
    let e_star = 54e9 / (2.0 * (1.0 - 0.17f64 * 0.17));
    let (model, n) = coeff_numbers(&f);
    assert_eq!(model, "maugis");
    assert_eq!(x.model, PluginModel::Maugis);
    assert_eq!(n.len(), 3);
    assert!((n[0] / e_star - 1.0).abs() < 1e-10, "{} {e_star}", n[0]);
    assert!((n[1] / 0.05 - 1.0).abs() < 1e-10);
    assert!((n[2] / 0.55 - 1.0).abs() < 1e-10);
    assert!(f.contains("\nplugin load \"/opt/taborplugin.so\"\n"));
    // a path that does not exist is written, with a warning
    assert!(f.contains("# WARNING: the plugin /opt/taborplugin.so does not exist"));
    assert_eq!(x.warnings.len(), 1);
    assert_eq!(
        plugin_load_command("/my dir/tabor plugin.so"),
        "plugin load \"/my dir/tabor plugin.so\""
    );
    assert!(f.contains("\npair_style tabor\n"));
    // legal after create_box: no newton line
    assert!(!f.lines().any(|l| l.starts_with("newton")));
    assert!(f.contains("\ncomm_modify vel yes\n"));
    assert!(f.contains("# REPRODUCES: tabor's force law itself"));
    assert!(f.contains("# DOES NOT REPRODUCE: tangential"));
    // the skin covers the interaction range, which is the snap-off distance here
    let skin: f64 = f
        .lines()
        .find(|l| l.starts_with("neighbor "))
        .and_then(|l| l.split_whitespace().nth(1))
        .expect("neighbor")
        .parse()
        .expect("skin");
    assert!(skin >= x.interaction_range && x.interaction_range > 0.0);
    assert!((x.interaction_range + x.snap_off_overlap.min(x.jump_in_overlap)).abs() < 1e-20);
    // the Maugis-Dugdale pull-off force lies between JKR's 1.5 and DMT's 2 pi w R*
    let r = 0.5e-6;
    let p = -x.pull_off_force / (PI * 0.05 * r);
    assert!(p > 1.5 && p < 2.0, "{p}");
    assert!((p - 1.633).abs() < 2e-3, "{p}"); // tabor-ffi README: 1.633 at Λ = 0.55
                                              // tabor's restitution at the scene speed (test_plugin.py: 0.850192)
    let at = x
        .restitution
        .iter()
        .find(|s| (s.speed / 0.08 - 1.0).abs() < 1e-12)
        .expect("scene speed");
    assert!(
        (at.restitution - 0.850192).abs() < 1e-6,
        "{}",
        at.restitution
    );
}

#[test]
fn jkr_rules_and_derived_lambda() {
    let fg = export_plugin(&scene("examples/scenes/silica.toml"), SO, None).expect("fg");
    let (m, n) = coeff_numbers(&fg.fragment());
    assert_eq!(m, "jkr/fixed-grip");
    assert_eq!(n.len(), 2);
    let lc = export_plugin(
        &scene("integrations/lammps/scenes/jkr_load_controlled.toml"),
        SO,
        None,
    )
    .expect("lc");
    assert_eq!(coeff_numbers(&lc.fragment()).0, "jkr/load-controlled");
    // JKR pull-off (both rules): −(3/2) π w R*
    for x in [&fg, &lc] {
        let f = -1.5 * PI * x.work_of_adhesion.unwrap() * x.effective_radius;
        assert!((x.pull_off_force / f - 1.0).abs() < 1e-6);
    }
    // a range given: Λ derived by the scene, written as is
    let s = scene("examples/scenes/silica_maugis.toml");
    let x = export_plugin(&s, SO, None).expect("md");
    let (m, n) = coeff_numbers(&x.fragment());
    assert_eq!(m, "maugis");
    assert!((n[2] / s.tabor_parameter().unwrap() - 1.0).abs() < 1e-10);
}

#[test]
fn kelvin_voigt_adhesive_scene_gets_its_kuwabara_kono_time() {
    let x = export_plugin(
        &scene("examples/scenes/polymer_grains_viscoadhesive.toml"),
        SO,
        None,
    )
    .expect("export");
    // two equal Kelvin-Voigt bodies: E*(s) = (M + 4 η s)/2 with M = E/(1 − ν²), so
    // η_c = 2η and A = η_c/E* = 4η/M
    let m = 2e6 / (1.0 - 0.49f64 * 0.49);
    let a = 4.0 * 2e-4 / m;
    assert!((x.damping_time.unwrap() / a - 1.0).abs() < 1e-12);
    let f = x.fragment();
    let line = f.lines().find(|l| l.starts_with("pair_coeff")).unwrap();
    assert!(line.starts_with("pair_coeff * * jkr/fixed-grip "));
    let (_, n) = coeff_numbers(&f);
    assert!((n[2] / a - 1.0).abs() < 1e-10);
    assert!(line.contains(" damping "));
}

#[test]
fn refusals() {
    for (path, effect) in [
        ("examples/scenes/silica_maugis_plastic.toml", "plasticity"),
        ("examples/scenes/graded_adhesive.toml", "a graded medium"),
        (
            "examples/scenes/rubber_viscoelastic.toml",
            "a standard-medium viscosity",
        ),
        (
            "integrations/lammps/scenes/adhesive_viscoelastic.toml",
            "a standard-medium viscosity",
        ),
        (
            "examples/scenes/rubber_balls.toml",
            "a Kelvin-Voigt viscosity without adhesion",
        ),
        ("integrations/lammps/scenes/jkr_wall.toml", "a flat target"),
    ] {
        match export_plugin(&scene(path), SO, None) {
            Err(ExportError::Unrepresentable { effect: e, .. }) => {
                assert!(e.starts_with(effect), "{path}: {e}")
            }
            other => panic!("{path}: {other:?}"),
        }
    }
}
