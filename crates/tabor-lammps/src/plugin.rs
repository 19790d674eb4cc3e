//! From a tabor scene to a LAMMPS fragment for `pair_style tabor`, the plugin of
//! `integrations/lammps/plugin`, which evaluates tabor's force laws themselves
//! (through `tabor-ffi`) instead of LAMMPS's `jkr` with an effective γ.

use crate::friction::{null_stiffness_fits, scene_friction};
use crate::report::{ExportError, Geometry};
use crate::wall::wall_style;
use serde::Serialize;
use std::fmt::Display;
use tabor_ffi::ContactLaw;
use tabor_jkr::SeparationRule;
use tabor_scene::{AdhesionRange, Scene};
use tabor_visco::contact::{Body as ViscoBody, ViscoelasticContact};

/// The time step, as a fraction of the Hertz contact time at the reference speed,
/// at which the plugin's restitution was verified against `tabor impact` by running
/// LAMMPS (`integrations/lammps/test_plugin.py`: every difference below 1.2e-4).
pub const PLUGIN_TIME_STEP_FRACTION: f64 = 1.0 / 20000.0;

/// The bound on |e_LAMMPS − e_tabor| that the plugin's LAMMPS proof tests hold it to
/// at [`PLUGIN_TIME_STEP_FRACTION`].
pub const PLUGIN_RESTITUTION_ERROR: f64 = 1e-3;

/// The model keyword of `pair_coeff * * MODEL …` for `pair_style tabor`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PluginModel {
    /// `hertz E*`: no adhesion.
    Hertz,
    /// `jkr/fixed-grip E* w`.
    JkrFixedGrip,
    /// `jkr/load-controlled E* w`.
    JkrLoadControlled,
    /// `maugis E* w Λ`.
    Maugis,
}

impl PluginModel {
    /// The keyword `pair_coeff` reads.
    pub fn keyword(self) -> &'static str {
        match self {
            PluginModel::Hertz => "hertz",
            PluginModel::JkrFixedGrip => "jkr/fixed-grip",
            PluginModel::JkrLoadControlled => "jkr/load-controlled",
            PluginModel::Maugis => "maugis",
        }
    }
}

/// tabor's restitution at one speed (what the plugin reproduces in LAMMPS).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PluginSpeed {
    /// Impact speed (m/s).
    pub speed: f64,
    /// tabor's restitution (0 when the bodies stick).
    pub restitution: f64,
}

/// A scene exported for `pair_style tabor`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PluginExport {
    /// The scene's name.
    pub scene: String,
    /// The path of the plugin's shared library, as given (`plugin load PATH`).
    pub plugin: String,
    /// The force law.
    pub model: PluginModel,
    /// Effective modulus E* (Pa): 1/E* = (1−ν1²)/E1 + (1−ν2²)/E2.
    pub effective_modulus: f64,
    /// Work of adhesion w (J/m²), `None` for Hertz.
    pub work_of_adhesion: Option<f64>,
    /// Tabor parameter Λ (at the scene's R*), `None` unless Maugis-Dugdale.
    pub tabor_parameter: Option<f64>,
    /// The Dugdale range h (m) of `--per-contact-lambda` (`maugis E* w range h`),
    /// `None` for a fixed Λ.
    pub dugdale_range: Option<f64>,
    /// Kuwabara-Kono dissipative time A (s), `None` without viscosity.
    pub damping_time: Option<f64>,
    /// Effective radius R* (m) of the scene's two spheres.
    pub effective_radius: f64,
    /// Reduced mass (kg).
    pub effective_mass: f64,
    /// The overlap (m) at which the contact forms (≤ 0: before touching).
    pub jump_in_overlap: f64,
    /// The overlap (m) at which it breaks (< 0 with adhesion).
    pub snap_off_overlap: f64,
    /// The distance beyond touching (m) over which the law acts: the neighbor skin
    /// must be at least this.
    pub interaction_range: f64,
    /// The neighbor skin the fragment sets (m): 2 × the interaction range, at
    /// least a tenth of the smaller sphere radius.
    pub neighbor_skin: f64,
    /// The model's pull-off force, the most tensile force of the law (N, ≤ 0).
    pub pull_off_force: f64,
    /// tabor's sticking velocity (m/s), when the bodies can stick.
    pub sticking_velocity: Option<f64>,
    /// The reference speed of the restitution table (m/s): the scene's or --speed,
    /// else twice the sticking velocity, else 1 m/s.
    pub reference_speed: f64,
    /// Hertz contact time at the reference speed (s), seed 000 (5.12).
    pub contact_time: f64,
    /// The time step the claims were verified at: contact time/20000 (s).
    pub time_step: f64,
    /// tabor's restitution over two decades around the reference speed.
    pub restitution: Vec<PluginSpeed>,
    /// The wall of a flat target: the wallstyle and its arguments of
    /// `fix … wall/tabor` (`zplane 0.0 NULL` unless `--wall` says otherwise);
    /// `None` for two spheres (`pair_style tabor`).
    pub wall: Option<String>,
    /// The LAMMPS commands of the fragment.
    pub commands: Vec<String>,
    /// What the plugin reproduces.
    pub reproduces: Vec<String>,
    /// What it does not (its limits).
    pub does_not_reproduce: Vec<String>,
    /// Warnings about the export itself (a plugin path that does not exist).
    pub warnings: Vec<String>,
}

/// `plugin load PATH` with the path quoted for LAMMPS's parser (spaces allowed;
/// triple quotes when the path itself holds a double quote).
pub fn plugin_load_command(plugin: &str) -> String {
    if plugin.contains('"') {
        format!("plugin load \"\"\"{plugin}\"\"\"")
    } else {
        format!("plugin load \"{plugin}\"")
    }
}

fn model_err(e: impl Display) -> ExportError {
    ExportError::Model(e.to_string())
}

fn refuse(effect: &str, reason: impl Into<String>) -> ExportError {
    ExportError::Unrepresentable {
        effect: format!("{effect} with pair_style tabor"),
        reason: reason.into(),
    }
}

/// The Kuwabara-Kono time A (s) of a Kelvin-Voigt contact E*(s) = E* + η_c s
/// between the scene's bodies, `None` when neither is viscous. A standard medium
/// (one viscous body) or two relaxation times are refused: the plugin's damping
/// 2E*A a δ̇ is exactly the Kelvin-Voigt contact's 2η_c a δ̇ (A = η_c/E*), and
/// nothing else.
fn damping_time(scene: &Scene, adhesive: bool) -> Result<Option<f64>, ExportError> {
    if scene.sphere.viscosity.is_none() && scene.target.viscosity.is_none() {
        return Ok(None);
    }
    let body = |b: &tabor_scene::Body| {
        ViscoBody::new(
            b.material.youngs_modulus(),
            b.material.poisson_ratio(),
            b.viscosity,
        )
        .map_err(model_err)
    };
    let contact = ViscoelasticContact::of(&body(&scene.sphere)?, &body(&scene.target)?)
        .map_err(|e| refuse("viscoelasticity", format!("two viscous bodies with different relaxation times ({e}): a four-parameter medium, no Kuwabara-Kono time")))?;
    match contact {
        ViscoelasticContact::Elastic { .. } => Ok(None),
        ViscoelasticContact::StandardMedium { .. } => Err(refuse(
            "a standard-medium viscosity",
            "one Kelvin-Voigt body on an elastic one makes a standard linear medium (5.75), whose force has a relaxation memory; the plugin's damping is the Kuwabara-Kono force 2 E* A a v_n of a Kelvin-Voigt contact (give both bodies the same relaxation time, or use tabor export lammps without --plugin: damping viscoelastic calibrated at one speed)",
        )),
        ViscoelasticContact::KelvinVoigt {
            shear_modulus,
            viscosity,
        } => {
            if !adhesive {
                return Err(refuse(
                    "a Kelvin-Voigt viscosity without adhesion",
                    "tabor's Kelvin-Voigt sphere separates by the MDR edge condition (5.67), F = (5/4)(x + tau x')^(3/2) until x + tau x' = 0, while the plugin's Hertz + Kuwabara-Kono force is clipped at F = 0: the restitutions differ (use tabor export lammps without --plugin)",
                ));
            }
            // E*(s) = 4 (G* + η* s): η_c = 4η*, E* = 4G*; A = η_c/E* = η*/G*
            Ok(Some(viscosity / shear_modulus))
        }
    }
}

/// The wall of [`export_plugin`] for a flat target: the plane z = 0 below the
/// particles (`fix … wall/tabor … zplane 0.0 NULL`).
pub const DEFAULT_WALL: &str = "zplane 0.0 NULL";

/// Exports `scene` for the plugin loaded from `plugin` (the `.so` that
/// `cargo xtask lammps-plugin` prints): `pair_style tabor` for two spheres,
/// `fix tabor_wall all wall/tabor` on [`DEFAULT_WALL`] for a flat target.
/// `speed` (m/s) only centres the restitution table: the plugin's force law holds
/// at every speed.
///
/// Errors: [`ExportError::Unrepresentable`] for a graded medium, plasticity, a
/// standard-medium or two-relaxation-time viscosity, and a Kelvin-Voigt viscosity
/// without adhesion (see `crates/tabor-lammps/README.md`).
pub fn export_plugin(
    scene: &Scene,
    plugin: &str,
    speed: Option<f64>,
) -> Result<PluginExport, ExportError> {
    export_plugin_with(scene, plugin, speed, PluginOptions::default())
}

/// Choices of [`export_plugin_with`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PluginOptions {
    /// Write Maugis-Dugdale as `maugis E* w range h` (the Dugdale range held fixed,
    /// each contact's Λ = d_n(R*)/h from its own size) instead of a fixed Λ; h is
    /// the scene's, or d_n(R*)/Λ at the scene's R* (so the scene's own pair gets
    /// exactly its Λ). Refused for a scene that is not Maugis-Dugdale.
    pub per_contact_lambda: bool,
    /// The wall of a flat target: a wallstyle of `fix wall/tabor` and its
    /// arguments, as `--wall` takes them; `None`: [`DEFAULT_WALL`]. A wall given
    /// for two spheres is refused.
    pub wall: Option<String>,
}

/// [`export_plugin`] with the wall of a flat target given (`wall`: a wallstyle and
/// its arguments, as `--wall` takes them; `None`: [`DEFAULT_WALL`]). A wall given
/// for two spheres is refused.
pub fn export_plugin_wall(
    scene: &Scene,
    plugin: &str,
    speed: Option<f64>,
    wall: Option<&str>,
) -> Result<PluginExport, ExportError> {
    let options = PluginOptions {
        wall: wall.map(str::to_owned),
        ..PluginOptions::default()
    };
    export_plugin_with(scene, plugin, speed, options)
}

/// [`export_plugin`] with [`PluginOptions`].
pub fn export_plugin_with(
    scene: &Scene,
    plugin: &str,
    speed: Option<f64>,
    options: PluginOptions,
) -> Result<PluginExport, ExportError> {
    let geometry = if scene.target.radius.is_some() {
        Geometry::Pair
    } else {
        Geometry::Wall
    };
    if let Some((k, _)) = scene.target.gradation {
        return Err(refuse(
            "a graded medium",
            format!("gradation exponent k = {k}: the plugin's laws are homogeneous-half-space laws (Hertz, JKR, Maugis-Dugdale), and tabor's graded JKR (5.47)-(5.51) is not in the C ABI"),
        ));
    }
    if let Some(sy) = scene.yield_stress() {
        return Err(refuse(
            "plasticity",
            format!("yield stress {sy:e} Pa: the plugin's force laws are elastic (no residual indentation or plastic loss); use tabor export lammps without --plugin (damping calibrated at one speed)"),
        ));
    }
    let adhesion = scene.adhesion.as_ref().filter(|a| a.work_of_adhesion > 0.0);
    let a_time = damping_time(scene, adhesion.is_some())?;
    let wall = match (geometry, options.wall.as_deref()) {
        (Geometry::Wall, w) => Some(wall_style(w.unwrap_or(DEFAULT_WALL))?),
        (Geometry::Pair, Some(w)) => {
            return Err(ExportError::Model(format!(
                "--wall {w:?}: the scene's target is a sphere (pair_style tabor); --wall is for a flat target"
            )))
        }
        (Geometry::Pair, None) => None,
    };
    let e_star = scene.effective_modulus;
    let r = scene.effective_radius;
    let m = scene.effective_mass;
    let (model, w, lambda) = match adhesion {
        None => (PluginModel::Hertz, None, None),
        Some(a) => match a.range {
            AdhesionRange::TaborParameter(l) => {
                (PluginModel::Maugis, Some(a.work_of_adhesion), Some(l))
            }
            AdhesionRange::Jkr => match a.separation {
                SeparationRule::FixedGrip => {
                    (PluginModel::JkrFixedGrip, Some(a.work_of_adhesion), None)
                }
                SeparationRule::LoadControlled => (
                    PluginModel::JkrLoadControlled,
                    Some(a.work_of_adhesion),
                    None,
                ),
            },
        },
    };
    // --per-contact-lambda: the range h = d_n(R*)/Λ at the scene's R* (exactly
    // the scene's Λ for the scene's own pair), then Λ = d_n(R*)/h per contact
    let dugdale_range = match (options.per_contact_lambda, w, lambda) {
        (false, _, _) => None,
        (true, Some(w), Some(l)) => Some(
            tabor_jkr::JkrSphere::new(e_star, r, w)
                .map_err(model_err)?
                .scales()
                .depth
                / l,
        ),
        (true, _, _) => {
            return Err(refuse(
                "a per-contact Tabor parameter",
                "--per-contact-lambda needs a Maugis-Dugdale scene ([adhesion] range, cohesive_stress, tabor_parameter, maugis_parameter or tabor_mu)",
            ))
        }
    };
    let law = match (model, w, lambda) {
        (PluginModel::Maugis, Some(w), Some(l)) => match dugdale_range {
            Some(h) => ContactLaw::maugis_dugdale_range(e_star, r, w, h),
            None => ContactLaw::maugis_dugdale(e_star, r, w, l),
        },
        (PluginModel::JkrFixedGrip, Some(w), _) => {
            ContactLaw::jkr(e_star, r, w, SeparationRule::FixedGrip)
        }
        (PluginModel::JkrLoadControlled, Some(w), _) => {
            ContactLaw::jkr(e_star, r, w, SeparationRule::LoadControlled)
        }
        _ => ContactLaw::hertz(e_star, r),
    }
    .map_err(model_err)?;
    let range = law.interaction_range();
    let smaller_radius = scene
        .sphere
        .radius
        .unwrap_or(f64::INFINITY)
        .min(scene.target.radius.unwrap_or(f64::INFINITY));
    let skin = (2.0 * range).max(0.1 * smaller_radius);
    let sticking = scene.sticking_velocity().map_err(model_err)?;
    let v_ref = speed
        .or(scene.speed)
        .or(sticking.map(|v| 2.0 * v))
        .unwrap_or(1.0);
    let mut restitution = Vec::new();
    for k in -4..=4 {
        let v = v_ref * 10f64.powf(k as f64 / 4.0);
        // speeds outside the scene's models (e.g. beyond small strain) are left out
        let Ok(o) = scene.outcome_at(v) else {
            continue;
        };
        restitution.push(PluginSpeed {
            speed: v,
            restitution: if o.sticks { 0.0 } else { o.restitution },
        });
    }
    // seed 000 (5.12): t_c = 2.868 (m*²/(R* E*² v))^(1/5)
    let contact_time = 2.868 * (m * m / (r * e_star * e_star * v_ref)).powf(0.2);
    let fmt = |x: f64| format!("{x:.10e}");
    let mut coeff = format!("{} {}", model.keyword(), fmt(e_star));
    if let Some(w) = w {
        coeff += &format!(" {}", fmt(w));
    }
    match (dugdale_range, lambda) {
        (Some(h), _) => coeff += &format!(" range {}", fmt(h)),
        (None, Some(l)) => coeff += &format!(" {}", fmt(l)),
        _ => {}
    }
    if let Some(a) = a_time {
        coeff += &format!(" damping {}", fmt(a));
    }
    // a DEM damping law: pair granular's model name, its value after it
    // (tabor_viscoadhesive::NormalDamping, the library's definitions)
    let dem_damping = scene
        .damping
        .and_then(|d| d.model().map(|m| (m, d.value(), d.describe())));
    if let Some((m, value, _)) = &dem_damping {
        coeff += &format!(" damping {m} {}", fmt(*value));
    }
    // the scene's [friction] with pair granular's keywords (k_t NULL: the plugin
    // computes 8 G* from E* and `poisson nu`, for two bodies of one material)
    let friction = scene_friction(scene, true)?;
    let friction_kw = friction.as_ref().map(|f| {
        let nu = scene.sphere.material.poisson_ratio();
        let null = null_stiffness_fits(scene, f, 2.0 * e_star * (1.0 - nu * nu), nu);
        format!(
            "{}{}",
            if null {
                format!("poisson {nu} ")
            } else {
                String::new()
            },
            f.lammps_keywords(null)
        )
    });
    if let Some(k) = &friction_kw {
        coeff += &format!(" {k}");
    }
    // every line is legal after create_box with LAMMPS's defaults: the fragment
    // does not change `newton` (the pair style works with either setting)
    let commands = match &wall {
        None => vec![
            "comm_modify vel yes".to_string(),
            plugin_load_command(plugin),
            "pair_style tabor".to_string(),
            format!("pair_coeff * * {coeff}"),
            format!("neighbor {} bin", fmt(skin)),
            "neigh_modify every 1 delay 0 check yes".to_string(),
        ],
        // the same MODEL ARGS [KEYWORDS] as pair_coeff (one parser in the plugin)
        Some(w) => vec![
            plugin_load_command(plugin),
            format!("fix tabor_wall all wall/tabor {coeff} {w}"),
        ],
    };
    let law_name = match model {
        PluginModel::Hertz => "Hertz".to_string(),
        PluginModel::JkrFixedGrip => "JKR with the fixed-grip separation".to_string(),
        PluginModel::JkrLoadControlled => "JKR with the load-controlled separation".to_string(),
        PluginModel::Maugis => match dugdale_range {
            Some(h) => format!(
                "Maugis-Dugdale at the fixed range h = {h:.6e} m (cohesive stress w/h = {:.6e} Pa), each contact's Lambda = d_n(R*)/h: Lambda = {:.6e} at the scene's R*; the table over Lambda adds |dF| <= 3e-5 F_n",
                w.unwrap_or(f64::NAN) / h,
                lambda.unwrap_or(f64::NAN)
            ),
            None => format!("Maugis-Dugdale at Lambda = {:.6e}", lambda.unwrap_or(f64::NAN)),
        },
    };
    let mut reproduces = vec![format!(
        "tabor's force law itself ({law_name}{}), so tabor's restitution at every speed{}: |e_LAMMPS - e_tabor| <= {PLUGIN_RESTITUTION_ERROR:.0e} at timestep <= Hertz contact time/20000 ({})",
        if a_time.is_some() {
            " + Kuwabara-Kono damping 2 E* A a v_n with the law's contact radius: tabor's viscous-adhesive model of a Kelvin-Voigt contact, A = eta_c/E*"
        } else {
            ""
        },
        if sticking.is_some() {
            " and the sticking velocity"
        } else {
            ""
        },
        if wall.is_some() {
            "measured <= 6.4e-4 already at contact time/5000 on the wall in integrations/lammps/test_plugin_wall.py"
        } else {
            "measured <= 1.2e-4 in integrations/lammps/test_plugin.py"
        }
    )];
    if let Some((_, _, d)) = &dem_damping {
        reproduces.push(format!(
            "the scene's [damping], {d}: the library's definition (tabor_viscoadhesive::NormalDamping, LAMMPS pair granular's for Hertz) on the law's own contact radius, adhesive laws too (where pair granular refuses tsuji and coeff_restitution), unclipped as pair granular without limit_damping"
        ));
    }
    if adhesion.is_some() {
        reproduces.push(format!(
            "the pull-off force {:.6e} N (most tensile force of the law; measured within 1e-7 in LAMMPS), the jump-in at overlap {:.6e} m and the snap-off at {:.6e} m",
            law.pull_off_force(),
            law.jump_in_overlap(),
            law.snap_off_overlap()
        ));
    }
    reproduces.push("the contact radius and the force along the whole loading and unloading path (tables: |dF|/F_n <= 2e-6 adhesive part, 3e-11 Hertzian part; see crates/tabor-ffi/README.md)".into());
    if let Some(k) = &friction_kw {
        reproduces.push(format!(
            "the scene's friction, rolling and twisting ({k}): tabor's tangential models, which follow pair granular's (the Coulomb limits with tabor's own pull-off force)"
        ));
    }
    let mut limits = vec![
        if friction_kw.is_some() {
            "energy per mechanism: LAMMPS reports no work of friction, rolling or twisting (tabor impact --angle does)".to_string()
        } else {
            "tangential, rolling and twisting contact: the scene has no [friction], normal forces only (give a [friction] section for pair granular's sub-models)".to_string()
        },
        if wall.is_some() {
            "energy tally: the wall fix tallies no energy (its contact histories are written to restart files; after read_restart include this fragment again, same fix ID)".to_string()
        } else {
            "energy tally: the pair style tallies no energy (its contact histories are written to restart files; after read_restart include this fragment again)".to_string()
        },
    ];
    if model == PluginModel::Maugis && dugdale_range.is_none() {
        limits.push("Maugis-Dugdale keeps Lambda fixed for every effective radius of a polydisperse system (the range h = d_n(R*)/Lambda grows as R*^(1/3)); --per-contact-lambda writes `range h` instead, each contact at its own Lambda".to_string());
    }
    if wall.is_none() {
        limits.push(
            "the neighbor skin must stay at least the interaction range (checked at run)".into(),
        );
    } else {
        limits.push("other walls, and the contacts between the particles: the fragment is the sphere-wall contact only (add pair_style tabor for particle-particle contacts)".into());
    }
    if let Some(h) = dugdale_range {
        reproduces.push(format!(
            "every other size at the same material constant: a contact of effective radius R* gets Lambda = {lambda:.6e} (R*/{r:.6e} m)^(1/3) (the Dugdale range {h:.6e} m is fixed), verified in LAMMPS across the three Maugis-Dugdale cases (integrations/lammps/test_plugin_lambda.py)",
            lambda = lambda.unwrap_or(f64::NAN)
        ));
    }
    if range > 0.0 && wall.is_none() {
        limits.push(format!(
            "bodies created closer than the interaction range ({range:.4e} m beyond touching): they jump in where they start and miss the attraction's work; create grains at least that far apart"
        ));
    }
    if scene.sphere.material != scene.target.material {
        limits.push("the individual moduli: pair_coeff carries the effective modulus E* of the two materials".into());
    }
    Ok(PluginExport {
        scene: scene.name.clone(),
        plugin: plugin.to_string(),
        model,
        effective_modulus: e_star,
        work_of_adhesion: w,
        tabor_parameter: lambda,
        dugdale_range,
        damping_time: a_time,
        effective_radius: r,
        effective_mass: m,
        jump_in_overlap: law.jump_in_overlap(),
        snap_off_overlap: law.snap_off_overlap(),
        interaction_range: range,
        neighbor_skin: skin,
        pull_off_force: law.pull_off_force(),
        sticking_velocity: sticking,
        reference_speed: v_ref,
        contact_time,
        time_step: contact_time * PLUGIN_TIME_STEP_FRACTION,
        restitution,
        wall,
        commands,
        reproduces,
        does_not_reproduce: limits,
        warnings: if std::path::Path::new(plugin).exists() {
            Vec::new()
        } else {
            vec![format!(
                "the plugin {plugin} does not exist (build it with cargo xtask lammps-plugin): plugin load will fail"
            )]
        },
    })
}

impl PluginExport {
    /// The LAMMPS input fragment: comment lines (the law, its numbers, what it
    /// reproduces and its limits, tabor's restitution), then the commands.
    pub fn fragment(&self) -> String {
        let mut s = String::new();
        let mut line = |t: &str| {
            s.push_str(t);
            s.push('\n');
        };
        match &self.wall {
            None => {
                line(&format!(
                    "# tabor export lammps --plugin: scene \"{}\" (sphere-sphere: pair_style tabor, tabor's own force law)",
                    self.scene
                ));
                line(
                    "# Include after atom_style sphere / create_box (units si); newton on or off.",
                );
            }
            Some(w) => {
                line(&format!(
                    "# tabor export lammps --plugin: scene \"{}\" (sphere on a flat: fix wall/tabor {w}, tabor's own force law)",
                    self.scene
                ));
                line("# Include after atom_style sphere / create_box (units si), before the run; the wall acts on group all.");
                line("# The wall is the flat target: R* = the particle's radius, m* = its mass, E* that of particle and wall.");
            }
        }
        for w in &self.warnings {
            line(&format!("# WARNING: {w}"));
        }
        line(&format!(
            "# law: {}; E* = {:.10e} Pa (1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2){}{}{}",
            self.model.keyword(),
            self.effective_modulus,
            self.work_of_adhesion.map_or(String::new(), |w| format!(
                ", w = {w:.10e} J/m^2 (= 2 gamma of LAMMPS's jkr)"
            )),
            match (self.dugdale_range, self.tabor_parameter) {
                (Some(h), Some(l)) => format!(
                    ", range h = {h:.10e} m (held fixed: each contact's Lambda = d_n(R*)/h, d_n = (9 pi w R*^2/(8 E*))^(2/3)/(3 R*); Lambda = {l:.10e} at the scene's R*)"
                ),
                (_, l) => l.map_or(String::new(), |l| format!(", Lambda = {l:.10e}")),
            },
            self.damping_time.map_or(String::new(), |a| format!(
                ", Kuwabara-Kono time A = {a:.10e} s"
            ))
        ));
        line(&format!(
            "# bodies: R* = {:.6e} m, m* = {:.6e} kg; interaction range {:.6e} m (jump-in at overlap {:.6e} m, snap-off at {:.6e} m){}",
            self.effective_radius,
            self.effective_mass,
            self.interaction_range,
            self.jump_in_overlap,
            self.snap_off_overlap,
            if self.wall.is_some() {
                String::new()
            } else {
                format!("; neighbor skin {:.6e} m", self.neighbor_skin)
            }
        ));
        for r in &self.reproduces {
            line(&format!("# REPRODUCES: {r}"));
        }
        if let Some(v) = self.sticking_velocity {
            line(&format!("# sticking velocity (tabor): {v:.6e} m/s"));
        }
        for n in &self.does_not_reproduce {
            line(&format!("# DOES NOT REPRODUCE: {n}"));
        }
        line(&format!(
            "# Hertz contact time at {:.4e} m/s: {:.4e} s; claims verified with timestep {:.4e} s (contact time/20000)",
            self.reference_speed, self.contact_time, self.time_step
        ));
        line("# speed (m/s)   e_tabor (the plugin's restitution in LAMMPS)");
        for p in &self.restitution {
            line(&format!("#   {:.4e}   {:.10}", p.speed, p.restitution));
        }
        for c in &self.commands {
            line(c);
        }
        s
    }
}
