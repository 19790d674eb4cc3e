//! The text of an export: the model keywords LAMMPS reads, the commands, and the
//! commented fragment (`Export::fragment`).

use crate::friction::FRICTIONLESS;
use crate::law::{GranularModel, NormalModel};
use crate::report::{Export, Geometry};

fn fmt_num(x: f64) -> String {
    format!("{x:.10e}")
}

/// The model keywords LAMMPS reads after `pair_coeff * *` or `wall/gran granular`,
/// for a frictionless central impact ([`FRICTIONLESS`]).
pub fn model_keywords(m: &GranularModel) -> String {
    keywords(m, FRICTIONLESS)
}

/// The model keywords with the tangential, rolling and twisting keywords `sub`
/// (`tabor_tangential::Friction::lammps_keywords`, or [`FRICTIONLESS`]).
pub(crate) fn keywords(m: &GranularModel, sub: &str) -> String {
    let normal = match m.normal {
        NormalModel::Hooke { stiffness } => {
            format!("hooke {} {}", fmt_num(stiffness), fmt_num(m.damp))
        }
        NormalModel::Hertz { stiffness } => {
            format!("hertz {} {}", fmt_num(stiffness), fmt_num(m.damp))
        }
        NormalModel::HertzMaterial {
            youngs_modulus,
            poisson_ratio,
        } => format!(
            "hertz/material {} {} {}",
            fmt_num(youngs_modulus),
            fmt_num(m.damp),
            poisson_ratio
        ),
        NormalModel::Dmt {
            youngs_modulus,
            poisson_ratio,
            surface_energy,
        } => format!(
            "dmt {} {} {} {}",
            fmt_num(youngs_modulus),
            fmt_num(m.damp),
            poisson_ratio,
            fmt_num(surface_energy)
        ),
        NormalModel::Jkr {
            youngs_modulus,
            poisson_ratio,
            surface_energy,
        } => format!(
            "jkr {} {} {} {}",
            fmt_num(youngs_modulus),
            fmt_num(m.damp),
            poisson_ratio,
            fmt_num(surface_energy)
        ),
    };
    format!(
        "{normal} {sub} damping {}{}",
        m.damping.keyword(),
        if m.limit_damping {
            " limit_damping"
        } else {
            ""
        }
    )
}

/// The LAMMPS commands of an export: `comm_modify vel yes` and the pair style with
/// its `pair_coeff * *`, or the wall fix on the plane z = 0.
pub(crate) fn commands(geometry: Geometry, keywords: &str) -> Vec<String> {
    match geometry {
        Geometry::Pair => vec![
            "comm_modify vel yes".to_string(),
            "pair_style granular".to_string(),
            format!("pair_coeff * * {keywords}"),
        ],
        Geometry::Wall => vec![
            "comm_modify vel yes".to_string(),
            format!("fix tabor_wall all wall/gran granular {keywords} zplane 0.0 NULL"),
        ],
    }
}

impl Export {
    /// The LAMMPS input fragment: comment lines stating the model, every calibrated
    /// number and its derivation, what is reproduced over which speeds and within
    /// which error, what is left out effect by effect, then the commands.
    pub fn fragment(&self) -> String {
        let mut s = String::new();
        let mut line = |t: &str| {
            s.push_str(t);
            s.push('\n');
        };
        line(&format!(
            "# tabor export lammps: scene \"{}\" ({})",
            self.scene,
            match self.geometry {
                Geometry::Pair => "sphere-sphere: pair_style granular",
                Geometry::Wall => "sphere on a flat wall: fix wall/gran granular",
            }
        ));
        line(&format!(
            "# Include after atom_style sphere / create_box (units si; LAMMPS's defaults, newton unchanged). {}",
            match &self.friction {
                Some(f) => format!("Friction, rolling and twisting from the scene's [friction]: pair granular's own sub-models ({f}); the claims below are about the normal restitution."),
                None => "Frictionless central impact.".to_string(),
            }
        ));
        line(&format!(
            "# LAMMPS model: {} + damping {}{}",
            self.model.normal.keyword(),
            self.model.damping.keyword(),
            if self.model.limit_damping {
                " + limit_damping"
            } else {
                ""
            }
        ));
        line(&format!(
            "# effective E* = {:.6e} Pa, R* = {:.6e} m, m* = {:.6e} kg; small strain up to {:.4e} m/s",
            self.effective_modulus,
            self.effective_radius,
            self.effective_mass,
            self.small_strain_speed
        ));
        for p in &self.parameters {
            line(&format!(
                "# {} = {:.10e} {}: {}",
                p.name, p.value, p.unit, p.derivation
            ));
        }
        let c = &self.reproduces;
        line(&format!(
            "# HOLDS FOR: {:.4e} ... {:.4e} m/s, |e_LAMMPS - e_tabor| <= {:.2e} + LAMMPS's time-step error",
            c.range[0], c.range[1], c.error
        ));
        line(&format!("# REPRODUCES: {}", c.statement));
        if let (Some(t), Some(l)) = (self.sticking_velocity, self.lammps_sticking_velocity) {
            line(&format!(
                "# sticking velocity: tabor {t:.6e} m/s, this LAMMPS model {l:.6e} m/s"
            ));
        }
        for n in &self.does_not_reproduce {
            line(&format!(
                "# DOES NOT REPRODUCE ({}{}): {}",
                n.effect,
                n.from_speed
                    .map_or(String::new(), |v| format!(", from {v:.4e} m/s on")),
                n.note
            ));
        }
        line(&format!(
            "# contact time at {:.4e} m/s: {:.4e} s; claims verified with timestep {:.4e} s (contact time/5000)",
            c.speed, self.contact_time, self.time_step
        ));
        line("# speed (m/s)   e_tabor        e_LAMMPS       difference  claimed");
        let lo = c.speed / 10f64.sqrt() * (1.0 - 1e-12);
        let hi = c.speed * 10f64.sqrt() * (1.0 + 1e-12);
        for p in self
            .comparison
            .iter()
            .filter(|p| p.speed >= lo && p.speed <= hi)
        {
            line(&format!(
                "#   {:.4e}   {:.10}   {:.10}   {:+.2e}   {}",
                p.speed,
                p.tabor,
                p.lammps,
                p.difference,
                if p.claimed { "yes" } else { "no" }
            ));
        }
        if self.geometry == Geometry::Wall {
            line("# the wall is the plane z = 0 with the sphere above it: change zplane to your geometry");
        }
        for c in &self.commands {
            line(c);
        }
        s
    }
}
