//! tabor's library answer for oblique collisions of two equal spheres
//! (`tabor_tangential::oblique`, continuous time with located stick/slip events):
//! the reference the LAMMPS plugin test (`integrations/lammps/test_plugin_friction.py`)
//! compares `pair_style tabor` with.
//!
//! stdin, one case a line: `R rho E nu w model lambda speed angle spin_z mu k_roll mu_roll
//! [tangential [spin_x]]` (SI units, angle in degrees, model `hertz`, `jkr`
//! (load-controlled) or `maugis`, spin_z the initial spin of the sphere about z, k_roll
//! 0 for no rolling and no twisting resistance, tangential `mindlin` (the default) or
//! `mindlin_deresiewicz`, the exact spring bed; spin_x the initial spin about x, the
//! line of centres at touch: a twist); stdout, one line each: the relative velocity
//! sphere − target after the impact (x, y), the sphere's and the target's spin about z,
//! 1 if they stick, the relative energy error of the integration, the sphere's and the
//! target's spin about x.
#![allow(missing_docs, clippy::unwrap_used, clippy::expect_used)]

use std::io::BufRead;
use tabor_dynamics::{ForceLaw, SimulationSettings};
use tabor_ffi::ContactLaw;
use tabor_jkr::{JkrForceLaw, JkrSphere, SeparationRule};
use tabor_maugis::{MaugisContact, MaugisDugdaleForceLaw, MaugisDugdaleImpact};
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact};
use tabor_tangential::{EffectiveShear, Friction, Rolling, Tangential, TangentialModel, Twisting};

fn main() {
    for line in std::io::stdin().lock().lines() {
        let line = line.unwrap();
        let f: Vec<&str> = line.split_whitespace().collect();
        if f.is_empty() {
            continue;
        }
        let x = |k: usize| f[k].parse::<f64>().expect("number");
        let (r, rho, e, nu, w) = (x(0), x(1), x(2), x(3), x(4));
        let (model, lambda, speed, angle, spin) = (f[5], x(6), x(7), x(8), x(9));
        let (mu, k_roll, mu_roll) = (x(10), x(11), x(12));
        let e_star = e / (2.0 * (1.0 - nu * nu));
        let reff = 0.5 * r;
        // the JKR sphere only for the adhesive models (w > 0)
        let sphere = || JkrSphere::new(e_star, reff, w).unwrap();
        let (mut law, pull_off): (Box<dyn ForceLaw>, f64) = match model {
            "hertz" => (
                Box::new(tabor_elastic::ElasticContact::hertz(e_star, reff).unwrap()),
                0.0,
            ),
            "jkr" => (
                Box::new(JkrForceLaw::new(sphere(), SeparationRule::LoadControlled)),
                1.5 * std::f64::consts::PI * w * reff,
            ),
            "maugis" => {
                let m =
                    MaugisDugdaleImpact::new(MaugisContact::new(sphere(), lambda).unwrap(), 1.0)
                        .unwrap();
                // the plugin's F_pulloff: the most tensile force of the law's branch
                let p = ContactLaw::maugis_dugdale(e_star, reff, w, lambda)
                    .unwrap()
                    .pull_off_force();
                (Box::new(MaugisDugdaleForceLaw::new(&m).unwrap()), -p)
            }
            other => panic!("unknown model {other}"),
        };
        let shear = EffectiveShear::of_pair(e, nu, e, nu).unwrap();
        let tangential: TangentialModel = f.get(13).copied().unwrap_or("mindlin").parse().unwrap();
        let mut friction =
            Friction::sliding(Tangential::new(tangential, 8.0 * shear.modulus(), 0.0, mu).unwrap());
        if k_roll > 0.0 {
            friction = friction
                .with_rolling(Rolling::sds(k_roll, 0.0, mu_roll).unwrap())
                .with_twisting(Twisting::Marshall);
        }
        let body = Body::solid_sphere(r, rho).unwrap();
        let imp = ObliqueImpact {
            sphere: body,
            target: body,
            normal: NormalContact {
                pull_off_force: pull_off,
                damping: 0.0,
                damping_exponent: 1.0,
            },
            friction: Some(friction),
            sphere_spin: [f.get(14).map_or(0.0, |_| x(14)), 0.0, spin],
            target_spin: [0.0; 3],
        };
        let out = imp
            .simulate(
                law.as_mut(),
                speed,
                angle,
                &SimulationSettings::with_tolerance(1e-9).unwrap(),
            )
            .unwrap();
        let (s, t) = (out.after.sphere, out.after.target);
        println!(
            "{:.17e} {:.17e} {:.17e} {:.17e} {} {:.3e} {:.17e} {:.17e}",
            s.velocity[0] - t.velocity[0],
            s.velocity[1] - t.velocity[1],
            s.angular_velocity[2],
            t.angular_velocity[2],
            u8::from(out.sticks),
            out.energy_error,
            s.angular_velocity[0],
            t.angular_velocity[0]
        );
    }
}
