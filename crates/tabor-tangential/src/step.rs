//! The per-contact, per-time-step evaluation of the tangential, rolling and
//! twisting models, exactly as LAMMPS's `pair_style granular` performs it
//! (`GranularModel::calculate_forces` and the `gran_sub_mod_tangential`,
//! `_rolling`, `_twisting` sub-models): the API a DEM engine (the C ABI, the
//! LAMMPS plugin) calls once per contact and step. No allocation, no error path:
//! the inputs are the engine's own numbers, the output is always finite for
//! finite inputs.
//!
//! Conventions (LAMMPS's): body `i` and body `j`; the unit normal `n` points from
//! `j` to `i`; `relative_velocity = v_i − v_j`; the returned tangential force acts
//! on `i` (and its negative on `j`); torques are returned for both bodies.

pub use crate::history::{rotate_into_plane, ContactHistory};
use crate::micro_slip;
use crate::model::{critical_force, Friction, TangentialModel, Twisting};
use nalgebra::Vector3;

/// LAMMPS's `EPSILON` (1e-10) of the frame update: a stored displacement is turned
/// into the current tangent plane only when its normal component is more than
/// this fraction of the Coulomb limit.
const FRAME_EPSILON: f64 = 1e-10;

/// The geometry and motion of one contact at one time step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactKinematics {
    /// Unit normal from body `j` to body `i` (LAMMPS `nx`).
    pub normal: Vector3<f64>,
    /// Overlap δ = R_i + R_j − |x_i − x_j| (m).
    pub overlap: f64,
    /// Radius of body `i` (m).
    pub radius_i: f64,
    /// Radius of body `j` (m); `f64::INFINITY` for a flat wall (LAMMPS
    /// `fix wall/gran`: effective radius R_i, torque arm R_i).
    pub radius_j: f64,
    /// v_i − v_j (m/s).
    pub relative_velocity: Vector3<f64>,
    /// ω_i (rad/s).
    pub angular_velocity_i: Vector3<f64>,
    /// ω_j (rad/s); ignored for a wall.
    pub angular_velocity_j: Vector3<f64>,
}

impl ContactKinematics {
    fn wall(&self) -> bool {
        self.radius_j.is_infinite()
    }

    /// The effective radius R_i R_j/(R_i + R_j) (R_i for a wall) (m).
    pub fn effective_radius(&self) -> f64 {
        if self.wall() {
            self.radius_i
        } else {
            self.radius_i * self.radius_j / (self.radius_i + self.radius_j)
        }
    }

    /// `ω_j`, zero for a wall.
    fn omega_j(&self) -> Vector3<f64> {
        if self.wall() {
            Vector3::zeros()
        } else {
            self.angular_velocity_j
        }
    }

    /// The relative tangential velocity of the contact point, LAMMPS `vtr`:
    /// `v_t − (R_i ω_i + R_j ω_j) × n`, with `v_t` the part of `v_i − v_j`
    /// normal to `n` (m/s).
    pub fn sliding_velocity(&self) -> Vector3<f64> {
        let n = self.normal;
        let v = self.relative_velocity;
        let vt = v - n * n.dot(&v);
        let mut wr = self.angular_velocity_i * self.radius_i;
        if !self.wall() {
            wr += self.angular_velocity_j * self.radius_j;
        }
        vt - wr.cross(&n)
    }

    /// The relative rolling velocity, LAMMPS `vrl` (Wang et al. 2015, eq. 31):
    /// `R_eff (ω_i − ω_j) × n` (m/s).
    pub fn rolling_velocity(&self) -> Vector3<f64> {
        (self.angular_velocity_i - self.omega_j()).cross(&self.normal) * self.effective_radius()
    }

    /// The relative twisting rate `(ω_i − ω_j) · n` (rad/s), Marshall 2009 eq. 29.
    pub fn twisting_rate(&self) -> f64 {
        (self.angular_velocity_i - self.omega_j()).dot(&self.normal)
    }

    /// The torque arms of the tangential force, `R_i − δ/2` and `R_j − δ/2`
    /// (LAMMPS's pair convention; a wall: `R_i` and 0) (m).
    pub fn torque_arms(&self) -> (f64, f64) {
        if self.wall() {
            (self.radius_i, 0.0)
        } else {
            (
                self.radius_i - 0.5 * self.overlap,
                self.radius_j - 0.5 * self.overlap,
            )
        }
    }
}

/// What the normal model says about the contact at this step: the inputs of the
/// tangential, rolling and twisting models that come from the normal contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalResponse {
    /// Contact radius a (m).
    pub contact_radius: f64,
    /// Elastic (and adhesive) normal force F_n,elastic (N, repulsive > 0).
    pub elastic_force: f64,
    /// Total normal force, elastic plus damping (N), after any `limit_damping`.
    pub total_force: f64,
    /// The pull-off force magnitude F_pulloff ≥ 0 (N) of a cohesive normal model,
    /// 0 otherwise (see [`critical_force`]).
    pub pull_off_force: f64,
    /// The normal damping coefficient η_n (N s/m), LAMMPS's `damp_prefactor`
    /// (e.g. `η_n0 m_eff a` for `damping viscoelastic`, `2 η_c a` for tabor's
    /// Kuwabara-Kono damping); 0 without damping.
    pub damping_coefficient: f64,
}

impl NormalResponse {
    /// `F_n0` of this response ([`critical_force`]).
    pub fn critical_force(&self) -> f64 {
        critical_force(self.elastic_force, self.total_force, self.pull_off_force)
    }
}

/// The tangential force and the torques of one contact at one step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactForces {
    /// Tangential force on body `i` (N); body `j` gets its negative.
    pub tangential_force: Vector3<f64>,
    /// Torque on body `i` (N m): tangential, rolling and twisting.
    pub torque_i: Vector3<f64>,
    /// Torque on body `j` (N m).
    pub torque_j: Vector3<f64>,
    /// The rolling resistance "force" `F_r` (N), LAMMPS `fr` (the torque is
    /// `R_eff n × F_r` on `i`).
    pub rolling_force: Vector3<f64>,
    /// The twisting torque magnitude along `n` on body `i` (N m).
    pub twisting_torque: f64,
    /// `F_n0` used for the Coulomb limits (N).
    pub critical_force: f64,
    /// True when the tangential force is at its Coulomb limit (sliding).
    pub sliding: bool,
}

impl Friction {
    /// One step of one contact: updates `history` (when `update_history`; LAMMPS
    /// does not on the setup force call) over the time step `time_step` (s) and
    /// returns the tangential force and the torques, as LAMMPS's
    /// `pair_style granular` computes them:
    ///
    /// 1. tangential (`gran_sub_mod_tangential.cpp`): the stored displacement is
    ///    rotated into the current tangent plane (keeping its length), incremented
    ///    by `dt v_tr`, and gives `F_t = −k ξ − x_γ,t η_n v_tr` with `k` the spring
    ///    of [`crate::Tangential::spring`]; beyond `μ F_n0` the force is scaled to
    ///    the limit and ξ reset to the elastic part of the scaled force;
    ///    `mindlin_rescale` first scales ξ by `a/a_old` when the contact shrinks;
    ///    `mindlin_deresiewicz` (not a LAMMPS model) advances instead a compact
    ///    spring bed of the method of dimensionality reduction (Mindlin-Deresiewicz
    ///    micro-slip, [`crate::micro_slip`]: [`crate::micro_slip::SPRINGS`] springs
    ///    in `z = x²`, each with its share of the limit `L = μ F_n0`), whose elastic
    ///    force `T` (`|T| ≤ L`) is kept in `history.tangential`, and adds the
    ///    damping `−x_γ,t η_n v_tr`, the sum again capped at `L`;
    /// 2. rolling `sds` (`gran_sub_mod_rolling.cpp`): the same on the rolling
    ///    displacement with `k_roll`, `γ_roll`, `μ_roll F_n0`;
    /// 3. twisting (`gran_sub_mod_twisting.cpp`): `M = −k θ − γ ω_tw`, limited to
    ///    `μ_tw F_n0` (Marshall 2009 eqs. 30, 34, 44);
    /// 4. torques (`granular_model.cpp`): `−(R − δ/2) n × F_t` on each body,
    ///    `± R_eff n × F_r` and `± M n`.
    ///
    /// A contact radius of 0 (the no-contact branch of Maugis-Dugdale) gives a
    /// zero spring. A spring whose stiffness vanishes with the contact radius
    /// (`mindlin`, `mindlin_rescale`: `k_t a`; `marshall` twisting: `½ k_t a²`)
    /// then stores no displacement (it is set to 0, so a contact area that forms
    /// again starts unstrained, as the library's [`crate::oblique`] impact
    /// does); the `linear_history` displacement and the `sds` twist keep
    /// accumulating, as in LAMMPS, and nothing divides by a zero spring (LAMMPS
    /// would).
    pub fn step(
        &self,
        kinematics: &ContactKinematics,
        normal: &NormalResponse,
        time_step: f64,
        update_history: bool,
        history: &mut ContactHistory,
    ) -> ContactForces {
        let n = kinematics.normal;
        let a = normal.contact_radius;
        let fn0 = normal.critical_force();
        let t = &self.tangential;
        let damp = t.damping_ratio * normal.damping_coefficient;
        let k = t.spring(a);
        let limit = t.coefficient * fn0;
        let vtr = kinematics.sliding_velocity();

        // 1. tangential
        if t.model == TangentialModel::MindlinDeresiewicz {
            let (fs, sliding) = if update_history {
                let (t_el, sliding) = micro_slip::advance(
                    &mut history.micro_slip,
                    &n,
                    &(vtr * time_step),
                    0.5 * t.stiffness,
                    a,
                    limit,
                );
                history.tangential = t_el.into();
                (-t_el, sliding)
            } else {
                let t = rotate_into_plane(Vector3::from(history.tangential), &n);
                (-t, t.norm() >= limit)
            };
            let damping_force = -vtr * damp;
            let mut total = fs + damping_force;
            let magnitude = total.norm();
            if magnitude > limit && magnitude > 0.0 {
                total *= limit / magnitude;
            }
            return self.finish(
                kinematics,
                normal,
                time_step,
                update_history,
                history,
                total,
                sliding || magnitude > limit,
            );
        }
        let mut xi = Vector3::from(history.tangential);
        if t.model == TangentialModel::MindlinRescale && a < history.tangential_contact_radius {
            xi *= a / history.tangential_contact_radius;
        }
        if update_history {
            if xi.dot(&n).abs() * k > FRAME_EPSILON * limit {
                xi = rotate_into_plane(xi, &n);
            }
            xi += vtr * time_step;
            if a <= 0.0 && t.vanishes_without_area() {
                // no contact area: the spring k_t a stores nothing
                xi = Vector3::zeros();
            }
            if t.model == TangentialModel::MindlinRescale {
                history.tangential_contact_radius = a;
            }
        }
        let damping_force = -vtr * damp;
        let mut fs = -xi * k + damping_force;
        let magnitude = fs.norm();
        let sliding = magnitude > limit;
        if sliding {
            if xi.norm() != 0.0 {
                fs *= limit / magnitude;
                if k > 0.0 {
                    xi = -(fs - damping_force) / k;
                }
            } else {
                fs = Vector3::zeros();
            }
        }
        history.tangential = xi.into();
        self.finish(
            kinematics,
            normal,
            time_step,
            update_history,
            history,
            fs,
            sliding,
        )
    }

    /// Steps 2-4 of [`Friction::step`] (rolling, twisting, torques) after the
    /// tangential force `fs` on body `i`.
    #[allow(clippy::too_many_arguments)]
    fn finish(
        &self,
        kinematics: &ContactKinematics,
        normal: &NormalResponse,
        time_step: f64,
        update_history: bool,
        history: &mut ContactHistory,
        fs: Vector3<f64>,
        sliding: bool,
    ) -> ContactForces {
        let n = kinematics.normal;
        let a = normal.contact_radius;
        let fn0 = normal.critical_force();
        let t = &self.tangential;
        let damp = t.damping_ratio * normal.damping_coefficient;
        let (arm_i, arm_j) = kinematics.torque_arms();
        let n_cross_fs = n.cross(&fs);
        let mut torque_i = -n_cross_fs * arm_i;
        let mut torque_j = -n_cross_fs * arm_j;

        // 2. rolling
        let mut rolling_force = Vector3::zeros();
        if let Some(r) = &self.rolling {
            let vrl = kinematics.rolling_velocity();
            let limit_r = r.coefficient * fn0;
            let mut psi = Vector3::from(history.rolling);
            if update_history {
                if psi.dot(&n).abs() * r.stiffness > FRAME_EPSILON * limit_r {
                    psi = rotate_into_plane(psi, &n);
                }
                psi += vrl * time_step;
            }
            let mut fr = -psi * r.stiffness - vrl * r.damping;
            let magnitude = fr.norm();
            if magnitude > limit_r {
                if psi.norm() != 0.0 {
                    psi = -(fr * (limit_r / magnitude) + vrl * r.damping) / r.stiffness;
                    fr *= limit_r / magnitude;
                } else {
                    fr = Vector3::zeros();
                }
            }
            if update_history {
                history.rolling = psi.into();
            }
            let torque = n.cross(&fr) * kinematics.effective_radius();
            torque_i += torque;
            torque_j -= torque;
            rolling_force = fr;
        }

        // 3. twisting
        let mut twisting_torque = 0.0;
        if let Some(tw) = &self.twisting {
            let (k_tw, damp_tw, mu_tw) = match *tw {
                // Marshall 2009 eq. 32 with LAMMPS's k_t (the coefficient, not k_t a)
                Twisting::Marshall => (
                    0.5 * t.stiffness * a * a,
                    0.5 * damp * a * a,
                    2.0 / 3.0 * t.coefficient * a,
                ),
                Twisting::Sds {
                    stiffness,
                    damping,
                    coefficient,
                } => (stiffness, damping, coefficient),
            };
            let rate = kinematics.twisting_rate();
            if update_history {
                history.twisting += rate * time_step;
                if a <= 0.0 && tw.vanishes_without_area() {
                    // no contact area: the spring ½ k_t a² stores nothing
                    history.twisting = 0.0;
                }
            }
            let mut torque = -k_tw * history.twisting - damp_tw * rate;
            let limit_tw = mu_tw * fn0;
            if torque.abs() > limit_tw {
                let sign = if rate > 0.0 {
                    1.0
                } else if rate < 0.0 {
                    -1.0
                } else {
                    0.0
                };
                if k_tw > 0.0 {
                    history.twisting = (limit_tw * sign - damp_tw * rate) / k_tw;
                }
                torque = -limit_tw * sign;
            }
            torque_i += n * torque;
            torque_j -= n * torque;
            twisting_torque = torque;
        }

        ContactForces {
            tangential_force: fs,
            torque_i,
            torque_j,
            rolling_force,
            twisting_torque,
            critical_force: fn0,
            sliding,
        }
    }
}
