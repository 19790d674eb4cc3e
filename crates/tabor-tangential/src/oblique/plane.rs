//! The rates and the event values of a planar state in two dimensions: the
//! physics of [`Setup::evaluate`] and [`Setup::event_values`] on the reduced
//! state of [`super::planar`] (SI units, [`PM`] components), every in-plane
//! vector as its x-y components, every spin and every cross product with the
//! in-plane normal as its component about z. The out-of-plane components the 3-D
//! forms carry are exact zeros, and every operation here is the 3-D one without
//! its terms in them (a product with an exact 0, added), in the same order: the
//! same numbers up to the sign of a zero (`planar_rates_match_the_full_ones`).
//! Twisting sticks at θ = 0 with `ω_tw = 0` in a planar state: its torque is 0
//! and only its stick event (the limit) remains.

use super::bed::BedState;
use super::elements::{ratio, spring_rates, twist_coefficients};
use super::limits::{CAPTURE, EVENTS, NORMAL_FORCE_ZERO, RATE_CAP, WARMUP};
use super::planar::{PM, P_E, P_EN, P_U, P_WI, P_WJ, P_XR, P_XT};
use super::state::*;
use crate::model::{Friction, TangentialModel};
use nalgebra::{Vector2, Vector3};
use tabor_dynamics::ForceLaw;
use tabor_restitution::Result;

/// An in-plane vector (x, y).
type V2 = Vector2<f64>;

/// The rates of a planar state and the slip rates its event values need.
#[cfg(test)]
pub(super) struct PlaneEval {
    /// SI rates of the reduced state.
    pub(super) dz: [f64; PM],
    /// The tangential element's slip rate ([`Eval::slip_rate_t`]).
    pub(super) slip_rate_t: f64,
    /// The rolling element's slip rate ([`Eval::slip_rate_r`]).
    pub(super) slip_rate_r: f64,
}

/// The in-plane vector at `z[i..i + 2]`.
fn v2(z: &[f64; PM], i: usize) -> V2 {
    V2::new(z[i], z[i + 1])
}

/// Writes `v` to `dz[i..i + 2]`.
fn put2(dz: &mut [f64; PM], i: usize, v: &V2) {
    dz[i] = v.x;
    dz[i + 1] = v.y;
}

/// `(w ẑ) × v`: a spin `w` about z crossed with the in-plane `v`.
fn spin_cross(w: f64, v: &V2) -> V2 {
    V2::new(-(w * v.y), w * v.x)
}

/// The z component of `a × b` for in-plane `a`, `b`.
fn cross_z(a: &V2, b: &V2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The 3-D vector of the in-plane `v`.
fn lift(v: &V2) -> Vector3<f64> {
    Vector3::new(v.x, v.y, 0.0)
}

/// [`super::elements::direction`] in the plane.
fn direction2(x: &V2, fallback: &V2) -> V2 {
    let n = x.norm();
    if n > 0.0 {
        x / n
    } else {
        let m = fallback.norm();
        if m > 0.0 {
            fallback / m
        } else {
            V2::zeros()
        }
    }
}

/// [`super::elements::cap`] in the plane.
fn cap2(f: V2, limit: f64, frozen: bool) -> V2 {
    let size = f.norm();
    if frozen && size > limit {
        f * (limit / size)
    } else {
        f
    }
}

/// [`super::elements::turn_rate`] in the plane.
fn turn_rate2(drive: &V2, uhat: &V2, n: &V2, limit: f64, time: f64) -> V2 {
    let drive = drive - n * n.dot(drive);
    let perp = drive - uhat * uhat.dot(&drive);
    let limit = limit.max(drive.norm() * time / RATE_CAP);
    if limit > 0.0 {
        perp / limit
    } else {
        V2::zeros()
    }
}

impl<'a> Setup<'a> {
    /// [`Setup::geometry`] of the reduced SI state `z`: the normal, the overlap,
    /// its rate and ṅ.
    pub(super) fn planar_geometry(&self, t: f64, z: &[f64; PM]) -> (V2, f64, f64, V2) {
        let e = v2(z, P_E);
        let u = v2(z, P_U);
        if self.flat {
            // −x̂, with the signs of its zeros
            let n = V2::new(-1.0, -0.0);
            let overlap = self.v_n * t + e[0];
            return (n, overlap, -n.dot(&u), V2::zeros());
        }
        let p = self.d_touch.xy() + self.u0.xy() * t;
        let d = p + e;
        let r = d.norm();
        let numerator =
            2.0 * self.r_sum * self.v_n * t - self.v * self.v * t * t - 2.0 * p.dot(&e) - e.dot(&e);
        let overlap = numerator / (self.r_sum + r);
        let inv_r = 1.0 / r;
        let n = d * inv_r;
        let rate = -n.dot(&u);
        let n_dot = (u + n * rate) * inv_r;
        (n, overlap, rate, n_dot)
    }

    /// The spins about z of the reduced SI state `z`: ω_i, ω_j (0 on a flat).
    fn planar_spins(&self, z: &[f64; PM]) -> (f64, f64) {
        (z[P_WI], if self.flat { 0.0 } else { z[P_WJ] })
    }

    /// The radii of [`Setup::evaluate`]: the torque arms and R_i, R_j.
    pub(super) fn planar_radii(&self, overlap: f64) -> (f64, f64, f64, f64) {
        let r_i = self.imp.sphere.radius;
        if self.flat {
            (r_i, 0.0, r_i, 0.0)
        } else {
            let r_j = self.imp.target.radius;
            (r_i - 0.5 * overlap, r_j - 0.5 * overlap, r_i, r_j)
        }
    }

    /// [`Setup::evaluate`] of the reduced SI state `z` (planar: twisting sticks).
    #[cfg(test)]
    pub(super) fn planar_evaluate(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        z: &[f64; PM],
        modes: &Modes,
    ) -> Result<PlaneEval> {
        let mut dz = [0.0; PM];
        let (slip_rate_t, slip_rate_r) = self.planar_rates(law, t, z, modes, &mut dz)?;
        Ok(PlaneEval {
            dz,
            slip_rate_t,
            slip_rate_r,
        })
    }

    /// [`Setup::planar_evaluate`] into `dz` (zeros on entry): the SI rates, and
    /// the tangential and rolling slip rates returned (∞ where an element
    /// sticks).
    pub(super) fn planar_rates(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        z: &[f64; PM],
        modes: &Modes,
        dz: &mut [f64; PM],
    ) -> Result<(f64, f64)> {
        let (n, overlap, rate, n_dot) = self.planar_geometry(t, z);
        let u = v2(z, P_U);
        let (wi, wj) = self.planar_spins(z);
        let mut out = (f64::INFINITY, f64::INFINITY);
        put2(dz, P_E, &(u - self.u0.xy()));
        if !modes.in_contact {
            let f_el = law.force(overlap, rate)?;
            put2(dz, P_U, &(n * (f_el / self.m_eff)));
            dz[P_EN] = f_el * rate;
            return Ok(out);
        }
        let fr = self.imp.friction.as_ref();
        let slipping = modes.tangential == Mode::Slip || modes.rolling == Mode::Slip;
        let rescaling = !modes.loading
            && fr.is_some_and(|f| f.tangential.model == TangentialModel::MindlinRescale);
        let np = self.normal(law, overlap, rate, slipping || rescaling)?;
        let (f_el, a) = (np.force, np.radius);
        let (a_prime, f_prime) = np.slopes.unwrap_or((0.0, 0.0));
        let normal = &self.imp.normal;
        let c_n = normal.damping_at(a);
        let f_d = c_n * rate;
        let f_n = f_el + f_d;
        let pull_off = normal.pull_off_force;
        let cohesive = pull_off > 0.0;
        let fc = crate::critical_force(f_el, f_n, pull_off);
        let (arm_i, arm_j, r_i, r_j) = self.planar_radii(overlap);

        let vt = u - n * n.dot(&u);
        let wr = wi * r_i + wj * r_j;
        let v_tr = vt - spin_cross(wr, &n);
        let w_rel = wi - wj;
        let v_rl = spin_cross(w_rel, &n) * self.r_eff;

        if modes.warmup {
            put2(dz, P_U, &(n * (f_n / self.m_eff)));
            put2(dz, P_XT, &v_tr);
            put2(dz, P_XR, &v_rl);
            dz[P_EN] = f_el * rate;
            dz[P_EN + 1] = f_d * rate;
            return Ok(out);
        }
        let mut f_t = V2::zeros();
        let mut f_r = V2::zeros();
        let mut tang = None;
        if let Some(fr) = fr {
            let t = &fr.tangential;
            let k = t.spring(a);
            let gamma = t.damping_ratio * c_n;
            let limit = t.coefficient * fc;
            let xi = v2(z, P_XT);
            if let Some(bed) = &self.bed {
                let f_bed = bed
                    .borrow()
                    .force(&BedState::new(lift(&n), lift(&xi), a, limit));
                let s = dashpot_share(&f_bed, &lift(&(v_tr * gamma)), limit);
                f_t = f_bed.xy() - v_tr * (gamma * s);
                put2(dz, P_XT, &(v_tr - n * xi.dot(&n_dot)));
                dz[P_EN + 3] = s * gamma * v_tr.norm_squared();
            } else {
                f_t = match modes.tangential {
                    Mode::Stick => cap2(-(xi * k + v_tr * gamma), limit, modes.frozen[0]),
                    Mode::Slip => -direction2(&xi, &v_tr) * limit,
                };
                tang = Some((k, gamma, limit, xi));
            }
            if let Some(r) = &fr.rolling {
                let psi = v2(z, P_XR);
                let limit_r = r.coefficient * fc;
                f_r = match modes.rolling {
                    Mode::Stick => cap2(
                        -(psi * r.stiffness + v_rl * r.damping),
                        limit_r,
                        modes.frozen[1],
                    ),
                    Mode::Slip => -direction2(&psi, &v_rl) * limit_r,
                };
            }
        }

        // accelerations (the twisting torque is 0)
        let u_dot = (n * f_n + f_t) / self.m_eff;
        let n_cross_ft = cross_z(&n, &f_t);
        let torque_roll = cross_z(&n, &f_r) * self.r_eff;
        let wi_dot = (-n_cross_ft * arm_i + torque_roll) * self.inv_i_i;
        let wj_dot = if self.flat {
            0.0
        } else {
            (-n_cross_ft * arm_j - torque_roll) * self.inv_i_j
        };
        put2(dz, P_U, &u_dot);
        dz[P_WI] = wi_dot;
        dz[P_WJ] = wj_dot;

        // energies (power removed from the bodies; twisting's is 0)
        dz[P_EN] = f_el * rate;
        dz[P_EN + 1] = f_d * rate;
        dz[P_EN + 4] = -f_t.dot(&v_tr);
        dz[P_EN + 5] = -f_r.dot(&v_rl);
        let arm_gain = f_t.dot(&spin_cross(wi * (r_i - arm_i) + wj * (r_j - arm_j), &n));
        dz[P_EN + 7] = -arm_gain;

        let Some(fr) = fr else {
            return Ok(out);
        };

        // rates of the quantities the slip conditions need (only a slip asks:
        // the same operations, where they are used; 0 where none slips)
        let a_dot = a_prime * rate;
        let c_n_dot = normal.damping_rate(a, a_dot);
        let (fc_dot, v_tr_dot, v_rl_dot) = if slipping {
            let accel_normal = -n_dot.dot(&u) - n.dot(&u_dot);
            let fc_dot = {
                let raw = if cohesive { f_el + 2.0 * pull_off } else { f_n };
                let mut d = f_prime * rate;
                if !cohesive {
                    d += c_n_dot * rate + c_n * accel_normal;
                }
                let tensile = if cohesive { raw < 0.0 } else { modes.tensile };
                if tensile {
                    -d
                } else {
                    d
                }
            };
            let vt_dot = u_dot - n_dot * n.dot(&u) - n * (n_dot.dot(&u) + n.dot(&u_dot));
            let v_tr_dot =
                vt_dot - spin_cross(wi_dot * r_i + wj_dot * r_j, &n) - spin_cross(wr, &n_dot);
            let v_rl_dot =
                (spin_cross(wi_dot - wj_dot, &n) + spin_cross(w_rel, &n_dot)) * self.r_eff;
            (fc_dot, v_tr_dot, v_rl_dot)
        } else {
            (0.0, V2::zeros(), V2::zeros())
        };

        if let Some((k, gamma, limit, xi)) = tang {
            let t = &fr.tangential;
            let (k_dot, gamma_dot, rescale_rate) =
                spring_rates(t, (a, a_dot), c_n_dot, !modes.loading, self.time);
            match modes.tangential {
                Mode::Stick => {
                    let d = v_tr - n * xi.dot(&n_dot) + xi * rescale_rate;
                    put2(dz, P_XT, &d);
                    dz[P_EN + 3] = gamma * v_tr.norm_squared();
                }
                Mode::Slip => {
                    let limit_dot = t.coefficient * fc_dot;
                    let uhat = direction2(&xi, &v_tr);
                    let drive =
                        v_tr * k + v_tr * (gamma_dot - k_dot * ratio(gamma, k)) + v_tr_dot * gamma;
                    let turn = turn_rate2(&drive, &uhat, &n, limit, self.time);
                    let w = turn - n * uhat.dot(&n_dot);
                    put2(dz, P_XT, &(w * xi.norm()));
                    // the slip rate and the sliding work as in `Setup::evaluate`
                    let uv = uhat.dot(&v_tr);
                    let on_surface = limit - gamma * uv;
                    let kappa_rate = ratio(k_dot, k) + rescale_rate;
                    let g = kappa_rate * on_surface
                        + k * uv
                        + gamma_dot * uv
                        + gamma * uhat.dot(&v_tr_dot)
                        - limit_dot;
                    out.0 = g;
                    let slip_rate = if modes.frozen[0] { g.max(0.0) } else { g };
                    if on_surface >= 0.0 {
                        // as `Setup::evaluate` ([`slip_power`])
                        let udot_v = (w - uhat * uhat.dot(&w)).dot(&v_tr);
                        let (power, _) = slip_power(
                            (t.model, modes.frozen[0]),
                            (on_surface, slip_rate, k),
                            (uv, gamma, udot_v),
                        );
                        dz[P_EN + 2] = power;
                        dz[P_EN + 3] = gamma * v_tr.norm_squared();
                    } else {
                        dz[P_EN + 3] = gamma * v_tr.norm_squared() + on_surface * uv;
                    }
                }
            }
        }
        if let Some(r) = &fr.rolling {
            let psi = v2(z, P_XR);
            let limit_r = r.coefficient * fc;
            match modes.rolling {
                Mode::Stick => put2(dz, P_XR, &(v_rl - n * psi.dot(&n_dot))),
                Mode::Slip => {
                    let uhat = direction2(&psi, &v_rl);
                    let drive = v_rl * r.stiffness + v_rl_dot * r.damping;
                    let turn = turn_rate2(&drive, &uhat, &n, limit_r, self.time);
                    put2(dz, P_XR, &((turn - n * uhat.dot(&n_dot)) * psi.norm()));
                    out.1 = uhat.dot(&drive) - r.coefficient * fc_dot;
                }
            }
        }
        Ok(out)
    }

    /// [`Setup::event_values`] of the reduced SI state `z` (planar: twisting
    /// sticks at θ = 0, ω_tw = 0, so its trial torque is 0).
    pub(super) fn planar_event_values(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        z: &[f64; PM],
        modes: &Modes,
    ) -> Result<[f64; EVENTS]> {
        let (n, overlap, rate, _) = self.planar_geometry(t, z);
        let mut g = [f64::INFINITY; EVENTS];
        g[0] = law.branch_end(overlap, rate)? / self.length;
        if modes.in_contact {
            g[1] = if modes.loading { rate } else { -rate } / self.v_n;
        }
        if self.imp.normal.damping != 0.0 {
            g[CAPTURE] = self.capture_value(law, t, &Setup::full_of(z), modes)?;
        }
        if modes.warmup {
            g[8] = WARMUP - overlap / self.length;
            return Ok(g);
        }
        let Some(fr) = self.imp.friction.as_ref() else {
            return Ok(g);
        };
        if !modes.in_contact || modes.frozen_for_good() {
            return Ok(g);
        }
        modes.thaw_events(&mut g, t, self.time);
        let normal = &self.imp.normal;
        if normal.pull_off_force <= 0.0 && normal.damping > 0.0 {
            let np = self.normal(law, overlap, rate, false)?;
            let f_n = np.force + normal.damping_at(np.radius) * rate;
            g[NORMAL_FORCE_ZERO] = if modes.tensile { -f_n } else { f_n } / self.force;
        }
        let slip_rates = if modes.tangential == Mode::Slip || modes.rolling == Mode::Slip {
            self.planar_rates(law, t, z, modes, &mut [0.0; PM])?
        } else {
            (f64::INFINITY, f64::INFINITY)
        };
        // the contact quantities of `Setup::contact` and the trial forces
        let contact = || -> Result<Trials> {
            let u = v2(z, P_U);
            let (wi, wj) = self.planar_spins(z);
            let np = self.normal(law, overlap, rate, false)?;
            let (a, f_el) = (np.radius, np.force);
            let c_n = self.imp.normal.damping_at(a);
            let fc = crate::critical_force(f_el, f_el + c_n * rate, self.imp.normal.pull_off_force);
            let r_j = if self.flat {
                0.0
            } else {
                self.imp.target.radius
            };
            let v_tr = u - n * n.dot(&u) - spin_cross(wi * self.imp.sphere.radius + wj * r_j, &n);
            let tg = &fr.tangential;
            let trial_t = v2(z, P_XT) * tg.spring(a) + v_tr * (tg.damping_ratio * c_n);
            let v_rl = spin_cross(wi - wj, &n) * self.r_eff;
            let trial_r = fr.rolling.as_ref().map_or(0.0, |r| {
                (v2(z, P_XR) * r.stiffness + v_rl * r.damping).norm()
            });
            Ok(Trials {
                radius: a,
                damping: c_n,
                critical_force: fc,
                tangential: trial_t.norm(),
                rolling: trial_r,
            })
        };
        let tangential = self.bed.is_none();
        self.element_events(&mut g, (fr, modes, tangential), contact, slip_rates)?;
        Ok(g)
    }

    /// The friction elements' event values of a planar state into `g`: where
    /// one sticks, the margin `(μ F_c − |T|)/F` of its trial force T (the
    /// tangential element only where `tangential`: not the spring bed) and the
    /// twisting limit, from the contact quantities `contact` gives (asked only
    /// there); where one slips, its slip rate of `slip_rates` (force per time).
    /// A frozen element has none. Shared by the Cartesian and the polar planar
    /// states ([`super::polar`]), which differ only in how they get T.
    pub(super) fn element_events(
        &self,
        g: &mut [f64; EVENTS],
        (fr, modes, tangential): (&Friction, &Modes, bool),
        contact: impl FnOnce() -> Result<Trials>,
        slip_rates: (f64, f64),
    ) -> Result<()> {
        let tangential = tangential && !modes.frozen[0];
        let rolling = fr.rolling.as_ref().filter(|_| !modes.frozen[1]);
        let twisting = fr.twisting.as_ref().filter(|_| !modes.frozen[2]);
        let sticks = (tangential && modes.tangential == Mode::Stick)
            || (rolling.is_some() && modes.rolling == Mode::Stick)
            || twisting.is_some();
        if sticks {
            let c = contact()?;
            let fc = c.critical_force;
            if tangential && modes.tangential == Mode::Stick {
                g[2] = (fr.tangential.coefficient * fc - c.tangential) / self.force;
            }
            if let Some(r) = rolling.filter(|_| modes.rolling == Mode::Stick) {
                g[4] = (r.coefficient * fc - c.rolling) / self.force;
            }
            if let Some(tw) = twisting {
                let (_, _, l) = twist_coefficients(tw, fr, c.radius, c.damping, fc);
                g[6] = l / (self.force * self.length);
            }
        }
        let rate_unit = self.force / self.time;
        if tangential && modes.tangential == Mode::Slip {
            g[3] = slip_rates.0 / rate_unit;
        }
        if rolling.is_some() && modes.rolling == Mode::Slip {
            g[5] = slip_rates.1 / rate_unit;
        }
        Ok(())
    }
}

/// The contact quantities a planar state's stick events need: contact radius
/// (m), normal damping coefficient c_n (N s/m), critical normal force F_c (N),
/// and the sizes (N) of the tangential and rolling trial forces.
pub(super) struct Trials {
    pub(super) radius: f64,
    pub(super) damping: f64,
    pub(super) critical_force: f64,
    pub(super) tangential: f64,
    pub(super) rolling: f64,
}
