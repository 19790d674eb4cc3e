//! Power-law profiles (5.39) and graded media (5.47)-(5.52) against independent
//! paths: the relations written out here, direct quadrature of ∫F dd, the elementary
//! antiderivative of F·dd/da, and the homogeneous sphere as a limit case.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::f64::consts::PI;
use tabor_jkr::{
    AdhesiveContact, GradedSphere, JkrImpact, JkrSphere, PowerLawProfile, SeparationRule,
};
use tabor_numerics::quadrature::integrate_smooth;
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_numerics::special::gamma;
use tabor_numerics::QuadTolerance;
use tabor_restitution::{sticking_velocity, Error, ImpactModel, StickingMethod};

const E: f64 = 2.78e10;
const R: f64 = 0.5e-6;
const DG: f64 = 0.05;
const MASS: f64 = 5.55e-15;

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// `d = P a^p − Q a^q`, `F = S a^s − T a^t`, written out per model below.
#[derive(Clone, Copy, Debug)]
struct Powers {
    p_coef: f64,
    p: f64,
    q_coef: f64,
    q: f64,
    s_coef: f64,
    s: f64,
    t_coef: f64,
    t: f64,
}

impl Powers {
    /// The brief's MDR relations for `f(r) = A rⁿ`, β(n) from Γ directly.
    fn power_law(e: f64, n: f64, a_coef: f64, dg: f64) -> Self {
        let beta = PI.sqrt() * gamma(0.5 * n + 1.0).unwrap() / gamma(0.5 * n + 0.5).unwrap();
        let c = (2.0 * PI * dg / e).sqrt();
        Powers {
            p_coef: beta * a_coef,
            p: n,
            q_coef: c,
            q: 0.5,
            s_coef: 2.0 * e * n / (n + 1.0) * beta * a_coef,
            s: n + 1.0,
            t_coef: 2.0 * e * c,
            t: 1.5,
        }
    }
    /// Seed (5.47)-(5.48).
    fn graded(c: f64, k: f64, r: f64, dg: f64) -> Self {
        Powers {
            p_coef: 1.0 / ((1.0 + k) * r),
            p: 2.0,
            q_coef: (2.0 * PI * dg / c).sqrt(),
            q: 0.5 * (1.0 - k),
            s_coef: 4.0 * c / ((1.0 + k).powi(2) * (3.0 + k) * r),
            s: 3.0 + k,
            t_coef: 2.0 / (1.0 + k) * (2.0 * PI * c * dg).sqrt(),
            t: 0.5 * (3.0 + k),
        }
    }
    fn depth(&self, a: f64) -> f64 {
        self.p_coef * a.powf(self.p) - self.q_coef * a.powf(self.q)
    }
    fn depth_slope(&self, a: f64) -> f64 {
        self.p * self.p_coef * a.powf(self.p - 1.0) - self.q * self.q_coef * a.powf(self.q - 1.0)
    }
    fn force(&self, a: f64) -> f64 {
        self.s_coef * a.powf(self.s) - self.t_coef * a.powf(self.t)
    }
    fn force_slope(&self, a: f64) -> f64 {
        self.s * self.s_coef * a.powf(self.s - 1.0) - self.t * self.t_coef * a.powf(self.t - 1.0)
    }
    /// Elementary antiderivative of F·dd/da (a sum of four powers).
    fn antiderivative(&self, a: f64) -> f64 {
        let term = |c: f64, e: f64| c * a.powf(e + 1.0) / (e + 1.0);
        term(self.s_coef * self.p * self.p_coef, self.s + self.p - 1.0)
            - term(self.s_coef * self.q * self.q_coef, self.s + self.q - 1.0)
            - term(self.t_coef * self.p * self.p_coef, self.t + self.p - 1.0)
            + term(self.t_coef * self.q * self.q_coef, self.t + self.q - 1.0)
    }
    fn guess(&self) -> f64 {
        (self.q_coef / self.p_coef).powf(1.0 / (self.p - self.q))
    }
    fn root(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
        brent(f, lo, hi, RootTolerance::relative(1e-15))
            .unwrap()
            .value
    }
    fn first_touch(&self) -> f64 {
        let g = self.guess();
        Self::root(|a| self.depth(a), 1e-3 * g, 1e3 * g)
    }
    fn separation(&self, rule: SeparationRule) -> f64 {
        let g = self.guess();
        match rule {
            SeparationRule::FixedGrip => Self::root(|a| self.depth_slope(a), 1e-6 * g, g),
            SeparationRule::LoadControlled => {
                Self::root(|a| self.force_slope(a), 1e-6 * g, 1e3 * g)
            }
        }
    }
    fn work_by_quadrature(&self, from: f64, to: f64) -> f64 {
        integrate_smooth(
            |a| self.force(a) * self.depth_slope(a),
            from,
            to,
            QuadTolerance::relative(1e-14),
        )
        .unwrap()
        .value
    }
    fn loss_by_quadrature(&self, rule: SeparationRule) -> f64 {
        self.work_by_quadrature(self.first_touch(), self.separation(rule))
    }
    fn loss_by_antiderivative(&self, rule: SeparationRule) -> f64 {
        self.antiderivative(self.separation(rule)) - self.antiderivative(self.first_touch())
    }
}

/// `refused_exponent`: the profile exponent n ≤ 3/2 of a power law, whose
/// load-controlled separation must be refused (the force minimum lies at or beyond
/// first touch); `None` where both rules must answer.
fn assert_relations<C>(
    force: impl Fn(f64) -> f64,
    depth: impl Fn(f64) -> f64,
    c: &C,
    w: &Powers,
    refused_exponent: Option<f64>,
) where
    C: AdhesiveContact,
{
    let a0 = c.first_touch().unwrap().contact_radius;
    assert!(rel(a0, w.first_touch()) < 1e-12);
    for x in [0.0, 0.1, 0.5, 0.9, 1.0, 1.3, 2.0, 5.0] {
        let a = x * a0;
        let fs = w.s_coef * a.powf(w.s) + w.t_coef * a.powf(w.t);
        let ds = w.p_coef * a.powf(w.p) + w.q_coef * a.powf(w.q);
        // 1e-12 of the larger term of each relation.
        assert!((force(a) - w.force(a)).abs() <= 1e-12 * fs, "F at x = {x}");
        assert!((depth(a) - w.depth(a)).abs() <= 1e-12 * ds, "d at x = {x}");
    }
    for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
        match (rule, refused_exponent) {
            (SeparationRule::LoadControlled, Some(n)) => assert_eq!(
                c.critical_state(rule).map(|_| ()),
                Err(Error::InvalidParameter {
                    parameter: "profile_exponent",
                    value: n,
                    requirement: "must be > 3/2 for load-controlled separation: for n <= 3/2 \
                                  the force minimum lies at or beyond first touch",
                })
            ),
            _ => {
                let s = c.critical_state(rule).unwrap();
                let a = w.separation(rule);
                assert!(rel(s.contact_radius, a) < 1e-12, "{rule}");
                assert!(rel(s.force, w.force(a)) < 1e-11, "{rule}");
                assert!(rel(s.depth, w.depth(a)) < 1e-11, "{rule}");
            }
        }
    }
}

#[test]
fn power_law_n2_is_the_sphere() {
    let sphere = JkrSphere::new(E, R, DG).unwrap();
    let profile = PowerLawProfile::new(E, 2.0, 0.5 / R, DG).unwrap();
    assert!(rel(profile.profile_factor(), 2.0) < 1e-14);
    for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
        let a = sphere.energy_loss(rule, 1e-12).unwrap().joules;
        let b = profile.energy_loss(rule, 1e-12).unwrap().joules;
        // (5.39) at n = 2 is (5.36): 1e-13; the quadratures: 1e-11.
        assert!(rel(b, a) < 1e-11, "{rule}: {b} vs {a}");
        let sa = sphere.critical_state(rule).unwrap();
        let sb = profile.critical_state(rule).unwrap();
        assert!(rel(sb.contact_radius, sa.contact_radius) < 1e-13);
        assert!(rel(sb.force, sa.force) < 1e-13);
        assert!(rel(sb.depth, sa.depth) < 1e-12);
    }
    let a = sphere
        .energy_loss(SeparationRule::FixedGrip, 1e-12)
        .unwrap()
        .joules;
    let b = profile
        .energy_loss(SeparationRule::FixedGrip, 1e-12)
        .unwrap()
        .joules;
    assert!(rel(b, a) < 1e-13);
    for kinetic in [1e-18, 1e-16, 1e-12] {
        let a = sphere
            .max_contact_radius(kinetic, 1e-12)
            .unwrap()
            .contact_radius;
        let b = profile
            .max_contact_radius(kinetic, 1e-12)
            .unwrap()
            .contact_radius;
        assert!(rel(b, a) < 1e-11, "{kinetic}: {b} vs {a}");
    }
    let a_c = sphere.scales().contact_radius;
    for x in [0.2, 1.0, 3.0] {
        let a = x * a_c;
        assert!(rel(profile.force(a).unwrap(), sphere.force(a).unwrap()) < 1e-12);
        assert!(rel(profile.depth(a).unwrap(), sphere.depth(a).unwrap()) < 1e-12);
    }
}

#[test]
fn power_law_closed_form_5_39_against_quadrature() {
    for (n, a_coef) in [
        (0.6, 30.0),
        (0.8, 3e3),
        (1.0, 0.3),
        (1.5, 1e5),
        (2.5, 1e9),
        (3.0, 1e13),
        (4.0, 1e20),
        (6.0, 1e33),
    ] {
        let c = PowerLawProfile::new(E, n, a_coef, DG).unwrap();
        let w = Powers::power_law(E, n, a_coef, DG);
        let refused = (n <= 1.5).then_some(n);
        assert_relations(
            |a| c.force(a).unwrap(),
            |a| c.depth(a).unwrap(),
            &c,
            &w,
            refused,
        );
        let fg = c.energy_loss(SeparationRule::FixedGrip, 1e-12).unwrap();
        assert!(fg.joules > 0.0 && fg.cost.evaluations == 0);
        // Closed form vs quadrature along the written-out relations: 1e-10.
        let q = w.loss_by_quadrature(SeparationRule::FixedGrip);
        assert!(rel(fg.joules, q) < 1e-10, "n = {n}: {} vs {q}", fg.joules);
        assert!(
            rel(
                fg.joules,
                w.loss_by_antiderivative(SeparationRule::FixedGrip)
            ) < 1e-10
        );
        let lc = c.energy_loss(SeparationRule::LoadControlled, 1e-10);
        if n > 1.5 {
            let lc = lc.unwrap();
            let q = w.loss_by_quadrature(SeparationRule::LoadControlled);
            let exact = w.loss_by_antiderivative(SeparationRule::LoadControlled);
            assert!(rel(lc.joules, q) < 1e-10, "n = {n}");
            assert!(rel(lc.joules, exact) < 1e-10, "n = {n}");
            assert!(lc.error_estimate <= 1e-10 * lc.joules);
            assert!(lc.cost.evaluations > 0);
            assert!(lc.joules < fg.joules);
        } else {
            match lc {
                Err(Error::InvalidParameter {
                    parameter, value, ..
                }) => {
                    assert_eq!(parameter, "profile_exponent");
                    assert_eq!(value, n);
                }
                other => panic!("n = {n}: {other:?}"),
            }
        }
    }
}

#[test]
fn power_law_max_contact_radius_balances_the_energy() {
    for (n, a_coef) in [(0.8, 3e3), (2.0, 1e6), (3.0, 1e13)] {
        let c = PowerLawProfile::new(E, n, a_coef, DG).unwrap();
        let w = Powers::power_law(E, n, a_coef, DG);
        let loss = c
            .energy_loss(SeparationRule::FixedGrip, 1e-12)
            .unwrap()
            .joules;
        for factor in [0.01, 1.0, 100.0] {
            let kinetic = factor * loss;
            let tol = 1e-10;
            let m = c.max_contact_radius(kinetic, tol).unwrap();
            let work = w.work_by_quadrature(w.first_touch(), m.contact_radius);
            // Relative to the terms that balance (kinetic + the loss's scale): tol + 1e-12.
            assert!(
                (work - kinetic).abs() <= (tol + 1e-12) * (kinetic + loss),
                "n = {n}, {factor}: {work} vs {kinetic}"
            );
            assert!(m.energy_residual <= tol);
            assert!(m.cost.evaluations > 0);
        }
    }
}

#[test]
fn power_law_rejects_n_at_or_below_one_half() {
    for n in [0.5, 0.3, 0.0, -1.0, f64::NAN, f64::INFINITY] {
        match PowerLawProfile::new(E, n, 1.0, DG) {
            Err(Error::InvalidParameter { parameter, .. }) => {
                assert_eq!(parameter, "profile_exponent")
            }
            other => panic!("n = {n}: {other:?}"),
        }
    }
    let e = PowerLawProfile::new(E, 0.5, 1.0, DG)
        .unwrap_err()
        .to_string();
    assert!(e.contains("profile_exponent") && e.contains("0.5"), "{e}");
}

fn reference_length() -> f64 {
    (2.0 * PI * DG * R * R / E).cbrt()
}

#[test]
fn graded_k0_is_the_sphere() {
    let sphere = JkrSphere::new(E, R, DG).unwrap();
    let graded = GradedSphere::new(E, 0.0, R, DG).unwrap();
    for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
        let a = sphere.energy_loss(rule, 1e-12).unwrap().joules;
        let b = graded.energy_loss(rule, 1e-12).unwrap().joules;
        assert!(rel(b, a) < 1e-11, "{rule}");
        let sa = sphere.critical_state(rule).unwrap();
        let sb = graded.critical_state(rule).unwrap();
        assert!(rel(sb.contact_radius, sa.contact_radius) < 1e-13);
        assert!(rel(sb.force, sa.force) < 1e-13);
    }
    let a = sphere
        .energy_loss(SeparationRule::FixedGrip, 1e-12)
        .unwrap()
        .joules;
    let b = graded
        .energy_loss(SeparationRule::FixedGrip, 1e-12)
        .unwrap()
        .joules;
    assert!(rel(b, a) < 1e-13);
    let ta = sphere.first_touch().unwrap();
    let tb = graded.first_touch().unwrap();
    assert!(rel(tb.contact_radius, ta.contact_radius) < 1e-13 && rel(tb.force, ta.force) < 1e-13);
    for kinetic in [1e-18, 1e-16, 1e-12] {
        let a = sphere
            .max_contact_radius(kinetic, 1e-12)
            .unwrap()
            .contact_radius;
        let b = graded
            .max_contact_radius(kinetic, 1e-12)
            .unwrap()
            .contact_radius;
        assert!(rel(b, a) < 1e-11);
    }
    // (5.52) at k = 0 and c_N = E0 is 1.
    assert!(rel(graded.loss_ratio_to_homogeneous(E).unwrap(), 1.0) < 1e-13);
    let a_c = sphere.scales().contact_radius;
    for x in [0.2, 1.0, 3.0] {
        let a = x * a_c;
        assert!(rel(graded.force(a).unwrap(), sphere.force(a).unwrap()) < 1e-12);
        assert!(rel(graded.depth(a).unwrap(), sphere.depth(a).unwrap()) < 1e-12);
    }
}

#[test]
fn graded_closed_forms_against_quadrature() {
    let homogeneous = Powers::graded(E, 0.0, R, DG);
    let homogeneous_loss = homogeneous.loss_by_quadrature(SeparationRule::FixedGrip);
    for k in [-0.9, -0.5, -0.2, 0.0, 0.3, 0.6, 0.9] {
        for stiffer in [0.3, 1.0, 5.0] {
            // c_N chosen so that the modulus at depth of order a0 is about stiffer·E.
            let c_n = stiffer * E * reference_length().powf(-k);
            let g = GradedSphere::new(c_n, k, R, DG).unwrap();
            let w = Powers::graded(c_n, k, R, DG);
            assert_relations(
                |a| g.force(a).unwrap(),
                |a| g.depth(a).unwrap(),
                &g,
                &w,
                None,
            );
            // (5.50)-(5.51) vs quadrature and antiderivative: 1e-10.
            let fg = g.energy_loss(SeparationRule::FixedGrip, 1e-12).unwrap();
            let q = w.loss_by_quadrature(SeparationRule::FixedGrip);
            assert!(rel(fg.joules, q) < 1e-10, "k = {k}: {} vs {q}", fg.joules);
            assert!(
                rel(
                    fg.joules,
                    w.loss_by_antiderivative(SeparationRule::FixedGrip)
                ) < 1e-10
            );
            // Load-controlled by the crate's quadrature vs the test's.
            let lc = g
                .energy_loss(SeparationRule::LoadControlled, 1e-10)
                .unwrap();
            assert!(
                rel(
                    lc.joules,
                    w.loss_by_quadrature(SeparationRule::LoadControlled)
                ) < 1e-10
            );
            assert!(
                rel(
                    lc.joules,
                    w.loss_by_antiderivative(SeparationRule::LoadControlled)
                ) < 1e-10
            );
            assert!(lc.error_estimate <= 1e-10 * lc.joules && lc.joules < fg.joules);
            // (5.52) vs the ratio of two quadratures.
            let ratio = g.loss_ratio_to_homogeneous(E).unwrap();
            assert!(rel(ratio, q / homogeneous_loss) < 1e-10, "k = {k}");
            // (5.49): the maximum contact radius balances ∫ F dd from first touch.
            for factor in [0.01, 1.0, 100.0] {
                let kinetic = factor * fg.joules;
                let tol = 1e-10;
                let m = g.max_contact_radius(kinetic, tol).unwrap();
                let work = w.work_by_quadrature(w.first_touch(), m.contact_radius);
                assert!(
                    (work - kinetic).abs() <= (tol + 1e-12) * (kinetic + fg.joules),
                    "k = {k}, {factor}"
                );
            }
        }
    }
}

#[test]
fn graded_rejects_k_outside_the_open_interval() {
    for k in [-1.0, 1.0, 1.5, -3.0, f64::NAN, f64::NEG_INFINITY] {
        match GradedSphere::new(E, k, R, DG) {
            Err(Error::InvalidParameter { parameter, .. }) => {
                assert_eq!(parameter, "gradation_exponent")
            }
            other => panic!("k = {k}: {other:?}"),
        }
    }
}

#[test]
fn impact_models_derive_restitution_and_sticking_generically() {
    let profile = PowerLawProfile::new(E, 3.0, 1e13, DG).unwrap();
    let graded = GradedSphere::new(E * reference_length().powf(-0.4), 0.4, R, DG).unwrap();
    for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
        let m1 = JkrImpact::new(profile, MASS).unwrap().with_separation(rule);
        let m2 = JkrImpact::new(graded, MASS).unwrap().with_separation(rule);
        for (loss, model) in [
            (
                profile.energy_loss(rule, 1e-12).unwrap().joules,
                &m1 as &dyn ImpactModel,
            ),
            (
                graded.energy_loss(rule, 1e-12).unwrap().joules,
                &m2 as &dyn ImpactModel,
            ),
        ] {
            assert!(model.loss_is_speed_independent());
            let v = sticking_velocity(model, 1e-12).unwrap();
            assert_eq!(v.method, StickingMethod::ClosedForm);
            // (5.38): v_c = √(2|ΔU|/m), 1e-10 (the loss is a quadrature for load control).
            assert!(rel(v.speed, (2.0 * loss / MASS).sqrt()) < 1e-10);
            let out = tabor_restitution::impact(model, 2.0 * v.speed).unwrap();
            assert!((out.restitution - 0.75f64.sqrt()).abs() < 1e-9);
        }
    }
}
