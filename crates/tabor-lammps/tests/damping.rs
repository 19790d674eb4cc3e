#![allow(clippy::unwrap_used, clippy::expect_used)]
//! `[damping]` exported to LAMMPS: `damping <model>` with the scene's value, the
//! LAMMPS law (`LammpsImpact`, LAMMPS's damping written independently in
//! `law.rs`) against tabor's scene, and the refusals LAMMPS makes.

use tabor_lammps::{export, export_plugin, ExportError, LammpsImpact, Scope, REPRODUCES};
use tabor_scene::{Format, Scene};

const SILICA: &str =
    "[sphere]\nradius = 1e-6\ndensity = 2650\nyoungs_modulus = 54e9\npoisson_ratio = 0.17\n\
    [target]\nradius = 1e-6\ndensity = 2650\nyoungs_modulus = 54e9\npoisson_ratio = 0.17\n\
    [impact]\nspeed = 0.3\n";

fn scene(extra: &str) -> Scene {
    Scene::from_str(&format!("{SILICA}{extra}"), Format::Toml).unwrap()
}

/// Hertz + `coeff_restitution`: `hertz/material … damping coeff_restitution` with
/// the scene's e, and LAMMPS's law reproduces tabor's restitution (e) at every
/// speed, speed-independent.
#[test]
fn coeff_restitution_without_adhesion_is_lammps_own_law() {
    let s = scene("[damping]\nmodel = \"coeff_restitution\"\nrestitution = 0.6\n");
    let x = export(&s, None).unwrap();
    let f = x.fragment();
    assert!(f.contains("pair_coeff * * hertz/material "), "{f}");
    assert!(f.contains(" 6.0000000000e-1 0.17 "), "{f}");
    assert!(f.contains("damping coeff_restitution"), "{f}");
    assert!(!f.contains("limit_damping"), "{f}");
    assert_eq!(x.reproduces.scope, Scope::SpeedIndependent);
    let law = LammpsImpact::new(x.model, x.effective_radius, x.effective_mass).unwrap();
    for v in [1e-3, 0.3, 10.0] {
        let lammps = law.restitution(v).unwrap();
        let tabor = s.outcome_at(v).unwrap().restitution;
        assert!(
            (lammps - tabor).abs() <= REPRODUCES,
            "{v}: {lammps} vs {tabor}"
        );
        assert!((tabor - 0.6).abs() < 1e-8, "{tabor}");
    }
}

/// `tsuji` and `viscoelastic` without adhesion: LAMMPS's law (its α(e) and η_n0
/// read from the fragment's model) against tabor's scene.
#[test]
fn tsuji_and_viscoelastic_without_adhesion_are_lammps_own_laws() {
    for extra in [
        "[damping]\nmodel = \"tsuji\"\ncoefficient = 0.7\n",
        "[damping]\nmodel = \"viscoelastic\"\ncoefficient = 5e15\n",
    ] {
        let s = scene(extra);
        let x = export(&s, None).unwrap();
        let law = LammpsImpact::new(x.model, x.effective_radius, x.effective_mass).unwrap();
        for v in [0.01, 0.3, 3.0] {
            let lammps = law.restitution(v).unwrap();
            let tabor = s.outcome_at(v).unwrap().restitution;
            assert!(
                (lammps - tabor).abs() <= REPRODUCES,
                "{extra} {v}: {lammps} vs {tabor}"
            );
        }
    }
}

/// With adhesion LAMMPS refuses `coeff_restitution` and `tsuji` (an error at
/// `pair_coeff`): so does the plain export, naming why and what tabor does.
#[test]
fn coeff_restitution_with_adhesion_is_refused_as_lammps_does() {
    for model in [
        "coeff_restitution\"\nrestitution = 0.5",
        "tsuji\"\ncoefficient = 0.5",
    ] {
        let s = scene(&format!(
            "[adhesion]\nwork_of_adhesion = 0.05\n[damping]\nmodel = \"{model}\n"
        ));
        let Err(ExportError::Unrepresentable { effect, reason }) = export(&s, None) else {
            panic!("{model}: exported");
        };
        assert!(effect.contains("with adhesion"), "{effect}");
        assert!(
            reason.contains("LAMMPS refuses") && reason.contains("(4/3) E* a"),
            "{reason}"
        );
    }
    // viscoelastic works with jkr in LAMMPS
    let s = scene("[adhesion]\nwork_of_adhesion = 0.05\n[damping]\nmodel = \"viscoelastic\"\ncoefficient = 5e15\n");
    let f = export(&s, None).unwrap().fragment();
    assert!(
        f.contains("pair_coeff * * jkr ") && f.contains("damping viscoelastic"),
        "{f}"
    );
}

/// `tabor export lammps --plugin`: `damping <model> <value>` for `pair_style
/// tabor`, with adhesion too (where `pair granular` refuses `tsuji` and
/// `coeff_restitution`).
#[test]
fn the_plugin_export_writes_damping() {
    let s = scene("[damping]\nmodel = \"coeff_restitution\"\nrestitution = 0.5\n");
    let x = export_plugin(&s, "x.so", None).unwrap();
    let f = x.fragment();
    assert!(
        f.contains("pair_coeff * * hertz ")
            && f.contains(" damping coeff_restitution 5.0000000000e-1"),
        "{f}"
    );
    assert!(x.reproduces.iter().any(|r| r.contains("[damping]")));
    let s = scene(
        "[adhesion]\nwork_of_adhesion = 0.05\n[damping]\nmodel = \"tsuji\"\ncoefficient = 0.7\n",
    );
    let x = export_plugin(&s, "x.so", None).unwrap();
    let f = x.fragment();
    assert!(f.contains(" damping tsuji 7.0000000000e-1"), "{f}");
    assert!(matches!(
        export(&s, None),
        Err(ExportError::Unrepresentable { .. })
    ));
}
