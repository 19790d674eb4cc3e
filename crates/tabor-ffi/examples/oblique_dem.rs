//! The same oblique collision of two equal spheres that
//! `integrations/lammps/collide.py::collide_oblique` runs in LAMMPS, integrated
//! here step by step with the contact model of the C ABI (`ContactModel::step`,
//! the very code `pair_style tabor` calls) and LAMMPS's `nve/sphere` scheme
//! (half kick, drift, forces at the half-step velocities, half kick; a setup
//! force call that does not advance the friction history): the same-form
//! reference of `test_plugin_friction.py` for `tangential mindlin_deresiewicz`,
//! which checks that the plugin carries the micro-slip bed's history (springs,
//! basis, spacing, storage) as `tabor_tangential::Friction::step` defines it.
//!
//! stdin, one case a line: `R rho E nu w model lambda speed angle mu dt steps reach`
//! (SI units, model `hertz`, `jkr` (load-controlled) or `maugis`, `steps` the whole
//! run from the start `collide_oblique` uses: `approach + run_steps`); stdout, one
//! line each: the relative velocity sphere − target (x, y), both spins about z, 1
//! if separated (beyond the radii plus `reach` and receding).
#![allow(missing_docs, clippy::unwrap_used, clippy::expect_used)]

use nalgebra::Vector3;
use std::io::BufRead;
use tabor_ffi::*;

fn main() {
    for line in std::io::stdin().lock().lines() {
        let line = line.unwrap();
        let f: Vec<&str> = line.split_whitespace().collect();
        if f.is_empty() {
            continue;
        }
        let x = |k: usize| f[k].parse::<f64>().expect("number");
        let (r, rho, e, nu, w, model, lambda) = (x(0), x(1), x(2), x(3), x(4), f[5], x(6));
        let (speed, angle, mu, dt) = (x(7), x(8).to_radians(), x(9), x(10));
        let (steps, reach) = (x(11) as usize, x(12));
        let e_star = e / (2.0 * (1.0 - nu * nu));
        let params = TaborLawParams {
            model: match model {
                "hertz" => TABOR_MODEL_HERTZ,
                "jkr" => TABOR_MODEL_JKR_LOAD_CONTROLLED,
                "maugis" => TABOR_MODEL_MAUGIS_DUGDALE,
                other => panic!("unknown model {other}"),
            },
            effective_modulus: e_star,
            effective_radius: 1.0,
            work_of_adhesion: w,
            tabor_parameter: lambda,
            damping_time: 0.0,
            damping_model: TABOR_DAMPING_KUWABARA_KONO,
            damping_value: 0.0,
            dugdale_range: 0.0,
            cohesive_stress: 0.0,
        };
        // the plugin's `tangential mindlin_deresiewicz NULL 0 mu`: k_t = 8 G*,
        // G* = E* (1 − ν)/(2 (2 − ν))
        let friction = TaborFrictionParams {
            tangential_model: TABOR_TANGENTIAL_MINDLIN_DERESIEWICZ,
            tangential_stiffness: 8.0 * e_star * (1.0 - nu) / (2.0 * (2.0 - nu)),
            friction_coefficient: mu,
            ..TaborFrictionParams::default()
        };
        let contact = ContactModel::new(
            law_from_params(&params).unwrap(),
            friction_from_params(&friction).unwrap(),
        );
        let m = rho * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3);
        let inertia = 0.4 * m * r * r;
        // collide_oblique's start: the undisturbed paths touch after `approach`
        // steps; here the whole run is given, the start from the same formula
        let approach = 20.0 + (reach / angle.cos().max(0.05) / (speed * dt)).ceil();
        let s = approach * speed * dt;
        let u = Vector3::new(speed * angle.cos(), speed * angle.sin(), 0.0);
        let mut xs = [
            Vector3::new(-2.0 * r - s * angle.cos(), -s * angle.sin(), 0.0),
            Vector3::zeros(),
        ];
        let mut vs = [u * 0.5, -u * 0.5];
        let mut ws = [Vector3::zeros(); 2];
        let mut h = TaborContactHistory::default();
        let forces = |xs: &[Vector3<f64>; 2],
                      vs: &[Vector3<f64>; 2],
                      ws: &[Vector3<f64>; 2],
                      h: &mut TaborContactHistory,
                      update: i32| {
            let d = xs[0] - xs[1];
            let dist = d.norm();
            if h.contact == 0.0 && dist >= 2.0 * r + reach {
                return (Vector3::zeros(), Vector3::zeros(), Vector3::zeros());
            }
            let state = TaborContactState {
                normal: (d / dist).into(),
                overlap: 2.0 * r - dist,
                radius_i: r,
                radius_j: r,
                relative_velocity: (vs[0] - vs[1]).into(),
                angular_velocity_i: ws[0].into(),
                angular_velocity_j: ws[1].into(),
                time_step: dt,
                update_history: update,
                effective_mass: 0.5 * m,
            };
            let out = contact.step(&state, h).unwrap();
            (
                Vector3::from(out.force),
                Vector3::from(out.torque_i),
                Vector3::from(out.torque_j),
            )
        };
        let (mut force, mut ti, mut tj) = forces(&xs, &vs, &ws, &mut h, 0);
        for _ in 0..steps {
            vs[0] += force * (0.5 * dt / m);
            vs[1] -= force * (0.5 * dt / m);
            ws[0] += ti * (0.5 * dt / inertia);
            ws[1] += tj * (0.5 * dt / inertia);
            xs[0] += vs[0] * dt;
            xs[1] += vs[1] * dt;
            (force, ti, tj) = forces(&xs, &vs, &ws, &mut h, 1);
            vs[0] += force * (0.5 * dt / m);
            vs[1] -= force * (0.5 * dt / m);
            ws[0] += ti * (0.5 * dt / inertia);
            ws[1] += tj * (0.5 * dt / inertia);
        }
        let d = xs[1] - xs[0];
        let receding = d.dot(&(vs[1] - vs[0])) > 0.0;
        let separated = d.norm() > 2.0 * r + reach && receding;
        let rel = vs[0] - vs[1];
        println!(
            "{:.17e} {:.17e} {:.17e} {:.17e} {}",
            rel[0],
            rel[1],
            ws[0][2],
            ws[1][2],
            u8::from(separated)
        );
    }
}
