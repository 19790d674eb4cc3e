//! Shared by the integration tests: a classical RK4 integrator and the coupled
//! JKR + Kuwabara-Kono contact of the bundled polymer grains, written out in SI
//! (independent of tabor's force laws).
#![allow(dead_code)]

use std::f64::consts::PI;

/// One classical Runge-Kutta step of ẍ = acc(x, ẋ).
pub fn rk4(x: f64, u: f64, h: f64, acc: &dyn Fn(f64, f64) -> f64) -> (f64, f64) {
    let k1 = (u, acc(x, u));
    let k2 = (
        u + 0.5 * h * k1.1,
        acc(x + 0.5 * h * k1.0, u + 0.5 * h * k1.1),
    );
    let k3 = (
        u + 0.5 * h * k2.1,
        acc(x + 0.5 * h * k2.0, u + 0.5 * h * k2.1),
    );
    let k4 = (u + h * k3.1, acc(x + h * k3.0, u + h * k3.1));
    (
        x + h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0),
        u + h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1),
    )
}

/// Integrates ẍ = acc(x, ẋ) from (0, v0) with `steps` steps per `time_scale` until
/// `end(x, ẋ)` (positive while in contact) falls to 0 while ẋ < 0; the last step is
/// shortened by bisection to land on the end. Returns the rebound speed, or 0 when
/// ẋ turns positive again (caught: sticks).
pub fn rebound(
    v0: f64,
    time_scale: f64,
    steps: usize,
    acc: &dyn Fn(f64, f64) -> f64,
    end: &dyn Fn(f64, f64) -> f64,
) -> f64 {
    let h = time_scale / steps as f64;
    let (mut x, mut u) = (0.0, v0);
    let mut turned = false;
    for _ in 0..100 * steps {
        let (xn, un) = rk4(x, u, h, acc);
        if un < 0.0 {
            turned = true;
        }
        if turned && un > 0.0 {
            return 0.0;
        }
        if turned && end(xn, un) <= 0.0 {
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                let (xm, um) = rk4(x, u, mid, acc);
                if end(xm, um) > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return -rk4(x, u, hi, acc).1;
        }
        (x, u) = (xn, un);
    }
    panic!("no end of contact");
}

/// Two 5 µm polymer grains (E = 2 MPa, ν = 0.49, ρ = 970 kg/m³, Δγ = 0.04 J/m²,
/// the bundled `polymer_grains_viscoadhesive.toml`) with shear viscosity `eta`
/// (Pa s) on both: JKR (fixed grip) + the Kuwabara-Kono force 2 η_c a ḋ with the
/// JKR contact radius. JKR written out: d(a) = a²/R − √(2πΔγa/E*),
/// F(a) = 4E*a³/(3R) − √(8πΔγE*a³), snap-off at dd/da = 0.
pub struct Grains {
    /// Effective radius R (m).
    pub r: f64,
    /// Effective modulus E* (Pa).
    pub e: f64,
    /// Effective mass m (kg).
    pub m: f64,
    /// Work of adhesion Δγ (J/m²).
    pub dg: f64,
    /// η_c = E* τ with τ = 4η/M (Pa s).
    pub eta_c: f64,
    /// The JKR snap-off radius a_c and depth d_c.
    pub a_c: f64,
    pub d_c: f64,
}

impl Grains {
    pub fn new(eta: f64) -> Self {
        let (r, dg) = (2.5e-6, 0.04);
        let m_body = 2e6 / (1.0 - 0.49 * 0.49);
        let e = m_body / 2.0;
        let tau = 4.0 * eta / m_body;
        let m = 4.0 / 3.0 * PI * 5e-6f64.powi(3) * 970.0 / 2.0;
        let a_c = (PI * dg * r * r / (8.0 * e)).cbrt();
        let mut g = Grains {
            r,
            e,
            m,
            dg,
            eta_c: e * tau,
            a_c,
            d_c: 0.0,
        };
        g.d_c = g.d_of(a_c);
        g
    }

    pub fn d_of(&self, a: f64) -> f64 {
        a * a / self.r - (2.0 * PI * self.dg * a / self.e).sqrt()
    }

    pub fn f_of(&self, a: f64) -> f64 {
        4.0 * self.e * a.powi(3) / (3.0 * self.r) - (8.0 * PI * self.dg * self.e * a.powi(3)).sqrt()
    }

    /// The contact radius on the stable branch a ≥ a_c, where d(a) increases:
    /// bisection.
    pub fn a_of(&self, d: f64) -> f64 {
        let a_c = self.a_c;
        let (mut lo, mut hi) = (a_c, a_c.max((self.r * d.abs()).sqrt()) * 4.0 + a_c);
        while self.d_of(hi) < d {
            hi *= 2.0;
        }
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if self.d_of(mid) < d {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// d̈ = −(F(a) + 2 η_c a ḋ)/m.
    pub fn acc(&self, d: f64, u: f64) -> f64 {
        let a = self.a_of(d.max(self.d_c));
        -(self.f_of(a) + 2.0 * self.eta_c * a * u) / self.m
    }

    /// Positive while in contact: d − d_c.
    pub fn end(&self, d: f64, _u: f64) -> f64 {
        d - self.d_c
    }

    /// The Hertz contact time of the contact at `v0`, 2.87 (m²/(R E*² v0))^(1/5) (s).
    pub fn time_scale(&self, v0: f64) -> f64 {
        2.87 * (self.m * self.m / (self.r * self.e * self.e * v0)).powf(0.2)
    }

    /// The rebound speed at `v0` (0 when the grains stick), `steps` RK4 steps per
    /// contact time.
    pub fn rebound(&self, v0: f64, steps: usize) -> f64 {
        rebound(
            v0,
            self.time_scale(v0),
            steps,
            &|d, u| self.acc(d, u),
            &|d, u| self.end(d, u),
        )
    }
}
