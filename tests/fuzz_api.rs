#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Property-based fuzzing of the public API (issue 9): every public constructor and
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
//! This file: restitution (effective quantities and checks), numerics, the elastic
//! contacts and impacts, JKR (sphere, power-law profile, graded sphere),
//! Maugis-Dugdale and the time-domain simulator. The dissipative models are in
//! `fuzz_api_dissipative.rs`, the scenes in `fuzz_api_scenes.rs`.
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
use proptest::test_runner::TestCaseError;
use tabor::restitution;

mod common;

use common::{
    check, check_e, check_model, check_other, fuzz_tests, phys, run, tol, u, unit, variant, x,
};

// ---------------------------------------------------------------------------
// Properties, one group per crate (or per part of a crate)

fn restitution_group(cases: u32, _only: Option<u8>) {
    use restitution::checks::{elastic_limit_check, quasi_static_check};
    use restitution::effective::{effective_modulus, effective_radius, reduced_mass, sphere_mass};
    use restitution::ElasticMaterial;
    run(
        "restitution",
        cases,
        (x(), u(), x(), u(), x(), x(), x(), any::<bool>()),
        |(e1, nu1, e2, nu2, a, b, c, rigid)| {
            let m1 = ElasticMaterial::new(e1, nu1);
            check("ElasticMaterial::new", &[e1, nu1], &m1)?;
            let m2 = if rigid {
                Ok(ElasticMaterial::rigid())
            } else {
                ElasticMaterial::new(e2, nu2)
            };
            if let (Ok(m1), Ok(m2)) = (&m1, &m2) {
                check("effective_modulus", &[e1, nu1], &effective_modulus(m1, m2))?;
            }
            check("effective_radius", &[a, b], &effective_radius(a, Some(b)))?;
            check("effective_radius", &[a], &effective_radius(a, None))?;
            check("reduced_mass", &[a, b], &reduced_mass(a, Some(b)))?;
            check("reduced_mass", &[a], &reduced_mass(a, None))?;
            check("sphere_mass", &[a, b], &sphere_mass(a, b))?;
            check_e(
                "restitution_from_loss",
                &[a, b, c],
                &restitution::restitution_from_loss(a, b, c),
            )?;
            check(
                "quasi_static_check",
                &[a, b, c],
                &quasi_static_check(a, b, c),
            )?;
            check(
                "elastic_limit_check",
                &[e1, a, b, c, e2],
                &elastic_limit_check(e1, a, b, c, e2),
            )?;
            Ok(())
        },
    );
}

fn numerics_group(cases: u32, _only: Option<u8>) {
    use tabor::numerics::quadrature::integrate_smooth;
    use tabor::numerics::root_finding::brent;
    use tabor::numerics::special::*;
    use tabor::numerics::{GaussLegendre, QuadTolerance, RootTolerance};
    run(
        "numerics",
        cases,
        (x(), u(), u(), x(), x(), tol(), 0usize..80),
        |(a, b, c, lo, hi, t, n)| {
            check_other("gamma", &[a], &gamma(a))?;
            check_other("ln_gamma", &[a], &ln_gamma(a))?;
            check_other("beta", &[a, b], &beta(a, b))?;
            check_other(
                "regularized_incomplete_beta",
                &[c, a, b],
                &regularized_incomplete_beta(c, a, b),
            )?;
            check_other("incomplete_beta", &[c, a, b], &incomplete_beta(c, a, b))?;
            check_other("power_law_beta", &[b], &power_law_beta(b))?;
            check_other(
                "graded_power_law_beta",
                &[b, c],
                &graded_power_law_beta(b, c),
            )?;
            check_other("gamma_ratio", &[a, b], &gamma_ratio(a, b))?;
            let tolerance = RootTolerance {
                absolute: 0.0,
                relative: t,
                max_iterations: 200,
            };
            check_other(
                "brent",
                &[lo, hi, a, t],
                &brent(|v| v - a, lo, hi, tolerance),
            )?;
            check_other(
                "integrate_smooth",
                &[lo, hi, t],
                &integrate_smooth(|v| v * v - a * v, lo, hi, QuadTolerance::relative(t)),
            )?;
            if let Ok(g) = GaussLegendre::new(n) {
                // plain f64 (no Result): finite bounds and integrand give a finite value
                let v = g.integrate(|v| v * v, -1.0, 2.0);
                prop_assert!(v.is_finite(), "GaussLegendre({n}) gave {v}");
            }
            Ok(())
        },
    );
}

fn elastic_group(cases: u32, only: Option<u8>) {
    use tabor::elastic::trajectory::{
        harmonic_normalized_time, normalized_contact_time, normalized_time,
    };
    use tabor::elastic::{ElasticContact, ElasticImpact};
    run(
        "elastic",
        cases,
        (
            phys(1e3, 1e13),
            phys(1e-9, 1.0),
            u(),
            u(),
            phys(1e-20, 1e3),
            phys(1e-4, 1e3),
            u(),
            variant(4, only),
        ),
        |(e, r, n, k, m, v, s, which)| {
            let (c, inputs) = match which {
                0 => (ElasticContact::hertz(e, r), vec![e, r]),
                1 => (ElasticContact::power_law(e, r, n), vec![e, r, n]),
                2 => (ElasticContact::graded_sphere(e, k, r), vec![e, k, r]),
                _ => (
                    ElasticContact::graded_power_law(e, k, r, n),
                    vec![e, k, r, n],
                ),
            };
            check("ElasticContact", &inputs, &c)?;
            check("normalized_time", &[s, n], &normalized_time(s, n))?;
            check("normalized_contact_time", &[n], &normalized_contact_time(n))?;
            check(
                "harmonic_normalized_time",
                &[s],
                &harmonic_normalized_time(s),
            )?;
            let Ok(c) = c else { return Ok(()) };
            if s.is_finite() {
                for f in [
                    c.force(s),
                    c.stiffness(s),
                    c.contact_radius(s),
                    c.stored_energy(s),
                ] {
                    prop_assert!(!f.is_nan(), "contact function at {s} gave NaN ({c:?})");
                }
            }
            let imp = ElasticImpact::new(c, m);
            check("ElasticImpact::new", &[m], &imp)?;
            let Ok(imp) = imp else { return Ok(()) };
            check("max_overlap", &[v], &imp.max_overlap(v))?;
            check("max_force", &[v], &imp.max_force(v))?;
            check("max_contact_radius", &[v], &imp.max_contact_radius(v))?;
            check("contact_time", &[v], &imp.contact_time(v))?;
            check("max_pressure", &[v], &imp.max_pressure(v))?;
            if let Ok(d) = imp.max_overlap(v) {
                check(
                    "time_at_overlap",
                    &[v],
                    &imp.time_at_overlap(v, d * s.abs()),
                )?;
            }
            if let Ok(t) = imp.contact_time(v) {
                check("hunter_overlap", &[v], &imp.hunter_overlap(v, t * s.abs()))?;
            }
            check_model("ElasticImpact", &[e, r, m], &imp, v, 1e-8)
        },
    );
}

fn jkr_group(cases: u32, only: Option<u8>) {
    use tabor::jkr::{
        normalized, GradedSphere, JkrImpact, JkrSphere, PowerLawProfile, SeparationRule,
    };
    run(
        "jkr",
        cases,
        (
            phys(1e3, 1e13),
            phys(1e-9, 1.0),
            phys(1e-4, 10.0),
            phys(1e-20, 1e3),
            phys(1e-5, 1e2),
            u(),
            x(),
            (variant(3, only), any::<bool>(), tol()),
        ),
        |(e, r, w, m, v, n, a, (which, load, t))| {
            let rule = if load {
                SeparationRule::LoadControlled
            } else {
                SeparationRule::FixedGrip
            };
            check("normalized::force", &[a], &normalized::force(a))?;
            check("normalized::depth", &[a], &normalized::depth(a))?;
            check(
                "normalized::kinetic_energy_to_reach",
                &[a],
                &normalized::kinetic_energy_to_reach(a),
            )?;
            check(
                "normalized::max_contact_radius",
                &[a, t],
                &normalized::max_contact_radius(a, t),
            )?;
            check(
                "normalized::energy_loss",
                &[t],
                &normalized::energy_loss(rule, t),
            )?;
            match which {
                0 => {
                    let s = JkrSphere::new(e, r, w);
                    check("JkrSphere::new", &[e, r, w], &s)?;
                    let Ok(s) = s else { return Ok(()) };
                    check("JkrSphere::force", &[a], &s.force(a))?;
                    check("JkrSphere::depth", &[a], &s.depth(a))?;
                    jkr_impact(JkrImpact::new(s, m), rule, &[e, r, w, m], v, t)
                }
                1 => {
                    let p = PowerLawProfile::new(e, n, r, w);
                    check("PowerLawProfile::new", &[e, n, r, w], &p)?;
                    let Ok(p) = p else { return Ok(()) };
                    check("PowerLawProfile::force", &[a], &p.force(a))?;
                    check("PowerLawProfile::depth", &[a], &p.depth(a))?;
                    jkr_impact(JkrImpact::new(p, m), rule, &[e, n, r, w, m], v, t)
                }
                _ => {
                    let k = n;
                    let g = GradedSphere::new(e, k, r, w);
                    check("GradedSphere::new", &[e, k, r, w], &g)?;
                    let Ok(g) = g else { return Ok(()) };
                    check("GradedSphere::force", &[a], &g.force(a))?;
                    check("GradedSphere::depth", &[a], &g.depth(a))?;
                    check(
                        "GradedSphere::loss_ratio_to_homogeneous",
                        &[a],
                        &g.loss_ratio_to_homogeneous(a),
                    )?;
                    jkr_impact(JkrImpact::new(g, m), rule, &[e, k, r, w, m], v, t)
                }
            }
        },
    );
}

fn jkr_impact<C: tabor::jkr::AdhesiveContact>(
    imp: tabor::restitution::Result<tabor::jkr::JkrImpact<C>>,
    rule: tabor::jkr::SeparationRule,
    inputs: &[f64],
    v: f64,
    t: f64,
) -> Result<(), TestCaseError> {
    check("JkrImpact::new", inputs, &unit(&imp))?;
    let Ok(imp) = imp else { return Ok(()) };
    let imp = imp.with_separation(rule);
    check("adhesive_energy_loss", inputs, &imp.adhesive_energy_loss())?;
    check(
        "JkrImpact::max_contact_radius",
        &[v],
        &imp.max_contact_radius(v),
    )?;
    check_model("JkrImpact", inputs, &imp, v, 1e-8)?;
    check(
        "JkrImpact::with_tolerance",
        &[t],
        &imp.with_tolerance(t).map(|_| ()),
    )
}

fn maugis_group(cases: u32, only: Option<u8>) {
    use tabor::jkr::JkrSphere;
    use tabor::maugis::units::*;
    use tabor::maugis::*;
    run(
        "maugis",
        cases,
        (
            phys(1e-4, 1e6),
            x(),
            phys(1e3, 1e13),
            phys(1e-9, 1.0),
            phys(1e-4, 10.0),
            phys(1e-20, 1e3),
            phys(1e-5, 1e2),
            (
                x(),
                variant(3, only),
                prop_oneof![0usize..40, any::<usize>()],
            ),
        ),
        |(lambda, d, e, r, w, m, v, (s, which, points))| {
            let _ = TaborCase::of(d);
            check("impact_path", &[lambda], &impact_path(lambda))?;
            check("loss_over_jkr_fast", &[lambda], &loss_over_jkr_fast(lambda))?;
            check("normalized_loss", &[lambda], &normalized_loss(lambda, 1e-8))?;
            check(
                "equilibrium_state",
                &[lambda, d],
                &equilibrium_state(lambda, d),
            )?;
            check(
                "trace_impact",
                &[lambda, s],
                &trace_impact(lambda, s, points),
            )?;
            check("JkrScales::new", &[e, r, w], &JkrScales::new(e, r, w))?;
            check(
                "tabor_parameter_from_cohesive_stress",
                &[s, w, e, r],
                &tabor_parameter_from_cohesive_stress(s, w, e, r),
            )?;
            check(
                "tabor_parameter_from_range",
                &[s, w, e, r],
                &tabor_parameter_from_range(s, w, e, r),
            )?;
            check(
                "tabor_parameter_from_maugis",
                &[s],
                &tabor_parameter_from_maugis(s),
            )?;
            check(
                "tabor_parameter_from_tabor_mu",
                &[s],
                &tabor_parameter_from_tabor_mu(s),
            )?;
            check("maugis_parameter", &[s], &maugis_parameter(s))?;
            let (model, inputs) = match which {
                0 => (
                    JkrSphere::new(e, r, w)
                        .and_then(|sphere| MaugisContact::new(sphere, lambda))
                        .and_then(|contact| MaugisDugdaleImpact::new(contact, m)),
                    [e, r, w, lambda, m],
                ),
                1 => (
                    JkrSphere::new(e, r, w)
                        .and_then(|sphere| MaugisContact::from_cohesive_stress(sphere, s))
                        .and_then(|contact| MaugisDugdaleImpact::new(contact, m)),
                    [e, r, w, s, m],
                ),
                _ => (
                    JkrSphere::new(e, r, w)
                        .and_then(|sphere| MaugisContact::from_range(sphere, s))
                        .and_then(|contact| MaugisDugdaleImpact::new(contact, m)),
                    [e, r, w, s, m],
                ),
            };
            check("MaugisDugdaleImpact", &inputs, &unit(&model))?;
            let Ok(model) = model else { return Ok(()) };
            check(
                "MaugisDugdaleImpact::with_tolerance",
                &[d],
                &model.clone().with_tolerance(d).map(|_| ()),
            )?;
            let model = model.with_tolerance(1e-8).expect("valid tolerance");
            check(
                "energy_loss_joules",
                &[e, r, w],
                &model.energy_loss_joules(),
            )?;
            check(
                "MaugisDugdaleForceLaw::new",
                &[],
                &MaugisDugdaleForceLaw::new(&model).map(|_| ()),
            )?;
            check_model("MaugisDugdaleImpact", &[e, r, w, m], &model, v, 1e-8)
        },
    );
}

fn dynamics_group(cases: u32, _only: Option<u8>) {
    use tabor::dynamics::{simulate_impact, SimulatedImpact, SimulationSettings};
    use tabor::elastic::ElasticContact;
    run(
        "dynamics",
        cases,
        (
            phys(1e5, 1e12),
            phys(1e-9, 1.0),
            phys(1e-20, 1e3),
            phys(1e-4, 1e3),
            tol(),
        ),
        |(e, r, m, v, t)| {
            let settings = SimulationSettings::with_tolerance(t);
            check("SimulationSettings::with_tolerance", &[t], &unit(&settings))?;
            let settings = settings.unwrap_or_default();
            let Ok(mut law) = ElasticContact::hertz(e, r) else {
                return Ok(());
            };
            let s = simulate_impact(&mut law, m, v, &settings);
            check("simulate_impact", &[m, v], &s)?;
            if let Ok(s) = s {
                // a simulated elastic rebound is exact to the requested accuracy of
                // the outcome (with_tolerance integrates at 1/100 of it; the default
                // settings are with_tolerance(1e-9)), not better: e ≤ 1 + requested
                let t = 100.0 * settings.tolerance.relative;
                prop_assert!(
                    s.restitution >= 0.0 && s.restitution <= 1.0 + t,
                    "e = {} at tolerance {t}",
                    s.restitution
                );
            }
            let sim = SimulatedImpact::new(law, m, settings);
            check("SimulatedImpact::new", &[m], &unit(&sim))?;
            Ok(())
        },
    );
}

// ---------------------------------------------------------------------------
// Tests: CI variants (`PROPTEST_CASES`, default 256) and the full run (ignored).

fuzz_tests! {
    restitution_group: fuzz_restitution, full_restitution, 1;
    numerics_group: fuzz_numerics, full_numerics, 1;
    elastic_group: fuzz_elastic, full_elastic, 4;
    jkr_group: fuzz_jkr, full_jkr, 3;
    maugis_group: fuzz_maugis, full_maugis, 3;
    dynamics_group: fuzz_dynamics, full_dynamics, 1;
}
