//! The stick/slip logic of the friction elements: contact quantities, entering
//! and leaving slip, the initial and later mode decisions and the event values
//! that locate the switches.

use super::elements::*;
use super::limits::*;
use super::state::*;
use crate::model::Twisting;
use nalgebra::Vector3;
use tabor_dynamics::ForceLaw;
use tabor_restitution::Result;

/// The contact quantities of [`Setup::contact`]: (a, F_n0, v_tr, v_rl, ω_tw, n).
pub(super) type Contact = (f64, f64, Vector3<f64>, Vector3<f64>, f64, Vector3<f64>);

impl<'a> Setup<'a> {
    /// Contact quantities at SI state `y` for the mode switches ([`Contact`]).
    pub(super) fn contact(&self, law: &dyn ForceLaw, t: f64, y: &[f64; N]) -> Result<Contact> {
        let (n, overlap, rate, _) = self.geometry(t, y);
        let u = v3(y, U);
        let wi = v3(y, WI);
        let wj = if self.flat {
            Vector3::zeros()
        } else {
            v3(y, WJ)
        };
        let np = self.normal(law, overlap, rate, false)?;
        let (a, f_el) = (np.radius, np.force);
        let c_n = self.imp.normal.damping_at(a);
        let fc = crate::critical_force(f_el, f_el + c_n * rate, self.imp.normal.pull_off_force);
        let r_j = if self.flat {
            0.0
        } else {
            self.imp.target.radius
        };
        let v_tr = u - n * n.dot(&u) - (wi * self.imp.sphere.radius + wj * r_j).cross(&n);
        let v_rl = (wi - wj).cross(&n) * self.r_eff;
        Ok((a, fc, v_tr, v_rl, (wi - wj).dot(&n), n))
    }

    /// (trial force T, limit L, damping γ, spring k, velocity) of the vector
    /// element stored at `slot` (XT or XR).
    #[allow(clippy::type_complexity)]
    pub(super) fn element(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        slot: usize,
    ) -> Result<(Vector3<f64>, f64, f64, f64, Vector3<f64>)> {
        if self.imp.friction.is_none() {
            return Ok((Vector3::zeros(), 0.0, 0.0, 0.0, Vector3::zeros()));
        }
        Ok(self.element_of(&self.contact(law, t, y)?, y, slot))
    }

    /// [`Setup::element`] from the contact quantities `c` of [`Setup::contact`].
    #[allow(clippy::type_complexity)]
    fn element_of(
        &self,
        c: &Contact,
        y: &[f64; N],
        slot: usize,
    ) -> (Vector3<f64>, f64, f64, f64, Vector3<f64>) {
        let zero = (Vector3::zeros(), 0.0, 0.0, 0.0, Vector3::zeros());
        let Some(fr) = &self.imp.friction else {
            return zero;
        };
        let (a, fc, v_tr, v_rl, _, _) = *c;
        let x = v3(y, slot);
        if slot == XT {
            let tg = &fr.tangential;
            let k = tg.spring(a);
            let gamma = tg.damping_ratio * self.imp.normal.damping_at(a);
            (x * k + v_tr * gamma, tg.coefficient * fc, gamma, k, v_tr)
        } else {
            let Some(r) = &fr.rolling else {
                return zero;
            };
            (
                x * r.stiffness + v_rl * r.damping,
                r.coefficient * fc,
                r.damping,
                r.stiffness,
                v_rl,
            )
        }
    }

    /// Stick → slip of a vector element: its state now carries the direction of
    /// the trial force (keeping the length of the displacement).
    pub(super) fn enter_slip(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        _modes: &Modes,
        slot: usize,
    ) -> Result<()> {
        let (trial, _, _, _, vel) = self.element(law, t, y, slot)?;
        let x = v3(y, slot);
        let len = x.norm().max(1e-6 * self.length);
        put_state(y, slot, &(direction(&trial, &vel) * len));
        Ok(())
    }

    /// Slip → stick: the displacement becomes the elastic part of the limit force.
    pub(super) fn leave_slip(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        _modes: &Modes,
        slot: usize,
    ) -> Result<()> {
        let (_, limit, gamma, k, vel) = self.element(law, t, y, slot)?;
        let x = v3(y, slot);
        let uhat = direction(&x, &vel);
        if k > 0.0 {
            put_state(y, slot, &((uhat * limit - vel * gamma) / k));
        }
        Ok(())
    }

    /// The trial twisting torque `k θ + γ ω_tw` (N m).
    pub(super) fn twist_trial(&self, law: &dyn ForceLaw, t: f64, y: &[f64; N]) -> Result<f64> {
        if self
            .imp
            .friction
            .as_ref()
            .is_none_or(|f| f.twisting.is_none())
        {
            return Ok(0.0);
        }
        Ok(self.twist_of(&self.contact(law, t, y)?, y).0)
    }

    /// The trial twisting torque and the limit (N m) from the contact quantities
    /// `c` of [`Setup::contact`] (0, 0 without twisting).
    fn twist_of(&self, c: &Contact, y: &[f64; N]) -> (f64, f64) {
        let Some(fr) = &self.imp.friction else {
            return (0.0, 0.0);
        };
        let Some(tw) = &fr.twisting else {
            return (0.0, 0.0);
        };
        let (a, fc, _, _, w_tw, _) = *c;
        let (k, g, l) = twist_coefficients(tw, fr, a, self.imp.normal.damping_at(a), fc);
        (k * y[XW] + g * w_tw, l)
    }

    pub(super) fn leave_twist_slip(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        modes: &Modes,
    ) -> Result<()> {
        let Some(fr) = &self.imp.friction else {
            return Ok(());
        };
        let Some(tw) = &fr.twisting else {
            return Ok(());
        };
        let (a, fc, _, _, w_tw, _) = self.contact(law, t, y)?;
        let (k, g, l) = twist_coefficients(tw, fr, a, self.imp.normal.damping_at(a), fc);
        if k > 0.0 {
            y[XW] = (l * modes.twist_sign - g * w_tw) / k;
        }
        Ok(())
    }

    /// True when an element's stiffness vanishes with the contact radius
    /// (`mindlin`, `mindlin_rescale` without the spring bed; `marshall`
    /// twisting): the elements [`Setup::release_without_area`] acts on.
    pub(super) fn has_area_springs(&self) -> bool {
        self.imp.friction.as_ref().is_some_and(|fr| {
            (self.bed.is_none() && fr.tangential.vanishes_without_area())
                || fr.twisting.is_some_and(|t| t.vanishes_without_area())
        })
    }

    /// At a branch end where the contact has no area (the law's contact radius
    /// `a_at_end` there, before the law's hook, is 0 within [`NO_AREA`]:
    /// Maugis-Dugdale's junction with its no-contact part), each sticking
    /// element whose stiffness vanishes with the contact radius (`mindlin`,
    /// `mindlin_rescale`: `k_t a`; `marshall` twisting: `½ k_t a²`) is set to zero
    /// displacement: a spring of zero stiffness stores nothing, and the
    /// displacement the motion carries it through on the no-contact part
    /// (LAMMPS's accumulate-from-touch; LAMMPS has no such part) would load the
    /// forming contact with energy no work put in. Where the no-contact part
    /// ends, a is exactly 0 and that end alone suffices: it is the same as
    /// zeroing the displacement all along the part (its stiffness is 0 there).
    /// Where the contact part ends, a is 0 up to the location of the event
    /// (`a ∝ √(δ − δ_j)`; 5·10⁻⁸ of the unit seen), and zeroing there changes
    /// nothing the next end would not. A slipping element (its force on the
    /// limit, its displacement the elastic part of it) is left to its slip;
    /// none has been seen to slip into a = 0, where its stick force vanishes.
    /// [`Friction::step`](crate::Friction::step) zeroes the displacement at
    /// every step where a = 0, whatever the element does.
    pub(super) fn release_without_area(&self, a_at_end: f64, y: &mut [f64; N], modes: &Modes) {
        let Some(fr) = &self.imp.friction else {
            return;
        };
        if a_at_end > NO_AREA * (self.r_eff * self.length).sqrt() {
            return;
        }
        if self.bed.is_none()
            && modes.tangential == Mode::Stick
            && fr.tangential.vanishes_without_area()
        {
            put_state(y, XT, &Vector3::zeros());
        }
        if modes.twisting == Mode::Stick
            && fr
                .twisting
                .as_ref()
                .is_some_and(|t| t.vanishes_without_area())
        {
            y[XW] = 0.0;
        }
    }

    /// At contact onset: a law with a Coulomb limit at first touch (adhesion)
    /// starts in stick; one without (Hertz: every limit and spring starts from 0)
    /// runs the first [`WARMUP`] of the overlap scale without friction forces, the
    /// springs following the motion, and decides there ([`Setup::decide_modes`]).
    pub(super) fn decide_initial_modes(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        modes: &mut Modes,
    ) -> Result<()> {
        if self.imp.friction.is_none() {
            return Ok(());
        }
        let (_, overlap, ..) = self.geometry(t, y);
        let (_, fc0, ..) = self.contact(law, t, y)?;
        if fc0 > 0.0 || overlap / self.length >= WARMUP {
            return self.decide_modes(law, t, y, modes);
        }
        modes.warmup = true;
        Ok(())
    }

    /// Each element whose trial force exceeds its limit is put on the limit (its
    /// displacement reset to the elastic part of the limit force, as LAMMPS) and
    /// slips if the trial force keeps outgrowing the limit there, else sticks.
    pub(super) fn decide_modes(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        modes: &mut Modes,
    ) -> Result<()> {
        for element in 0..3 {
            self.decide_element(law, t, y, modes, element)?;
        }
        Ok(())
    }

    /// [`Setup::decide_modes`] for one element (0 tangential, 1 rolling, 2
    /// twisting); nothing for an element the contact does not have (or the
    /// tangential one of a spring bed).
    fn decide_element(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        modes: &mut Modes,
        element: usize,
    ) -> Result<()> {
        let Some(fr) = &self.imp.friction else {
            return Ok(());
        };
        if element < 2 {
            let slot = [XT, XR][element];
            if (slot == XR && fr.rolling.is_none()) || (slot == XT && self.bed.is_some()) {
                return Ok(());
            }
            let (trial, limit, ..) = self.element(law, t, y, slot)?;
            if trial.norm() <= limit {
                return Ok(());
            }
            let mut slip = *modes;
            if slot == XT {
                slip.tangential = Mode::Slip;
            } else {
                slip.rolling = Mode::Slip;
            }
            let mut on_limit = *y;
            self.enter_slip(law, t, &mut on_limit, modes, slot)?;
            let ev = self.evaluate(law, t, &on_limit, &slip)?;
            let rate = if slot == XT {
                ev.slip_rate_t
            } else {
                ev.slip_rate_r
            };
            if rate > 0.0 {
                *y = on_limit;
                *modes = slip;
            } else {
                self.leave_slip(law, t, y, modes, slot)?;
            }
        } else if fr.twisting.is_some() {
            let m = self.twist_trial(law, t, y)?;
            let (a, fc, ..) = self.contact(law, t, y)?;
            let (_, _, l) = twist_coefficients(
                fr.twisting.as_ref().unwrap_or(&Twisting::Marshall),
                fr,
                a,
                self.imp.normal.damping_at(a),
                fc,
            );
            if m.abs() > l {
                let mut slip = *modes;
                slip.twisting = Mode::Slip;
                slip.twist_sign = if m >= 0.0 { 1.0 } else { -1.0 };
                if self.evaluate(law, t, y, &slip)?.slip_rate_w > 0.0 {
                    *modes = slip;
                } else {
                    self.leave_twist_slip(law, t, y, &slip)?;
                }
            }
        }
        Ok(())
    }

    /// Looks again at a frozen element (0 tangential, 1 rolling, 2 twisting) at
    /// its thaw time: it is no longer frozen; where it sticks, it slips if its
    /// trial force (capped while it was frozen) is beyond its limit and keeps
    /// outgrowing it ([`Setup::decide_modes`]); where it slips, it sticks if its
    /// slip rate is not positive ([`Setup::stick_reversed_slips`]). Returns the
    /// number of tangential switches.
    pub(super) fn thaw(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        modes: &mut Modes,
        element: usize,
    ) -> Result<usize> {
        modes.frozen[element] = false;
        modes.thaw[element] = f64::INFINITY;
        let mode = [modes.tangential, modes.rolling, modes.twisting][element];
        if mode == Mode::Stick {
            self.decide_element(law, t, y, modes, element)?;
            return Ok(usize::from(element == 0 && modes.tangential == Mode::Slip));
        }
        self.stick_reversed_slips(law, t, y, modes)
    }

    /// After an event: each slipping element whose slip rate is ≤ 0 there
    /// sticks. The slip rate of an element that keeps slipping through an
    /// event can jump there, below 0, where no event value crosses 0 to show
    /// it: at a branch change (Maugis-Dugdale's junction, where the contact
    /// radius opens as (δ − δ_j)^½ and the Coulomb limit's rate is unbounded,
    /// ending the slip), at the switch of another element (its force moves
    /// the accelerations), and at the zero of a damped contact's normal force,
    /// where the Coulomb limits `μ |F_n|` touch 0 and grow again
    /// ([`Modes::tensile`] switched: a sticking element carries no trial force
    /// there, and keeps sticking). Before, such an element slipped on against
    /// its own rate: a Maugis-Dugdale contact with a tangential dashpot booked
    /// −4 times the kinetic energy as sliding work. An element that entered
    /// slip at the event did so at a positive slip rate and keeps slipping.
    /// Returns the number of tangential switches.
    pub(super) fn stick_reversed_slips(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        modes: &mut Modes,
    ) -> Result<usize> {
        if self.imp.friction.is_none() || !modes.in_contact || modes.warmup {
            return Ok(0);
        }
        let slipping = |m: Mode, i: usize| m == Mode::Slip && !modes.frozen[i];
        let [tangential, rolling, twisting] = [
            slipping(modes.tangential, 0) && self.bed.is_none(),
            slipping(modes.rolling, 1),
            slipping(modes.twisting, 2),
        ];
        if !(tangential || rolling || twisting) {
            return Ok(0);
        }
        let ev = self.evaluate(law, t, y, modes)?;
        let mut switches = 0;
        if tangential && ev.slip_rate_t <= 0.0 {
            modes.tangential = Mode::Stick;
            self.leave_slip(law, t, y, modes, XT)?;
            switches += 1;
        }
        if rolling && ev.slip_rate_r <= 0.0 {
            modes.rolling = Mode::Stick;
            self.leave_slip(law, t, y, modes, XR)?;
        }
        if twisting && ev.slip_rate_w <= 0.0 {
            modes.twisting = Mode::Stick;
            self.leave_twist_slip(law, t, y, modes)?;
        }
        Ok(switches)
    }

    /// The event values at SI (t, y): all positive while the modes hold; those
    /// of the reduced state ([`Setup::planar_event_values`], the same values to
    /// a few ulps) where it is planar.
    pub(super) fn event_values(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        modes: &Modes,
    ) -> Result<[f64; EVENTS]> {
        if self.is_planar(y, modes) {
            return self.planar_event_values(law, t, &Setup::planar_of(y), modes);
        }
        self.full_event_values(law, t, y, modes)
    }

    /// The event values at SI (t, y) from the 3-D forms.
    pub(super) fn full_event_values(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        modes: &Modes,
    ) -> Result<[f64; EVENTS]> {
        let (_, overlap, rate, _) = self.geometry(t, y);
        let mut g = [f64::INFINITY; EVENTS];
        g[0] = law.branch_end(overlap, rate)? / self.length;
        if modes.in_contact {
            g[1] = if modes.loading { rate } else { -rate } / self.v_n;
        }
        g[CAPTURE] = self.capture_value(law, t, y, modes)?;
        if modes.warmup {
            g[8] = WARMUP - overlap / self.length;
            return Ok(g);
        }
        if !modes.in_contact || self.imp.friction.is_none() || modes.frozen_for_good() {
            return Ok(g);
        }
        modes.thaw_events(&mut g, t, self.time);
        let normal = &self.imp.normal;
        if normal.pull_off_force <= 0.0 && normal.damping > 0.0 {
            let np = self.normal(law, overlap, rate, false)?;
            let f_n = np.force + normal.damping_at(np.radius) * rate;
            g[NORMAL_FORCE_ZERO] = if modes.tensile { -f_n } else { f_n } / self.force;
        }
        let fr = self
            .imp
            .friction
            .as_ref()
            .map(|f| (f.rolling.is_some(), f.twisting.is_some()));
        let (rolling, twisting) = fr.unwrap_or((false, false));
        let rate_unit = self.force / self.time;
        let need_rates = modes.tangential == Mode::Slip
            || modes.rolling == Mode::Slip
            || modes.twisting == Mode::Slip;
        let ev = if need_rates {
            Some(self.evaluate(law, t, y, modes)?)
        } else {
            None
        };
        // the contact quantities, once, for the elements that stick
        let sticking = |m: Mode, frozen: bool| m == Mode::Stick && !frozen;
        let c = if (sticking(modes.tangential, modes.frozen[0]) && self.bed.is_none())
            || (rolling && sticking(modes.rolling, modes.frozen[1]))
            || (twisting && sticking(modes.twisting, modes.frozen[2]))
        {
            Some(self.contact(law, t, y)?)
        } else {
            None
        };
        match (modes.tangential, &c) {
            // micro-slip has no stick/slip switch of the whole contact
            _ if modes.frozen[0] || self.bed.is_some() => {}
            (Mode::Stick, Some(c)) => {
                let (trial, limit, ..) = self.element_of(c, y, XT);
                g[2] = (limit - trial.norm()) / self.force;
            }
            (Mode::Stick, None) => {}
            (Mode::Slip, _) => {
                g[3] = ev.as_ref().map_or(f64::INFINITY, |e| e.slip_rate_t) / rate_unit
            }
        }
        if rolling && !modes.frozen[1] {
            match (modes.rolling, &c) {
                (Mode::Stick, Some(c)) => {
                    let (trial, limit, ..) = self.element_of(c, y, XR);
                    g[4] = (limit - trial.norm()) / self.force;
                }
                (Mode::Stick, None) => {}
                (Mode::Slip, _) => {
                    g[5] = ev.as_ref().map_or(f64::INFINITY, |e| e.slip_rate_r) / rate_unit
                }
            }
        }
        if twisting && !modes.frozen[2] {
            let torque_unit = self.force * self.length;
            match (modes.twisting, &c) {
                (Mode::Stick, Some(c)) => {
                    let (m, l) = self.twist_of(c, y);
                    g[6] = (l - m.abs()) / torque_unit;
                }
                (Mode::Stick, None) => {}
                (Mode::Slip, _) => {
                    g[7] = ev.as_ref().map_or(f64::INFINITY, |e| e.slip_rate_w)
                        / (torque_unit / self.time)
                }
            }
        }
        Ok(g)
    }
}
