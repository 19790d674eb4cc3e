#![allow(clippy::unwrap_used, clippy::expect_used)]
//! `export_plugin` (the fragment for `pair_style tabor`) against the scenes'
//! numbers computed here by hand: E* = E/(2(1 − ν²)) for two equal spheres, w, Λ,
//! the Kuwabara-Kono time A = 4η(1 − ν²)/E of two equal Kelvin-Voigt bodies, the
//! neighbor skin against the interaction range, the pull-off force against
//! Maugis's own solution and the restitution against a velocity-Verlet run of the
//! plugin's force law, and the refusals.

use std::f64::consts::PI;
use std::path::PathBuf;
use tabor_ffi::{ContactLaw, TaborHistory};
use tabor_lammps::{
    export_plugin, export_plugin_wall, plugin_load_command, ExportError, PluginModel,
    PLUGIN_RESTITUTION_ERROR,
};
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
    // the Maugis-Dugdale pull-off force lies between JKR's 1.5 and DMT's 2 pi w R*,
    // at Maugis's own solution (1992, his normalization, solved here)
    let r = 0.5e-6;
    let p = -x.pull_off_force / (PI * 0.05 * r);
    assert!(p > 1.5 && p < 2.0, "{p}");
    let lambda = 0.55 / (PI * (9.0f64 / 4.0).cbrt() / 6.0);
    let maugis = -maugis_pull_off(lambda);
    assert!((p / maugis - 1.0).abs() < 1e-4, "{p} vs Maugis {maugis}");
    // tabor's restitution at the scene speed against a velocity-Verlet run of the
    // plugin's own force law (tabor-ffi), the way LAMMPS integrates it
    let at = x
        .restitution
        .iter()
        .find(|s| (s.speed / 0.08 - 1.0).abs() < 1e-12)
        .expect("scene speed");
    let law = ContactLaw::maugis_dugdale(x.effective_modulus, x.effective_radius, 0.05, 0.55)
        .expect("law");
    let e = verlet_restitution(&law, x.effective_mass, 0.08, x.time_step);
    assert!(
        (at.restitution - e).abs() < PLUGIN_RESTITUTION_ERROR,
        "{} vs Verlet {e}",
        at.restitution
    );
}

/// Maugis (1992) in his own units: lambda = 2 sigma0 (R/(pi w K^2))^(1/3), K = 4E*/3,
/// A = a (K/(pi w R^2))^(1/3), P = F/(pi w R), m = c/a; with s = sqrt(m^2 - 1),
/// t = atan(s): the gap condition
/// lambda A^2/2 [s + (m^2 - 2) t] + 4 lambda^2 A/3 [s t - m + 1] = 1 and
/// P = A^3 - lambda A^2 (s + m^2 t). Returns min P over A > 0 (the pull-off under
/// load control), by a scan and golden-section refinement.
fn maugis_pull_off(lambda: f64) -> f64 {
    let load = |a: f64| -> f64 {
        let gap = |m: f64| {
            let s = (m * m - 1.0).sqrt();
            let t = s.atan();
            lambda * a * a / 2.0 * (s + (m * m - 2.0) * t)
                + 4.0 * lambda * lambda * a / 3.0 * (s * t - m + 1.0)
                - 1.0
        };
        let (mut lo, mut hi) = (1.0, 2.0);
        while gap(hi) < 0.0 {
            hi *= 2.0;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if gap(mid) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let m = 0.5 * (lo + hi);
        let s = (m * m - 1.0).sqrt();
        a.powi(3) - lambda * a * a * (s + m * m * s.atan())
    };
    let n = 4000;
    let (mut best, mut at) = (f64::INFINITY, 0.0);
    for i in 1..=n {
        let a = 3.0 * i as f64 / n as f64;
        let p = load(a);
        if p < best {
            best = p;
            at = a;
        }
    }
    let (mut lo, mut hi) = (at - 3.0 / n as f64, at + 3.0 / n as f64);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if load(x1) < load(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    load(0.5 * (lo + hi))
}

/// The restitution of one central impact of reduced mass `m` at `v` (m/s) under
/// `law`, by velocity Verlet with time step `dt` (s), started outside the
/// interaction range: what LAMMPS does with pair_style tabor.
fn verlet_restitution(law: &ContactLaw, m: f64, v: f64, dt: f64) -> f64 {
    let mut history = TaborHistory::default();
    let mut d = law.jump_in_overlap().min(0.0) - 20.0 * v * dt;
    let mut rate = v;
    let mut f = law.evaluate(d, rate, &mut history).expect("force").force;
    let mut formed = false;
    for _ in 0..10_000_000 {
        let half = rate - 0.5 * dt * f / m;
        d += dt * half;
        f = law.evaluate(d, half, &mut history).expect("force").force;
        rate = half - 0.5 * dt * f / m;
        formed |= history.contact != 0.0;
        if formed && history.contact == 0.0 && rate < 0.0 {
            return -rate / v;
        }
    }
    0.0
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
    ] {
        match export_plugin(&scene(path), SO, None) {
            Err(ExportError::Unrepresentable { effect: e, .. }) => {
                assert!(e.starts_with(effect), "{path}: {e}")
            }
            other => panic!("{path}: {other:?}"),
        }
    }
}

/// A flat target: the wall fix with pair_coeff's MODEL ARGS, E* of sphere and wall
/// (1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2 = 2(1 − ν²)/E for the silica wall), R* = R;
/// the default wall zplane 0.0 NULL, another with --wall, bad walls refused, and
/// --wall refused for two spheres.
#[test]
fn a_flat_target_is_the_wall_fix() {
    let s = scene("integrations/lammps/scenes/maugis_wall.toml");
    let x = export_plugin(&s, SO, None).expect("export");
    let f = x.fragment();
    let e_star = 54e9 / (2.0 * (1.0 - 0.17f64 * 0.17));
    let line = f
        .lines()
        .find(|l| l.starts_with("fix tabor_wall all wall/tabor "))
        .expect("fix line");
    let words: Vec<&str> = line.split_whitespace().collect();
    assert_eq!(words[4], "maugis");
    let n: Vec<f64> = words[5..8]
        .iter()
        .map(|w| w.parse().expect("number"))
        .collect();
    assert!((n[0] / e_star - 1.0).abs() < 1e-10, "{} {e_star}", n[0]);
    assert!((n[1] / 0.05 - 1.0).abs() < 1e-10);
    assert!((n[2] / 0.55 - 1.0).abs() < 1e-10);
    assert_eq!(&words[8..], ["zplane", "0.0", "NULL"]);
    assert!((x.effective_radius / 1e-6 - 1.0).abs() < 1e-12);
    assert!(!f.lines().any(|l| l.starts_with("pair_style")));
    assert!(f.contains("# Include after atom_style sphere / create_box"));
    assert_eq!(x.wall.as_deref(), Some("zplane 0.0 NULL"));
    let y = export_plugin_wall(&s, SO, None, Some(" xplane  -1e-5 NULL")).expect("export");
    assert!(y
        .fragment()
        .lines()
        .any(|l| l.ends_with(" xplane -1e-5 NULL")));
    let y = export_plugin_wall(&s, SO, None, Some("zcylinder 2e-4")).expect("export");
    assert!(y.fragment().lines().any(|l| l.ends_with(" zcylinder 2e-4")));
    for bad in [
        "",
        "zplane 0",
        "zplane NULL NULL",
        "plane 0 1",
        "zcylinder x",
        "zplane 0 inf",
    ] {
        match export_plugin_wall(&s, SO, None, Some(bad)) {
            Err(ExportError::Model(m)) => assert!(m.contains("--wall"), "{bad}: {m}"),
            other => panic!("{bad}: {other:?}"),
        }
    }
    let pair = scene("integrations/lammps/scenes/maugis_case2.toml");
    assert!(export_plugin_wall(&pair, SO, None, Some("zplane 0 NULL")).is_err());
}

/// `--check` reads the wall line of the export without --plugin (LAMMPS's own
/// `fix wall/gran granular`), and a `fix wall/tabor` line is answered with what
/// it is (tabor's own law, which --check does not predict) instead of a parse error.
#[test]
fn check_reads_the_wall_gran_line_and_names_wall_tabor() {
    let s = scene("integrations/lammps/scenes/maugis_wall.toml");
    let x = tabor_lammps::export(&s, None).expect("export");
    let line = x
        .fragment()
        .lines()
        .find(|l| l.starts_with("fix ") && l.contains(" wall/gran granular "))
        .expect("wall/gran line")
        .to_string();
    assert!(tabor_lammps::check(&s, &line, None, &[]).is_ok());
    let e =
        tabor_lammps::parse_line("fix w all wall/tabor maugis 2.78e10 0.05 0.55 zplane 0.0 NULL")
            .expect_err("refused");
    assert!(e.to_string().contains("tabor's own force law"), "{e}");
}

#[test]
fn per_contact_lambda_writes_the_range_form() {
    use tabor_lammps::{export_plugin_with, PluginOptions};
    let on = PluginOptions {
        per_contact_lambda: true,
        ..PluginOptions::default()
    };
    // the scene gives the range 0.3 nm: written back to 10 digits
    let s = scene("examples/scenes/silica_maugis.toml");
    let x = export_plugin_with(&s, SO, None, on.clone()).expect("export");
    let f = x.fragment();
    let line = f.lines().find(|l| l.starts_with("pair_coeff")).unwrap();
    let words: Vec<&str> = line.split_whitespace().collect();
    assert_eq!(words[3..5].len(), 2);
    assert_eq!(words[6], "range", "{line}");
    let h: f64 = words[7].parse().unwrap();
    assert!((h / 0.3e-9 - 1.0).abs() < 1e-10, "{h}");
    assert_eq!(x.dugdale_range, Some(h));
    // by hand: Λ = d_n/h, d_n = (9π w R*²/(8E*))^(2/3)/(3R*) at R* = 0.5 µm
    let e_star = 54e9 / (2.0 * (1.0 - 0.17f64 * 0.17));
    let r = 0.5e-6;
    let d_n = (9.0 * PI * 0.05 * r * r / (8.0 * e_star)).powf(2.0 / 3.0) / (3.0 * r);
    assert!((x.tabor_parameter.unwrap() / (d_n / 0.3e-9) - 1.0).abs() < 1e-12);
    assert!(f.contains("held fixed: each contact's Lambda = d_n(R*)/h"));
    // a scene given by Λ: h = d_n/Λ, so the scene's own pair gets exactly its Λ
    let s2 = scene("integrations/lammps/scenes/maugis_case2.toml");
    let x2 = export_plugin_with(&s2, SO, None, on.clone()).expect("export");
    let law = ContactLaw::maugis_dugdale_range(e_star, r, 0.05, x2.dugdale_range.unwrap()).unwrap();
    let l = law.tabor_parameter_at(&law.scales(r).unwrap()).unwrap();
    assert!((l / 0.55 - 1.0).abs() < 1e-12, "{l}");
    // the fixed form is unchanged without the option
    let plain = export_plugin(&s, SO, None).unwrap();
    assert_eq!(plain.dugdale_range, None);
    let plain_coeff = plain.fragment();
    let plain_coeff = plain_coeff
        .lines()
        .find(|l| l.starts_with("pair_coeff"))
        .unwrap();
    assert_eq!(plain_coeff.split_whitespace().count(), 7, "{plain_coeff}");
    assert!(plain.fragment().contains("--per-contact-lambda writes"));
    // not Maugis-Dugdale: refused by name
    let e = export_plugin_with(&scene("examples/scenes/silica.toml"), SO, None, on.clone())
        .unwrap_err();
    assert!(e.to_string().contains("per-contact"), "{e}");
}

#[test]
fn check_reads_the_exported_range_form() {
    use tabor_lammps::{check_plugin, export_plugin_with, is_plugin_line, PluginOptions};
    let s = scene("examples/scenes/silica_maugis.toml");
    let on = PluginOptions {
        per_contact_lambda: true,
        ..PluginOptions::default()
    };
    let frag = export_plugin_with(&s, SO, None, on.clone())
        .unwrap()
        .fragment();
    let line = frag.lines().find(|l| l.starts_with("pair_coeff")).unwrap();
    assert!(is_plugin_line(line));
    assert!(!is_plugin_line(
        "pair_coeff * * hertz/material 54e9 0.5 0.17"
    ));
    let c = check_plugin(&s, line, None, &[]).unwrap();
    // the scene's own Λ (range 0.3 nm at R* = 0.5 µm), by hand as above
    let e_star = 54e9 / (2.0 * (1.0 - 0.17f64 * 0.17));
    let r = 0.5e-6;
    let d_n = (9.0 * PI * 0.05 * r * r / (8.0 * e_star)).powf(2.0 / 3.0) / (3.0 * r);
    assert!((c.tabor_parameter.unwrap() / (d_n / 0.3e-9) - 1.0).abs() < 1e-9);
    // the plugin's law integrated at t_c/20000 against tabor's restitution: the
    // bound the plugin is verified to in LAMMPS
    assert!(c.decade.len() >= 5);
    for p in &c.decade {
        let t = p.tabor.unwrap();
        assert!((p.lammps - t).abs() <= PLUGIN_RESTITUTION_ERROR, "{p:?}");
    }
    // stress s0 = w/h: the same law; a fixed Λ at the contact's Λ: the same within
    // the table over Λ's error (a restitution moves far less than 1e-5 here)
    let stress = line.replace(
        "range 3.0000000000e-10",
        &format!("stress {:e}", 0.05 / 0.3e-9),
    );
    let c2 = check_plugin(&s, &stress, None, &[]).unwrap();
    assert!((c2.at_speed.lammps - c.at_speed.lammps).abs() < 1e-12);
    let fixed = line.replace(
        "range 3.0000000000e-10",
        &format!("{:e}", c.tabor_parameter.unwrap()),
    );
    let c3 = check_plugin(&s, &fixed, None, &[]).unwrap();
    assert_eq!(c3.dugdale_range, None);
    assert!((c3.at_speed.lammps - c.at_speed.lammps).abs() < 1e-5);
    // bad input named
    for (bad, name) in [
        (
            line.replace("range 3.0000000000e-10", "range -1e-9"),
            "range",
        ),
        (
            line.replace("range 3.0000000000e-10", "0.3 range 3e-10"),
            "tabor_parameter",
        ),
    ] {
        let e = check_plugin(&s, &bad, None, &[]).unwrap_err().to_string();
        assert!(e.contains(name), "{e}");
    }
}

/// `--check` reads the plugin's material form (`material E nu gamma MODEL …`) as
/// the plugin does for one material: E* = E/(2(1 − ν²)) and w = 2γ, computed here
/// from the formulas; the prediction equals that of the E*/w line with those
/// numbers, and bad material numbers are named.
#[test]
fn check_reads_the_material_form() {
    use tabor_lammps::{check_plugin, is_plugin_line};
    let s = scene("examples/scenes/silica.toml");
    let (e, nu, gamma): (f64, f64, f64) = (54e9, 0.17, 0.025);
    let material = format!("pair_coeff * * material {e} {nu} {gamma} jkr/fixed-grip");
    assert!(is_plugin_line(&material));
    assert!(!is_plugin_line("pair_coeff * * material 54e9 0.17 0.025"));
    // E* = E/(2(1 − ν²)), in the plugin's order of operations (tabor_mix_modulus
    // in plugin/tabor_coeff.cpp: 1/((1 − ν²)/E + (1 − ν²)/E)), so that the
    // prediction is of the plugin's law to the bit
    let e_star = 1.0 / ((1.0 - nu * nu) / e + (1.0 - nu * nu) / e);
    assert!((e_star / (e / (2.0 * (1.0 - nu * nu))) - 1.0).abs() < 1e-15);
    let direct = format!("pair_coeff * * jkr/fixed-grip {e_star:e} {:e}", 2.0 * gamma);
    let (a, b) = (
        check_plugin(&s, &material, Some(0.2), &[]).unwrap(),
        check_plugin(&s, &direct, Some(0.2), &[]).unwrap(),
    );
    assert_eq!(a.effective_modulus, e_star);
    assert_eq!(a.work_of_adhesion, 2.0 * gamma);
    assert_eq!(a.at_speed, b.at_speed);
    assert!(a.notes.iter().any(|n| n.contains("w = 2 gamma")));
    for (bad, name) in [
        ("material 54e9 0.5 0.025", "nu = 0.5"),
        ("material -1 0.17 0.025", "E = -1"),
        ("material 54e9 0.17 -0.1", "gamma = -0.1"),
    ] {
        let line = format!("pair_coeff * * {bad} maugis 0.5");
        let err = check_plugin(&s, &line, None, &[]).unwrap_err().to_string();
        assert!(err.contains(name), "{err}");
    }
}
