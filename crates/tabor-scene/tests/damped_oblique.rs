//! `[damping]` in the oblique impact: tabor-tangential's integrator applies a
//! scene's DEM damping `c a^β ḋ` itself (`NormalContact`), against the central
//! damped outcome at normal incidence, the nominal restitution on a flat, and
//! the contact's end where the damped normal force turns tensile.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{silica_scene as scene, SILICA};
use tabor_scene::{Format, Scene};

/// The oblique impact of a damped scene (`[damping]` with adhesion): at a
/// vanishing angle, frictionless, tabor-tangential's integrator (its own ODE, the
/// damping `c a^β ḋ` of `NormalContact`, the work of each mechanism integrated
/// with the motion) reproduces the central damped outcome (tabor-dynamics with the
/// viscous wrapper): the restitution, the damping work and the adhesive
/// hysteresis, to the oblique impact's tolerance (1e-9 relative, as energies of
/// the kinetic energy).
#[test]
fn damped_oblique_impact_at_normal_incidence_is_the_central_one() {
    for (w, model) in [
        (0.05, "coeff_restitution\"\nrestitution = 0.6"),
        (0.05, "viscoelastic\"\ncoefficient = 5e15"),
        (0.0, "tsuji\"\ncoefficient = 0.6"),
    ] {
        let s = scene(&format!(
            "[adhesion]\nwork_of_adhesion = {w}\n[damping]\nmodel = \"{model}\n"
        ));
        let v = 0.5;
        let central = s.outcome_at(v).unwrap();
        let o = s.oblique(v, 1e-6).unwrap();
        let kinetic = 0.5 * s.effective_mass * v * v;
        let tol = 1e-8;
        assert!(
            (o.normal_restitution - central.restitution).abs() < tol,
            "{model}: {} vs {}",
            o.normal_restitution,
            central.restitution
        );
        let share = |name: &str| {
            central
                .effects
                .iter()
                .find(|x| x.name == name)
                .and_then(|x| x.energy_loss)
                .unwrap_or(0.0)
        };
        assert!(
            (o.losses.normal_damping - share("damping")).abs() < tol * kinetic,
            "{model}: {:e} vs {:e}",
            o.losses.normal_damping,
            share("damping")
        );
        assert!(
            (o.losses.normal_adhesion - share("adhesion")).abs() < tol * kinetic,
            "{model}: {:e} vs {:e}",
            o.losses.normal_adhesion,
            share("adhesion")
        );
    }
}

/// Hertz + `coeff_restitution` on a flat with friction at 45°: the normal motion
/// on a flat does not depend on the tangential one, so the normal restitution is
/// e exactly; the mechanisms account for the kinetic energy lost (the oblique
/// impact's energy error, 1e-9 relative), the damping work non-negative.
#[test]
fn damped_oblique_impact_on_a_flat_keeps_e_and_its_energy() {
    let text = format!(
        "{}[damping]\nmodel = \"coeff_restitution\"\nrestitution = 0.7\n[friction]\ncoefficient = 0.3\n",
        SILICA.replace(
            "[target]\nradius = 1e-6\ndensity = 2650\n",
            "[target]\n"
        )
    );
    let s = Scene::from_str(&text, Format::Toml).unwrap();
    for angle in [10.0, 45.0, 80.0] {
        let o = s.oblique(0.5, angle).unwrap();
        assert!(
            (o.normal_restitution - 0.7).abs() < 1e-8,
            "{angle}: {}",
            o.normal_restitution
        );
        assert!(o.losses.normal_damping > 0.0 && o.losses.sliding_friction >= 0.0);
        assert!(o.energy_error < 1e-8, "{angle}: {:e}", o.energy_error);
    }
}

/// A damped Hertz contact with friction (Tsuji damping, tangential damping,
/// `sds` rolling, `marshall` twisting; two silica spheres, 0.3 m/s): the total
/// normal force falls below 0 (the dashpot pulls) before the overlap vanishes,
/// and every Coulomb limit `μ |F_n|` touches 0 there. The contact still ends
/// where the overlap does: Hertz's elastic force returns all it stored (its
/// work over the contact below 1e-9 of the kinetic energy, the oblique
/// impact's tolerance), and a planar impact, whose twisting element carries no
/// torque, is the same with and without it (restitutions, rebound angle and
/// every loss to 1e-9). Until stop 37 both failed from 0.5° to 20°: the point
/// where the limits touch 0 was taken for the separation (3.8 % of the kinetic
/// energy left in the contact as "adhesion"; e_t −0.4329 at 0.5, 1 and 3°
/// alike; LAMMPS agrees with the fixed values, `integrations/lammps/test_oblique.py`).
#[test]
fn damped_oblique_contact_ends_where_the_overlap_vanishes() {
    let friction = "[friction]\ncoefficient = 0.3\ntangential_damping = 0.5\n\
                    rolling = { stiffness = 50.0, damping = 0.0, coefficient = 0.1 }\n";
    let damping = "[damping]\nmodel = \"tsuji\"\ncoefficient = 0.5\n";
    let with = scene(&format!("{friction}twisting = \"marshall\"\n{damping}"));
    let without = scene(&format!("{friction}{damping}"));
    let v = 0.3;
    let kinetic = 0.5 * with.effective_mass * v * v;
    for angle in [0.5, 1.0, 3.0, 5.0, 10.0, 20.0, 40.0, 60.0, 85.0] {
        let a = with.oblique(v, angle).unwrap();
        let b = without.oblique(v, angle).unwrap();
        assert!(
            a.losses.normal_adhesion.abs() < 1e-9 * kinetic,
            "{angle}°: Hertz's elastic work {:e} J of {kinetic:e} J",
            a.losses.normal_adhesion
        );
        let close = |x: f64, y: f64, what: &str| {
            assert!(
                (x - y).abs() <= 1e-9 * x.abs().max(y.abs()).max(1.0),
                "{angle}° {what}: with twisting {x:e}, without {y:e}"
            );
        };
        close(a.normal_restitution, b.normal_restitution, "e_n");
        close(
            a.tangential_restitution.unwrap_or(0.0),
            b.tangential_restitution.unwrap_or(0.0),
            "e_t",
        );
        close(
            a.rebound_angle.unwrap_or(0.0),
            b.rebound_angle.unwrap_or(0.0),
            "rebound angle",
        );
        for (name, x, y) in [
            ("damping", a.losses.normal_damping, b.losses.normal_damping),
            (
                "sliding",
                a.losses.sliding_friction,
                b.losses.sliding_friction,
            ),
            (
                "t-damping",
                a.losses.tangential_damping,
                b.losses.tangential_damping,
            ),
            (
                "spring",
                a.losses.tangential_spring,
                b.losses.tangential_spring,
            ),
        ] {
            assert!(
                (x - y).abs() <= 1e-9 * kinetic,
                "{angle}° {name}: with twisting {x:e}, without {y:e}"
            );
        }
    }
}

/// Found in stop 42, mended in stop 43: a strongly overdamped adhesive contact
/// with friction (viscoelastic η_n0 = 1e19 1/(m s), about 100 times critical
/// for this pair) creeps into its equilibrium without a turning point; the
/// oblique driver, which applies the damping itself, had no capture criterion
/// and ran into DOP853's step limit (10⁶ steps, ~14 s). It now sticks where its
/// escape energy runs out (`tabor_tangential::oblique`, "Capture"), at 0° and
/// 10°, the ledger closed.
#[test]
fn an_overdamped_adhesive_contact_with_friction_sticks() {
    let s = scene(
        "[adhesion]\nwork_of_adhesion = 0.05\nseparation = \"load-controlled\"\n\
         [damping]\nmodel = \"viscoelastic\"\ncoefficient = 1e19\n\
         [friction]\ncoefficient = 0.3\ntangential = \"linear_history\"\n\
         tangential_stiffness = 2.0e3\n",
    );
    for angle in [0.0, 10.0] {
        let o = s.oblique(0.3, angle).unwrap();
        assert!(o.sticks, "{angle}");
        assert!(o.energy_error < 1e-8, "{angle}: {}", o.energy_error);
    }
}
