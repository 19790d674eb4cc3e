#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The scene's `[friction]` in both exports: pair granular's sub-model keywords
//! (`tangential mindlin NULL x μ rolling sds k γ μ twisting marshall`) and the same
//! keywords for `pair_style tabor`, with the Mindlin stiffness against 8G* computed
//! here from the materials (Mindlin 1949: 1/G* = (2 − ν1)/G1 + (2 − ν2)/G2).

use std::path::PathBuf;
use tabor_lammps::{export, export_plugin, parse_line};
use tabor_scene::{Format, Scene};

fn scene(path: &str) -> Scene {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    Scene::from_path(&root.join(path)).expect("scene")
}

fn coeff_line(fragment: &str) -> String {
    fragment
        .lines()
        .find(|l| l.starts_with("pair_coeff"))
        .expect("pair_coeff")
        .to_string()
}

#[test]
fn friction_keywords_in_both_exports() {
    let s = scene("examples/scenes/silica_oblique.toml");
    let x = export(&s, None).expect("export");
    let sub = "tangential mindlin NULL 0 0.3 rolling sds 50 0 0.1 twisting marshall";
    assert_eq!(x.friction.as_deref(), Some(sub));
    let line = coeff_line(&x.fragment());
    assert!(
        line.contains(&format!(" {sub} damping viscoelastic")),
        "{line}"
    );
    // LAMMPS's own line reads back: the sub-models are recognized
    let p = parse_line(&line).expect("parses");
    assert_eq!(
        p.ignored,
        vec![
            "tangential mindlin NULL 0 0.3".to_string(),
            "rolling sds 50 0 0.1".to_string(),
            "twisting marshall".to_string()
        ]
    );
    // load-controlled JKR: LAMMPS's pull-off is tabor's, no friction-limit caveat
    assert!(!x
        .does_not_reproduce
        .iter()
        .any(|l| l.effect.starts_with("friction")));
    assert!(x
        .fragment()
        .contains("Friction, rolling and twisting from the scene's [friction]"));
    let plug = export_plugin(&s, "/x/taborplugin.so", None).expect("plugin");
    let pl = coeff_line(&plug.fragment());
    assert!(pl.ends_with(&format!(" poisson 0.17 {sub}")), "{pl}");
    assert!(plug.reproduces.iter().any(|r| r.contains("friction")));
}

#[test]
fn two_materials_get_an_explicit_mindlin_stiffness_and_limits_are_named() {
    let text = r#"
name = "silica-on-alumina"
[sphere]
radius = 1e-6
density = 2650
youngs_modulus = 54e9
poisson_ratio = 0.17
[target]
radius = 2e-6
density = 3950
youngs_modulus = 360e9
poisson_ratio = 0.23
[adhesion]
work_of_adhesion = 0.05
range = 0.3e-9
[friction]
coefficient = 0.5
tangential = "mindlin_rescale"
twisting = { stiffness = 1e-9, damping = 0.0, coefficient = 0.2 }
[impact]
speed = 0.1
"#;
    let s = Scene::from_str(text, Format::Toml).expect("scene");
    let x = export(&s, None).expect("export");
    let g = |e: f64, nu: f64| e / (2.0 * (1.0 + nu));
    let g_star = 1.0 / ((2.0 - 0.17) / g(54e9, 0.17) + (2.0 - 0.23) / g(360e9, 0.23));
    let sub = x.friction.clone().expect("friction");
    let k: f64 = sub.split_whitespace().nth(2).unwrap().parse().unwrap();
    assert!(
        (k / (8.0 * g_star) - 1.0).abs() < 1e-9,
        "{k} vs {}",
        8.0 * g_star
    );
    assert!(sub.starts_with("tangential mindlin_rescale "), "{sub}");
    assert!(sub.ends_with(" twisting sds 1e-9 0 0.2"), "{sub}");
    // Maugis-Dugdale: LAMMPS's jkr pull-off of the effective gamma is not the
    // scene's, and the fragment says so
    assert!(x
        .does_not_reproduce
        .iter()
        .any(|l| l.effect == "friction limit"));
    let plug = export_plugin(&s, "/x/taborplugin.so", None).expect("plugin");
    let pl = coeff_line(&plug.fragment());
    assert!(
        !pl.contains("poisson") && pl.contains(" tangential mindlin_rescale "),
        "{pl}"
    );
}

#[test]
fn no_friction_section_keeps_the_frictionless_line() {
    let x = export(&scene("examples/scenes/silica.toml"), None).expect("export");
    assert_eq!(x.friction, None);
    assert!(x
        .model_keywords
        .contains(" tangential linear_nohistory 0.0 0.0 damping "));
    assert!(x.does_not_reproduce.iter().any(|l| l.effect == "friction"));
}

/// `tangential = "mindlin_deresiewicz"`: `pair_style tabor` takes it (its
/// per-contact spring bed), `pair granular` has no such model and the export says so.
#[test]
fn micro_slip_goes_to_the_plugin_only() {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/silica_oblique.toml");
    let text = std::fs::read_to_string(path).unwrap().replace(
        "tangential = \"mindlin\"",
        "tangential = \"mindlin_deresiewicz\"",
    );
    let s = Scene::from_str(&text, Format::Toml).expect("scene");
    let e = export(&s, None).expect_err("pair granular has no micro-slip");
    let msg = e.to_string();
    assert!(
        msg.contains("mindlin_deresiewicz") && msg.contains("--plugin"),
        "{msg}"
    );
    let plug = export_plugin(&s, "/x/taborplugin.so", None).expect("plugin");
    let pl = coeff_line(&plug.fragment());
    assert!(
        pl.ends_with(
            " poisson 0.17 tangential mindlin_deresiewicz NULL 0 0.3 rolling sds 50 0 0.1 twisting marshall"
        ),
        "{pl}"
    );
}
