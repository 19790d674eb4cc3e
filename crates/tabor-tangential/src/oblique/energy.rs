//! The energy ledger of an oblique impact: the work of every mechanism,
//! integrated with the motion.

use serde::Serialize;

/// The kinetic energy lost to each mechanism (J), integrated with the motion.
/// Their sum is the kinetic energy lost, to `energy_error`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct EnergyLosses {
    /// Work against the elastic-adhesive normal force `∫ F_n δ̇ dt`: 0 for an
    /// elastic law, the adhesive hysteresis for JKR and Maugis-Dugdale.
    pub normal_adhesion: f64,
    /// Work against the viscous normal force.
    pub normal_damping: f64,
    /// Work of the tangential force on the slip (Coulomb friction).
    pub sliding_friction: f64,
    /// Work of the tangential force on the slip of `mindlin_deresiewicz`'s springs
    /// (micro-slip in the partial-slip annulus and gross sliding): the tangential
    /// work less the dashpot's and less what is left in the springs
    /// (`tangential_spring`); 0 for the other models.
    pub micro_slip: f64,
    /// Work against the tangential dashpot `∫ γ_t |v_t|² dt`.
    pub tangential_damping: f64,
    /// The rest of the tangential work: elastic energy left in the tangential
    /// spring when the contact breaks, plus the energy `mindlin`'s
    /// radius-dependent stiffness destroys (or, negative, creates), less the
    /// strain LAMMPS's history gives a damped spring that sticks again while its
    /// dashpot alone reaches the limit (`|L û − γ v|²/2k`, no work put in).
    pub tangential_spring: f64,
    /// Work of the rolling resistance (dissipated and left in its spring).
    pub rolling: f64,
    /// Work of the twisting resistance (dissipated and left in its spring).
    pub twisting: f64,
    /// The work of LAMMPS's torque-arm convention: torques use `R − δ/2`, the
    /// sliding velocity uses R; their mismatch (small, of order δ/R, either sign).
    pub torque_arm: f64,
}

impl EnergyLosses {
    /// The sum of all mechanisms (J).
    pub fn total(&self) -> f64 {
        self.by_mechanism().iter().map(|(_, w)| w).sum()
    }

    /// Every mechanism's loss (J) with its name (as the command line prints
    /// it), in the order of the fields.
    pub fn by_mechanism(&self) -> [(&'static str, f64); 9] {
        [
            ("normal adhesion", self.normal_adhesion),
            ("normal damping", self.normal_damping),
            ("sliding friction", self.sliding_friction),
            ("micro-slip", self.micro_slip),
            ("tangential damping", self.tangential_damping),
            ("tangential spring", self.tangential_spring),
            ("rolling", self.rolling),
            ("twisting", self.twisting),
            ("torque arm", self.torque_arm),
        ]
    }
}
