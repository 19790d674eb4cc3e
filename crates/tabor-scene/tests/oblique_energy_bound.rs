//! The energy bound of a passive contact, as a property: with tangential,
//! rolling and twisting elements of constant stiffness (`linear_history`,
//! micro-slip, `sds`), a normal law that loses its hysteresis over a cycle from
//! separation to separation (Hertz, JKR by either rule, Maugis-Dugdale, plastic)
//! and any DEM damping, the bodies' kinetic energy after a rebound, computed
//! here from the masses, the moments of inertia and the reported motion, is at
//! most their energy before, computed here from the inputs. Slack: the work of
//! the torque-arm convention (torques use `R − δ/2`; booked as `torque_arm`,
//! either sign, of order δ/R of the tangential work) and 1e-8 of the energy.
//! Each dissipative mechanism (normal and tangential damping, sliding,
//! micro-slip) books a work ≥ −1e-9 of the energy the contact moves (micro-slip
//! less the spring bed's resolution too). Every case must run: plasticity with adhesion is the one combination without
//! an oblique force law (a loss-level rule), refused by name; sticking is an
//! answer, checked for finite values only. (Measured over 300 cases: 215
//! rebounds within the bound, 72 sticking, 13 plastic-adhesive refusals.)

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use proptest::prelude::*;
use tabor_numerics::tolerance::MICRO_SLIP_RESOLUTION;
use tabor_scene::{Format, Scene};

/// (density, Young's modulus, Poisson's ratio): silica, alumina, steel.
const MATERIALS: [(f64, f64, f64); 3] = [
    (2650.0, 54e9, 0.17),
    (3900.0, 380e9, 0.23),
    (7850.0, 210e9, 0.3),
];

/// One random scene and impact.
#[derive(Clone, Debug)]
struct Case {
    radius: f64,
    sphere: usize,
    target: usize,
    /// 0: the same radius, 1: three times larger, 2: a flat
    target_kind: usize,
    /// 0 Hertz, 1 JKR load-controlled, 2 JKR fixed grip, 3 Maugis-Dugdale, 4 plastic
    normal: usize,
    work_of_adhesion: f64,
    range: f64,
    yield_stress: f64,
    plastic_adhesion: bool,
    /// 0 none, 1 tsuji, 2 coeff_restitution, 3 viscoelastic
    damping: usize,
    damping_value: f64,
    micro_slip: bool,
    mu: f64,
    stiffness: f64,
    tangential_damping: f64,
    rolling: Option<(f64, f64)>,
    twisting: Option<(f64, f64)>,
    speed: f64,
    angle: f64,
    spin: [f64; 3],
    target_spin: [f64; 3],
}

fn case() -> impl Strategy<Value = Case> {
    (
        (
            -6.5f64..-4.0,
            0usize..3,
            0usize..3,
            0usize..3,
            0usize..5,
            -2.0f64..-0.5,
            prop_oneof![Just(0.3e-9), Just(1e-9), Just(3e-9)],
            8.5f64..9.5,
            any::<bool>(),
        ),
        (
            0usize..4,
            0.0f64..1.0,
            any::<bool>(),
            0.05f64..0.8,
            2.0f64..5.0,
            prop_oneof![Just(0.0), 0.0f64..0.8],
            proptest::option::of((0.0f64..3.0, 0.02f64..0.3)),
            proptest::option::of((-9.0f64..-6.0, 0.02f64..0.3)),
        ),
        (
            -2.5f64..0.5,
            0.5f64..85.0,
            prop_oneof![
                (-2.0f64..2.0).prop_map(|z| [0.0, 0.0, z]),
                (-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0).prop_map(|(x, y, z)| [x, y, z]),
            ],
            (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y, z)| [x, y, z]),
        ),
    )
        .prop_map(|(a, b, c)| {
            let speed = 10f64.powf(c.0);
            let radius = 10f64.powf(a.0);
            let unit = speed / radius;
            Case {
                radius,
                sphere: a.1,
                target: a.2,
                target_kind: a.3,
                normal: a.4,
                work_of_adhesion: 10f64.powf(a.5),
                range: a.6,
                yield_stress: 10f64.powf(a.7),
                plastic_adhesion: a.8,
                damping: b.0,
                damping_value: b.1,
                micro_slip: b.2,
                mu: b.3,
                stiffness: 10f64.powf(b.4),
                tangential_damping: b.5,
                rolling: b.6.map(|(k, m)| (10f64.powf(k), m)),
                twisting: b.7.map(|(k, m)| (10f64.powf(k), m)),
                speed,
                angle: c.1,
                spin: c.2.map(|w| w * unit),
                target_spin: c.3.map(|w| w * unit),
            }
        })
}

fn body(material: usize, radius: Option<f64>, yield_stress: Option<f64>) -> String {
    let (rho, e, nu) = MATERIALS[material];
    let mut s = String::new();
    if let Some(r) = radius {
        s += &format!("radius = {r:e}\ndensity = {rho}\n");
    }
    if let Some(y) = yield_stress {
        s += &format!("yield_stress = {y:e}\n");
    }
    s + &format!("youngs_modulus = {e:e}\npoisson_ratio = {nu}\n")
}

impl Case {
    fn target_radius(&self) -> Option<f64> {
        match self.target_kind {
            0 => Some(self.radius),
            1 => Some(3.0 * self.radius),
            _ => None,
        }
    }

    fn plastic_adhesive(&self) -> bool {
        self.normal == 4 && self.plastic_adhesion
    }

    fn scene(&self) -> String {
        let plastic = (self.normal == 4).then_some(self.yield_stress);
        let mut s = format!(
            "name = \"energy bound\"\n[sphere]\n{}[target]\n{}",
            body(self.sphere, Some(self.radius), plastic),
            body(self.target, self.target_radius(), plastic)
        );
        let w = self.work_of_adhesion;
        match self.normal {
            1 => {
                s += &format!(
                    "[adhesion]\nwork_of_adhesion = {w}\nseparation = \"load-controlled\"\n"
                )
            }
            2 => s += &format!("[adhesion]\nwork_of_adhesion = {w}\n"),
            3 => {
                s += &format!(
                    "[adhesion]\nwork_of_adhesion = {w}\nrange = {:e}\n",
                    self.range
                )
            }
            4 if self.plastic_adhesion => s += &format!("[adhesion]\nwork_of_adhesion = {w}\n"),
            _ => {}
        }
        if self.normal != 4 {
            let v = self.damping_value;
            match self.damping {
                1 => {
                    s += &format!(
                        "[damping]\nmodel = \"tsuji\"\ncoefficient = {}\n",
                        0.1 + 0.8 * v
                    )
                }
                2 => {
                    s += &format!(
                        "[damping]\nmodel = \"coeff_restitution\"\nrestitution = {}\n",
                        0.3 + 0.65 * v
                    )
                }
                3 => {
                    s += &format!(
                        "[damping]\nmodel = \"viscoelastic\"\ncoefficient = {:e}\n",
                        10f64.powf(-4.0 + 3.0 * v)
                    )
                }
                _ => {}
            }
        }
        s += &format!("[friction]\ncoefficient = {}\n", self.mu);
        if self.micro_slip {
            s += "tangential = \"mindlin_deresiewicz\"\n";
        } else {
            s += &format!(
                "tangential = \"linear_history\"\ntangential_stiffness = {:e}\n",
                self.stiffness
            );
        }
        s += &format!("tangential_damping = {}\n", self.tangential_damping);
        if let Some((k, m)) = self.rolling {
            s += &format!("rolling = {{ stiffness = {k:e}, damping = 0.0, coefficient = {m} }}\n");
        }
        if let Some((k, m)) = self.twisting {
            s += &format!("twisting = {{ stiffness = {k:e}, damping = 0.0, coefficient = {m} }}\n");
        }
        let target_spin = match self.target_kind {
            2 => [0.0; 3],
            _ => self.target_spin,
        };
        s + &format!(
            "[impact]\nsphere_spin = {:?}\ntarget_spin = {:?}\n",
            self.spin, target_spin
        )
    }
}

/// Ok(None) for the refused combination, Ok(Some(margin)) the energy bound's
/// margin (≥ 0 where it holds) in units of the energy before.
fn run(c: &Case) -> Result<Option<f64>, String> {
    let text = c.scene();
    let scene = Scene::from_str(&text, Format::Toml).map_err(|e| format!("{e}\n{text}"))?;
    let o = match scene.oblique(c.speed, c.angle) {
        Ok(o) => o,
        Err(e) if c.plastic_adhesive() && e.to_string().contains("loss-level combination") => {
            return Ok(None)
        }
        Err(e) => return Err(format!("{e}\n{text}")),
    };
    let (mi, ii) = common::solid_sphere(c.radius, MATERIALS[c.sphere].0);
    let target = c
        .target_radius()
        .map(|r| common::solid_sphere(r, MATERIALS[c.target].0));
    let m_eff = target.map_or(mi, |(mj, _)| mi * mj / (mi + mj));
    let before = common::kinetic_energy(m_eff, ii, &[c.speed, 0.0, 0.0], &c.spin)
        + target.map_or(0.0, |(_, ij)| {
            common::kinetic_energy(0.0, ij, &[0.0; 3], &c.target_spin)
        });
    let (s, t) = (&o.after.sphere, &o.after.target);
    let after = common::kinetic_energy(mi, ii, &s.velocity, &s.angular_velocity)
        + target.map_or(0.0, |(mj, ij)| {
            common::kinetic_energy(mj, ij, &t.velocity, &t.angular_velocity)
        });
    if !(after.is_finite() && o.energy_error.is_finite()) {
        return Err(format!("not finite: {o:?}\n{text}"));
    }
    // what must dissipate does (the springs' remainder and the torque arm
    // excepted: a damped element's stick reset strains its spring, see
    // `oblique_stick_reset`), to 1e-9 of the energy the contact moves (the
    // kinetic energy before, or the attraction's work where it is larger: a slow
    // Maugis-Dugdale impact reaches contact with 10⁴ times its kinetic energy,
    // and its energies then leave the step control, `Setup::segment`). The
    // micro-slip work, the work done on the spring bed less its store, also to
    // the bed's resolution (`MICRO_SLIP_RESOLUTION` of the work done on it):
    // the bed's state follows each step's chord, its work the stages along the
    // motion (the path error of `tabor-tangential`'s README), which shows where
    // a contact captured mid-way ends with the bed loaded and little slipped
    // (8e-8 of the bed's work, 1e-9 of the energy moved, on a flat)
    let l = &o.losses;
    let moved = before.max(l.normal_adhesion.abs());
    let bed_work = (l.micro_slip + l.tangential_spring).abs();
    for (name, w, resolved) in [
        ("normal_damping", l.normal_damping, 0.0),
        ("sliding_friction", l.sliding_friction, 0.0),
        ("micro_slip", l.micro_slip, MICRO_SLIP_RESOLUTION * bed_work),
        ("tangential_damping", l.tangential_damping, 0.0),
    ] {
        let resolved = resolved + 1e-9 * moved;
        if w < -resolved {
            return Err(format!("{name} = {w:e} J of {before:e} J: {l:?}\n{text}"));
        }
    }
    if o.sticks {
        return Ok(Some(0.0));
    }
    let slack = (-o.losses.torque_arm).max(0.0) + 1e-8 * before;
    Ok(Some((before + slack - after) / before))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]
    #[test]
    fn a_passive_contact_gives_the_bodies_no_energy(c in case()) {
        match run(&c) {
            Ok(Some(margin)) => prop_assert!(
                margin >= 0.0,
                "kinetic energy after exceeds the energy before by {:e} of it\n{}",
                -margin,
                c.scene()
            ),
            Ok(None) => {}
            Err(e) => prop_assert!(false, "the simulation failed: {e}"),
        }
    }
}

/// The case the property found (steel on a larger alumina sphere, JKR
/// load-controlled with Tsuji damping, `linear_history` with a tangential
/// dashpot, a spin out of the plane): the element slips where the dashpot alone
/// reaches the limit, whose kink its energies outside the error control did not
/// resolve. At accuracy 1e-10 the sliding work was −2e-5 of the kinetic energy
/// and the tangential damping 2e-5 above its converged value; both now agree
/// with accuracy 1e-13 to 1e-9 of the kinetic energy.
#[test]
fn a_dashpot_slip_books_converged_energies() {
    let text = |accuracy: f64| {
        format!(
            "name = \"energy bound\"\naccuracy = {accuracy:e}\n\
             [sphere]\nradius = 6.783748509870126e-5\ndensity = 7850\nyoungs_modulus = 2.1e11\npoisson_ratio = 0.3\n\
             [target]\nradius = 2.0351245529610378e-4\ndensity = 3900\nyoungs_modulus = 3.8e11\npoisson_ratio = 0.23\n\
             [adhesion]\nwork_of_adhesion = 0.31622776601683794\nseparation = \"load-controlled\"\n\
             [damping]\nmodel = \"tsuji\"\ncoefficient = 0.6494502209512978\n\
             [friction]\ncoefficient = 0.7133326600473423\ntangential = \"linear_history\"\n\
             tangential_stiffness = 5.7618766619647984e4\ntangential_damping = 0.5970960119859051\n\
             rolling = {{ stiffness = 1e0, damping = 0.0, coefficient = 0.02 }}\n\
             [impact]\nsphere_spin = [0.0, -86.91931604934572, -1356.3191816172048]\n\
             target_spin = [0.0, 896.2324959837622, 0.0]\n"
        )
    };
    let at = |accuracy: f64| {
        Scene::from_str(&text(accuracy), Format::Toml)
            .unwrap()
            .oblique(0.08888268944313857, 18.995907948134185)
            .unwrap()
    };
    let (coarse, fine) = (at(1e-10), at(1e-13));
    let ke = fine.kinetic_energy;
    assert!(
        coarse.losses.sliding_friction >= -1e-9 * ke,
        "sliding work {:e} of {ke:e} J",
        coarse.losses.sliding_friction
    );
    for (name, a, b) in [
        (
            "sliding",
            coarse.losses.sliding_friction,
            fine.losses.sliding_friction,
        ),
        (
            "tangential damping",
            coarse.losses.tangential_damping,
            fine.losses.tangential_damping,
        ),
    ] {
        assert!(
            (a - b).abs() <= 1e-9 * ke,
            "{name}: {a:e} at 1e-10, {b:e} at 1e-13 (kinetic energy {ke:e} J)"
        );
    }
}

/// Found by the property test in two CI runs (stops 41 and 42): Maugis-Dugdale
/// on a flat with Tsuji damping, `linear_history` with a tangential dashpot, a
/// spin. The element slipped into the junction, where the contact radius opens
/// as (δ − δ_j)^½ and the Coulomb limit grows at an unbounded rate: the slip
/// rate jumped to −5e21 of its unit at the branch change, and the element
/// slipped on against it (its event value, negative from the segment's start,
/// was taken for one at its zero by rounding). The ledger closed, but booked
/// −26 and −4 times the kinetic energy as sliding work, offset by the
/// dampings. Now a slipping element whose slip rate is ≤ 0 after an event
/// sticks (`stick_reversed_slips`); both cases fail without it.
#[test]
fn maugis_dugdale_slip_ends_at_the_junction() {
    let first = Case {
        radius: 6.892547006425856e-7,
        sphere: 2,
        target: 1,
        target_kind: 2,
        normal: 3,
        work_of_adhesion: 0.1392959710651863,
        range: 3e-9,
        yield_stress: 316227766.01683795,
        plastic_adhesion: false,
        damping: 1,
        damping_value: 0.0,
        micro_slip: false,
        mu: 0.33303925144233665,
        stiffness: 2353.6776136826347,
        tangential_damping: 0.3611432903956592,
        rolling: None,
        twisting: None,
        speed: 0.08951906968117604,
        angle: 14.610560391171735,
        spin: [0.0, 0.0, -148267.24184857856],
        target_spin: [0.0, 0.0, 0.0],
    };
    let second = Case {
        radius: 4.95056869249825e-7,
        sphere: 0,
        target: 0,
        work_of_adhesion: 0.20269660620212593,
        range: 1e-9,
        mu: 0.1496584411994491,
        stiffness: 1706.634560783857,
        tangential_damping: 0.18196469921407596,
        speed: 0.3709029553997809,
        angle: 26.104550019569356,
        spin: [0.0, -706800.8675691099, 0.0],
        ..first.clone()
    };
    for c in [first, second] {
        let r = run(&c);
        assert!(matches!(r, Ok(Some(m)) if m >= 0.0), "{r:?}");
    }
}
