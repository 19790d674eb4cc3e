#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Property-based fuzzing of the public API (issue 9), the scenes: the builder with
//! arbitrary numbers (then outcome, sticking velocity, sweeps), a bundled scene file
//! with one value replaced by an arbitrary number or token, and arbitrary text in
//! both formats. No call may panic; a result must be finite (restitution in [0, 1])
//! and an error one non-empty line (a scene-file error naming its position or
//! field). The models are fuzzed in `fuzz_api.rs` and `fuzz_api_dissipative.rs`.
//! The harness, the checks and `fuzz_tests!` are in `tests/common/mod.rs`.
//!
//! The CI variant (`fuzz_*`) runs `PROPTEST_CASES` cases per entry-point group
//! (CI: 64; default 256), spread over the group's variants. The full fuzzing run is
//! the `#[ignore]`d `full_*` variant: `PROPTEST_CASES` cases (default 100000) for
//! each variant of a group, so at least 10⁵ cases reach every public entry point
//! (all three files):
//!
//!     PROPTEST_CASES=100000 cargo test --release --test 'fuzz_api*' -- --ignored

use proptest::prelude::*;

mod common;

use common::{check, check_other, fuzz_tests, phys, run, u, unit, variant, x};

// ---------------------------------------------------------------------------
// Properties

// Scenes: the builder with arbitrary numbers, then outcome / sticking velocity.
fn scene_builder_group(cases: u32, only: Option<u8>) {
    use tabor::restitution::ElasticMaterial;
    use tabor::scene::{spaced, ElasticSphere, Scene, SceneBuilder, SweepParameter};
    run(
        "scene_builder",
        cases,
        (
            (phys(1e-9, 1.0), phys(1e2, 2e4), phys(1e5, 1e12), u()),
            (phys(1e-9, 1.0), phys(1e5, 1e12), u(), any::<bool>()),
            (phys(1e-3, 10.0), x(), phys(1e-4, 1e2), phys(1e-12, 1e-3)),
            (variant(4, only), x(), 0usize..5, any::<bool>()),
        ),
        |((r1, rho, e1, nu1), (r2, e2, nu2, half), (w, extra, v, acc), (kind, p, points, log))| {
            // the builder takes validated materials: arbitrary moduli and Poisson's
            // ratios are checked by ElasticMaterial::new (and by the file groups)
            let m1 = ElasticMaterial::new(e1, nu1);
            check("ElasticMaterial::new", &[e1, nu1], &m1)?;
            let m2 = ElasticMaterial::new(e2, nu2);
            check("ElasticMaterial::new", &[e2, nu2], &m2)?;
            let (Ok(m1), Ok(m2)) = (m1, m2) else {
                return Ok(());
            };
            let mut b = SceneBuilder::new().sphere(ElasticSphere {
                radius: r1,
                density: rho,
                material: m1,
            });
            b = if half {
                b.target_half_space(m2, None)
            } else {
                b.target_sphere(ElasticSphere {
                    radius: r2,
                    density: rho,
                    material: m2,
                })
            };
            b = match kind {
                0 => b,
                1 => b.adhesion(w),
                2 => b.adhesion(w).tabor_parameter(extra),
                _ => b.target_yield_stress(extra),
            };
            let scene: Result<Scene, _> = b.speed(v).accuracy(acc).build();
            check_other("SceneBuilder::build", &[], &unit(&scene))?;
            check_other("spaced", &[], &spaced(p, v, points, log))?;
            let Ok(scene) = scene else { return Ok(()) };
            let o = scene.outcome();
            check_other("Scene::outcome", &[], &o)?;
            if let Ok(o) = &o {
                prop_assert!((0.0..=1.0).contains(&o.restitution), "{}", o.restitution);
            }
            check_other("Scene::sticking_velocity", &[], &scene.sticking_velocity())?;
            check_other("Scene::outcome_at", &[p], &scene.outcome_at(p))?;
            check_other("Scene::with_speed", &[p], &scene.with_speed(p).map(|_| ()))?;
            for parameter in [
                SweepParameter::Speed,
                SweepParameter::SphereRadius,
                SweepParameter::WorkOfAdhesion,
                SweepParameter::TaborParameter,
                SweepParameter::YieldStress,
            ] {
                check_other(
                    "Scene::with_parameter",
                    &[p],
                    &scene.with_parameter(parameter, p).map(|_| ()),
                )?;
            }
            Ok(())
        },
    );
}

/// A bundled scene with one value replaced by an arbitrary number (or token).
fn scene_text_group(cases: u32, _only: Option<u8>) {
    use tabor::scene::{Format, Scene};
    let template = include_str!("../examples/scenes/silica.toml");
    let keys: Vec<(usize, String)> = template
        .lines()
        .enumerate()
        .filter(|(_, l)| l.contains('=') && !l.trim_start().starts_with('#'))
        .map(|(i, l)| (i, l.split('=').next().unwrap_or("").trim().to_string()))
        .collect();
    let tokens = prop_oneof![
        x().prop_map(|v| format!("{v:e}")),
        prop::sample::select(vec![
            "nan".to_string(),
            "inf".into(),
            "-inf".into(),
            "\"1e-6\"".into(),
            "true".into(),
            "[]".into(),
            "{}".into(),
            "".into(),
            "1e999".into(),
            "0x10".into(),
            "\"load-controlled\"".into(),
            "\"bogus\"".into(),
        ]),
        "\\PC{0,12}",
    ];
    run(
        "scene_text",
        cases,
        (prop::sample::select(keys), tokens, any::<bool>()),
        |((line, key), token, rename)| {
            let text: String = template
                .lines()
                .enumerate()
                .map(|(i, l)| {
                    if i != line {
                        l.to_string()
                    } else if rename {
                        format!("{key}_typo = {token}")
                    } else {
                        format!("{key} = {token}")
                    }
                })
                .collect::<Vec<_>>()
                .join("\n");
            let scene = Scene::from_str(&text, Format::Toml);
            check_other("Scene::from_str", &[], &unit(&scene))?;
            if let Ok(scene) = scene {
                let o = scene.outcome();
                check_other("Scene::outcome", &[], &o)?;
                check_other("Scene::sticking_velocity", &[], &scene.sticking_velocity())?;
            } else if let Err(e) = scene {
                prop_assert!(
                    e.line.is_some() || e.field.is_some(),
                    "no position or field: {e}"
                );
            }
            Ok(())
        },
    );
}

/// Arbitrary text in both formats: no panic, one-line errors.
fn scene_garbage_group(cases: u32, _only: Option<u8>) {
    use tabor::scene::{Format, Scene};
    run(
        "scene_garbage",
        cases,
        prop_oneof![
            "\\PC{0,200}",
            "(\\[[a-z]{0,8}\\]\n([a-z_]{1,16} = [-0-9e.a-z\"]{0,10}\n){0,4}){0,6}",
            "\\{(\"[a-z_]{1,12}\": ?(\\{[^{}]{0,40}\\}|[-0-9e.]{1,8}|\"[a-z]*\"),? ?){0,6}\\}",
        ],
        |text: String| {
            for format in [Format::Toml, Format::Json] {
                let scene = Scene::from_str(&text, format);
                check_other("Scene::from_str", &[], &unit(&scene))?;
                if let Ok(scene) = scene {
                    check_other("Scene::outcome", &[], &scene.outcome())?;
                }
            }
            Ok(())
        },
    );
}

// ---------------------------------------------------------------------------
// Tests: CI variants (`PROPTEST_CASES`, default 256) and the full run (ignored).

fuzz_tests! {
    scene_builder_group: fuzz_scene_builder, full_scene_builder, 4;
    scene_text_group: fuzz_scene_text, full_scene_text, 1;
    scene_garbage_group: fuzz_scene_garbage, full_scene_garbage, 1;
}
