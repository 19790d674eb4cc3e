#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Property-based fuzzing of the public API (issue 9), the dissipative models: the
//! plastic contacts and impacts (Thornton, the interpolation model, the adhesive
//! interpolation model, superposition, the dimensionless fit, Jackson-Green), the
//! viscoelastic models and the penalty (DEM) laws. Every public constructor and
//! function gets arbitrary f64 values — NaN, ±∞, ±0, subnormals, ±f64::MAX, negative,
//! tiny and huge magnitudes, and plausible physical values so that deep code paths
//! are reached. Each call must not panic, and must give either
//!
//! - a result whose every number is finite (checked on its `Debug` form), with
//!   restitution coefficients in [0, 1], or
//! - a typed error; an error for a non-finite input must be
//!   `Error::InvalidParameter` (naming the parameter and its value), and every error
//!   message is one non-empty line.
//!
//! The elastic and adhesive models are in `fuzz_api.rs`, the scenes in
//! `fuzz_api_scenes.rs`.
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

use common::{check, check_e, check_model, fuzz_tests, phys, run, tol, u, unit, variant, x};

// ---------------------------------------------------------------------------
// Properties, one group per crate (or per part of a crate)

fn plastic_group(cases: u32, only: Option<u8>) {
    use tabor::jkr::JkrSphere;
    use tabor::plastic::*;
    run(
        "plastic",
        cases,
        (
            phys(1e5, 1e12),
            phys(1e-9, 1.0),
            phys(1e5, 1e10),
            phys(1e-4, 10.0),
            phys(1e-20, 1e3),
            phys(1e-4, 1e3),
            x(),
            (phys(1e-2, 1e2), u(), variant(6, only), phys(1e2, 2e4)),
        ),
        |(e, r, sy, w, m, v, a, (phi, nu, which, rho))| {
            check(
                "adhesion_parameter",
                &[e, r, sy, w],
                &adhesion_parameter(e, r, sy, w),
            )?;
            check("adhesive_yield_force", &[phi], &adhesive_yield_force(phi))?;
            check(
                "high_speed_restitution",
                &[a],
                &Thornton::high_speed_restitution(a),
            )?;
            check(
                "Interpolation::new",
                &[a, phi],
                &Interpolation::new(a, phi).map(|_| ()),
            )?;
            let ai = AdhesiveInterpolation::new(phi);
            check("AdhesiveInterpolation::new", &[phi], &unit(&ai))?;
            check(
                "AdhesiveInterpolation::with_constants",
                &[phi, a, nu],
                &AdhesiveInterpolation::with_constants(phi, a, nu).map(|_| ()),
            )?;
            if let Ok(ai) = &ai {
                let f = [ai.plastic_onset_depth(), ai.yield_kinetic_energy()];
                prop_assert!(f.iter().all(|v| v.is_finite()), "{f:?}");
                check("loading_force", &[a], &ai.loading_force(a))?;
                check(
                    "loading_contact_radius",
                    &[a],
                    &ai.loading_contact_radius(a),
                )?;
                check("loading_work", &[a], &ai.loading_work(a))?;
                check("max_depth", &[a], &ai.max_depth(a))?;
                check("turning_point", &[a], &ai.turning_point(a))?;
                check("energy_loss", &[a], &ai.energy_loss(a))?;
                check_e("restitution", &[a], &ai.restitution(a))?;
            }
            match which {
                0 | 1 => {
                    let c = PlasticContact::new(e, r, sy);
                    check("PlasticContact::new", &[e, r, sy], &c)?;
                    let Ok(c) = c else { return Ok(()) };
                    check("yield_velocity", &[m], &c.yield_velocity(m))?;
                    if which == 0 {
                        let p = PlasticImpact::new(c, Thornton, m);
                        check("PlasticImpact::new", &[m], &unit(&p))?;
                        let Ok(p) = p else { return Ok(()) };
                        check_e("PlasticImpact::restitution", &[v], &p.restitution(v))?;
                        check("PlasticImpact::max_depth", &[v], &p.max_depth(v))?;
                        check("PlasticImpact::residual_depth", &[v], &p.residual_depth(v))?;
                        check_model("PlasticImpact<Thornton>", &[e, r, sy, m], &p, v, 1e-8)
                    } else {
                        let p = PlasticImpact::new(c, Interpolation::default(), m);
                        let Ok(p) = p else { return Ok(()) };
                        let s = JkrSphere::new(e, r, w);
                        check("JkrSphere::new", &[e, r, w], &s)?;
                        let Ok(s) = s else { return Ok(()) };
                        let sp = Superposition::new(p, s);
                        check("Superposition::new", &[], &unit(&sp))?;
                        let Ok(sp) = sp else { return Ok(()) };
                        check_model("Superposition", &[e, r, sy, w, m], &sp, v, 1e-8)
                    }
                }
                2 => {
                    let imp = JkrSphere::new(e, r, w)
                        .and_then(|sphere| AdhesivePlasticContact::from_yield_stress(sphere, sy))
                        .and_then(|contact| AdhesiveInterpolationImpact::new(contact, m));
                    check(
                        "AdhesiveInterpolationImpact::from_yield_stress",
                        &[e, r, sy, w, m],
                        &unit(&imp),
                    )?;
                    let imp2 = JkrSphere::new(e, r, w)
                        .and_then(|sphere| AdhesivePlasticContact::new(sphere, phi))
                        .and_then(|contact| AdhesiveInterpolationImpact::new(contact, m));
                    check(
                        "AdhesiveInterpolationImpact::new",
                        &[e, r, w, phi, m],
                        &unit(&imp2),
                    )?;
                    let Ok(imp) = imp2 else { return Ok(()) };
                    let f = [imp.elastic_sticking_velocity(), imp.yield_velocity()];
                    prop_assert!(f.iter().all(|v| v.is_finite()), "{f:?}");
                    check_model(
                        "AdhesiveInterpolationImpact",
                        &[e, r, w, phi, m],
                        &imp,
                        v,
                        1e-8,
                    )
                }
                3 => {
                    let fit = DimensionlessFit::new(e, sy, rho, m);
                    check("DimensionlessFit::new", &[e, sy, rho, m], &unit(&fit))?;
                    let Ok(fit) = fit else { return Ok(()) };
                    let f = fit.restitution(v);
                    check("DimensionlessFit::restitution", &[v], &f)?;
                    if let Ok(f) = f {
                        prop_assert!((0.0..=1.0).contains(&f.restitution), "{f:?}");
                    }
                    check_model("DimensionlessFit", &[e, sy, rho, m], &fit, v, 1e-8)
                }
                _ => {
                    let jg = PlasticContact::new(e, r, sy)
                        .and_then(|contact| JacksonGreen::new(contact, nu));
                    check("JacksonGreen::new", &[e, r, sy, nu], &unit(&jg))?;
                    let Ok(jg) = jg else { return Ok(()) };
                    check(
                        "with_hardness_ratio",
                        &[a],
                        &jg.with_hardness_ratio(a).map(|_| ()),
                    )?;
                    check("JacksonGreen::yield_velocity", &[m], &jg.yield_velocity(m))?;
                    check("JacksonGreen::loading_force", &[a], &jg.loading_force(a))?;
                    check(
                        "JacksonGreen::loading_contact_radius",
                        &[a],
                        &jg.loading_contact_radius(a),
                    )?;
                    check("JacksonGreen::residual_depth", &[a], &jg.residual_depth(a))?;
                    Ok(())
                }
            }
        },
    );
}

/// The Jackson-Green time-domain model: few cases (one simulation each).
fn jackson_green_group(cases: u32, _only: Option<u8>) {
    use tabor::plastic::{JacksonGreen, PlasticContact, SimulationSettings};
    run(
        "jackson_green",
        cases,
        (
            phys(1e9, 1e12),
            phys(1e-4, 1e-1),
            phys(1e7, 1e10),
            phys(1e-8, 1e-1),
            phys(1e-2, 1e2),
            x(),
        ),
        |(e, r, sy, m, v, a)| {
            let Ok(jg) =
                PlasticContact::new(e, r, sy).and_then(|contact| JacksonGreen::new(contact, 0.3))
            else {
                return Ok(());
            };
            let imp = jg.impact(m, SimulationSettings::default());
            check("JacksonGreen::impact", &[m], &unit(&imp))?;
            let Ok(imp) = imp else { return Ok(()) };
            let s = imp.simulate(if a.is_nan() {
                v
            } else {
                v.min(a.abs().max(1e-3))
            });
            check("JacksonGreenImpact::simulate", &[], &s)?;
            if let Ok(s) = s {
                prop_assert!((0.0..=1.0).contains(&s.restitution), "{}", s.restitution);
            }
            Ok(())
        },
    );
}

fn visco_group(cases: u32, only: Option<u8>) {
    use tabor::visco::models::*;
    use tabor::visco::*;
    run(
        "visco",
        cases,
        (
            x(),
            x(),
            u(),
            x(),
            tol(),
            variant(8, only),
            phys(1e-3, 1e3),
            phys(1e-3, 1e3),
            any::<bool>(),
        ),
        |(a, b, nu, c, t, which, p, q, plausible)| {
            // dimensionless parameters: half of the time plausible (p, q), else anything
            let (a, b) = if plausible { (p, q) } else { (a, b) };
            match which {
                0 => {
                    check_e(
                        "kv_flat::restitution",
                        &[a],
                        &kelvin_voigt_flat::restitution(a),
                    )?;
                    check(
                        "kv_flat::contact_time",
                        &[a],
                        &kelvin_voigt_flat::contact_time(a),
                    )?;
                    check(
                        "kv_flat::damping_ratio",
                        &[a, b, c, nu],
                        &kelvin_voigt_flat::damping_ratio(a, b, c, nu),
                    )?;
                    check(
                        "kv_flat::natural_frequency",
                        &[a, b, c],
                        &kelvin_voigt_flat::natural_frequency(a, b, c),
                    )
                }
                1 => {
                    use kelvin_voigt_sphere as k;
                    for model in [SphereModel::KuwabaraKono, SphereModel::Rigorous] {
                        check_e("kv_sphere::restitution", &[a], &k::restitution(a, model))?;
                        check("kv_sphere::solve", &[a, t], &k::solve(a, model, t))?;
                        check(
                            "kv_sphere::viscous_parameter_for_restitution",
                            &[nu, t],
                            &k::viscous_parameter_for_restitution(nu, model, t),
                        )?;
                    }
                    check_e(
                        "kv_sphere::first_order_restitution",
                        &[a],
                        &k::first_order_restitution(a),
                    )?;
                    check(
                        "kv_sphere::viscous_parameter",
                        &[a, b, c, nu, p],
                        &k::viscous_parameter(a, b, c, nu, p),
                    )?;
                    check(
                        "kv_sphere::overlap_scale",
                        &[a, b, c, nu],
                        &k::overlap_scale(a, b, c, nu),
                    )
                }
                2 => {
                    use damping_law as d;
                    check("tsuji_damping", &[a], &d::tsuji_damping(a))?;
                    check(
                        "scaled_damping",
                        &[a, nu, b, c, p, q],
                        &d::scaled_damping(a, nu, b, c, p, q),
                    )?;
                    check_e("damping_law::restitution", &[nu, a], &d::restitution(nu, a))?;
                    check("damping_law::solve", &[nu, a, t], &d::solve(nu, a, t))
                }
                3 => {
                    use standard_flat as s;
                    check(
                        "standard_flat::parameters",
                        &[a, b, c, nu, p],
                        &s::parameters(a, b, c, nu, p),
                    )?;
                    check_e("standard_flat::restitution", &[a, b], &s::restitution(a, b))?;
                    check("standard_flat::solve", &[a, b, t], &s::solve(a, b, t))?;
                    check(
                        "standard_flat::equivalent_damping_ratio",
                        &[a, b],
                        &s::equivalent_damping_ratio(a, b),
                    )?;
                    check_e(
                        "standard_flat::equivalent_restitution",
                        &[a, b],
                        &s::equivalent_restitution(a, b),
                    )
                }
                4 => {
                    use standard_sphere as s;
                    check(
                        "standard_sphere::parameters",
                        &[a, b, c, nu, p, q],
                        &s::parameters(a, b, c, nu, p, q),
                    )?;
                    check_e(
                        "standard_sphere::restitution",
                        &[a, b],
                        &s::restitution(a, b),
                    )?;
                    check("standard_sphere::solve", &[a, b, t], &s::solve(a, b, t))
                }
                5 => {
                    use kelvin_maxwell_sphere as s;
                    check(
                        "kelvin_maxwell::parameters",
                        &[a, b, c, nu, p, q],
                        &s::parameters(a, b, c, nu, p, q),
                    )?;
                    check_e(
                        "kelvin_maxwell::restitution",
                        &[a, b],
                        &s::restitution(a, b),
                    )?;
                    check("kelvin_maxwell::solve", &[a, b, t], &s::solve(a, b, t))
                }
                6 => {
                    use compressible_flat as s;
                    check(
                        "compressible_flat::poisson_ratio",
                        &[a, b],
                        &s::poisson_ratio(a, b),
                    )?;
                    check(
                        "compressible_flat::damping_ratios",
                        &[a, b, c, nu, p, q],
                        &s::damping_ratios(a, b, c, nu, p, q),
                    )?;
                    check(
                        "compressible_flat::bulk_damping_ratio_equal_viscosities",
                        &[nu, a],
                        &s::bulk_damping_ratio_equal_viscosities(nu, a),
                    )?;
                    check_e(
                        "compressible_flat::restitution",
                        &[nu, a, b],
                        &s::restitution(nu, a, b),
                    )?;
                    check(
                        "compressible_flat::solve",
                        &[nu, a, b, t],
                        &s::solve(nu, a, b, t),
                    )
                }
                _ => {
                    // physical models: G, eta, radius, mass, speed
                    let (g, eta, r, m, v) = (a.abs() * 1e6, p, q * 1e-3, c.abs(), nu.abs() * 10.0);
                    let inputs = [g, eta, r, m];
                    if let Ok(k) = KelvinVoigtFlatPunch::new(g, eta, r, m) {
                        prop_assert!(k.damping_ratio().is_finite());
                        check_model("KelvinVoigtFlatPunch", &inputs, &k, v, 1e-8)?;
                    } else {
                        check(
                            "KelvinVoigtFlatPunch::new",
                            &inputs,
                            &KelvinVoigtFlatPunch::new(g, eta, r, m).map(|_| ()),
                        )?;
                    }
                    let k = KelvinVoigtSphere::new(g, eta, r, m, SphereModel::Rigorous);
                    check("KelvinVoigtSphere::new", &inputs, &unit(&k))?;
                    if let Ok(k) = k {
                        check(
                            "KelvinVoigtSphere::viscous_parameter",
                            &[v],
                            &k.viscous_parameter(v),
                        )?;
                        check_model("KelvinVoigtSphere", &inputs, &k, v, 1e-8)?;
                    }
                    for standard in [true, false] {
                        let s = if standard {
                            MaxwellBranchSphere::standard(g, b.abs() * 1e6, eta, r, m)
                        } else {
                            MaxwellBranchSphere::kelvin_maxwell(g, b.abs() * 1e6, eta, r, m)
                        };
                        check("MaxwellBranchSphere", &inputs, &unit(&s))?;
                        if let Ok(s) = s {
                            check("MaxwellBranchSphere::parameters", &[v], &s.parameters(v))?;
                            check_model("MaxwellBranchSphere", &inputs, &s, v, 1e-8)?;
                        }
                    }
                    Ok(())
                }
            }
        },
    );
}

fn penalty_group(cases: u32, only: Option<u8>) {
    use tabor::penalty::*;
    run(
        "penalty",
        cases,
        (
            x(),
            x(),
            u(),
            phys(1e-4, 1e2),
            phys(1e-3, 1e9),
            u(),
            phys(1e-6, 1e2),
            variant(5, only),
        ),
        |(a, b, e, v, k, n, l, which)| {
            check(
                "contact_characteristic",
                &[a, b],
                &contact_characteristic(a, b),
            )?;
            // documented: an infinite loss speed is the lossless limit
            check("loss_factor", &[a, b.min(f64::MAX)], &loss_factor(a, b))?;
            check_e(
                "characteristic_restitution",
                &[v, l.min(f64::MAX)],
                &characteristic_restitution(v, l),
            )?;
            // documented: an infinite loss speed is the lossless limit
            check_e(
                "characteristic_restitution",
                &[a, b.min(f64::MAX)],
                &characteristic_restitution(a, b),
            )?;
            // documented: ε = 1 (no loss) gives an infinite loss speed
            let ls = characteristic_loss_speed(e, v);
            if e != 1.0 || ls.is_err() {
                check("characteristic_loss_speed", &[e, v], &ls)?;
            }
            check("exact_damping_factor", &[e, v], &exact_damping_factor(e, v))?;
            check_e("damped_restitution", &[a, v], &damped_restitution(a, v))?;
            for model in DampingModel::ALL {
                check(model.name(), &[e, v], &model.damping_factor(e, v))?;
                let d = DampedPowerLaw::from_model(model, k, n, e, v);
                check("DampedPowerLaw::from_model", &[k, n, e, v], &unit(&d))?;
            }
            check(
                "PenaltyStiffness::new",
                &[k, n],
                &PenaltyStiffness::new(k, n).map(|_| ()),
            )?;
            check(
                "PenaltyStiffness::hertz",
                &[a, b],
                &PenaltyStiffness::hertz(a, b).map(|_| ()),
            )?;
            let d = DampedPowerLaw::new(k, n, b);
            check("DampedPowerLaw::new", &[k, n, b], &unit(&d))?;
            if let Ok(d) = &d {
                let f = [d.damping_coefficient()];
                prop_assert!(f.iter().all(|v| v.is_finite()), "{f:?}");
                check("DampedPowerLaw::force", &[a, b], &d.force(a, b))?;
                if which == 0 {
                    check_e("DampedPowerLaw::restitution", &[v], &d.restitution(v))?;
                }
            }
            let c = ContactCharacteristic::new(k, a.abs(), l);
            check(
                "ContactCharacteristic::new",
                &[k, a, l.min(f64::MAX)],
                &unit(&c),
            )?;
            if let Ok(c) = &c {
                check("ContactCharacteristic::force", &[a, b], &c.force(a, b))?;
                check_e(
                    "ContactCharacteristic::restitution",
                    &[v],
                    &c.restitution(v),
                )?;
                check("oscillation_loss", &[a, b], &c.oscillation_loss(a, b))?;
            }
            Ok(())
        },
    );
}

// ---------------------------------------------------------------------------
// Tests: CI variants (`PROPTEST_CASES`, default 256) and the full run (ignored).

fuzz_tests! {
    plastic_group: fuzz_plastic, full_plastic, 6;
    jackson_green_group: fuzz_jackson_green, full_jackson_green, 1;
    visco_group: fuzz_visco, full_visco, 8;
    penalty_group: fuzz_penalty, full_penalty, 5;
}
