//! The 2-D rates and event values of a planar state ([`super::plane`]) against
//! the 3-D ones of the full state ([`Setup::evaluate`], [`Setup::event_values`])
//! at random planar states, for every tangential model and every mode.

#![allow(clippy::unwrap_used)]

use super::bodies::{Body, NormalContact, ObliqueImpact};
use super::planar::{PLANAR, PM, P_EN};
use super::state::*;
use crate::{EffectiveShear, Friction, Rolling, Tangential, TangentialModel, Twisting};
use nalgebra::Vector3;
use std::cell::Cell;
use tabor_dynamics::ForceLaw;
use tabor_jkr::{JkrForceLaw, JkrSphere, SeparationRule};

/// A uniform number in [−1, 1) (xorshift64*: reproducible, no dependency).
fn uniform(seed: &mut u64) -> f64 {
    *seed ^= *seed >> 12;
    *seed ^= *seed << 25;
    *seed ^= *seed >> 27;
    let bits = seed.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
    2.0 * (bits as f64 / (1u64 << 53) as f64) - 1.0
}

/// The impact of two silica spheres (or a sphere on a flat) with the tangential
/// `model`, `sds` rolling, the twisting given, with or without damping, with
/// or without adhesion in the friction's rules (without: the Coulomb limits
/// `μ |F_n|` of a contact whose normal force may fall below 0).
fn impact(
    flat: bool,
    model: TangentialModel,
    twisting: Twisting,
    (damped, adhesive): (bool, bool),
) -> ObliqueImpact {
    let (e, nu, w, r) = (54e9, 0.17, 0.05, 1e-6);
    let sphere = Body::solid_sphere(r, 2650.0).unwrap();
    let reff = if flat { r } else { 0.5 * r };
    let shear = EffectiveShear::of_pair(e, nu, e, nu).unwrap();
    let (ratio, damping, rolling_damping) = if damped {
        (0.7, 2e-4, 1e-9)
    } else {
        (0.0, 0.0, 0.0)
    };
    let stiffness = match model {
        TangentialModel::LinearHistory => 8.0 * shear.modulus() * 1e-7,
        _ => 8.0 * shear.modulus(),
    };
    let friction = Friction::sliding(Tangential::new(model, stiffness, ratio, 0.3).unwrap())
        .with_rolling(Rolling::sds(50.0, rolling_damping, 0.1).unwrap())
        .with_twisting(twisting);
    ObliqueImpact {
        sphere,
        target: if flat { Body::flat() } else { sphere },
        normal: NormalContact {
            pull_off_force: if adhesive {
                1.5 * std::f64::consts::PI * w * reff
            } else {
                0.0
            },
            damping,
            damping_exponent: 0.5,
        },
        friction: Some(friction),
        sphere_spin: [0.0; 3],
        target_spin: [0.0; 3],
    }
}

/// The law of [`impact`]'s bodies (JKR, load-controlled), begun at 0.3 m/s and
/// 40°, with the setup of the simulation (as `ObliqueImpact::run` builds it).
fn setup(imp: &ObliqueImpact, flat: bool) -> (JkrForceLaw, Setup<'_>) {
    let (e, nu, w) = (54e9, 0.17, 0.05);
    let r_i = imp.sphere.radius;
    let (r_sum, r_eff) = if flat {
        (r_i, r_i)
    } else {
        (2.0 * r_i, 0.5 * r_i)
    };
    let mut law = JkrForceLaw::new(
        JkrSphere::new(e / (2.0 * (1.0 - nu * nu)), r_eff, w).unwrap(),
        SeparationRule::LoadControlled,
    );
    let (v, alpha) = (0.3, 40f64.to_radians());
    let v_n = v * alpha.cos();
    let (m_i, m_j) = (imp.sphere.mass, imp.target.mass);
    let m_eff = if flat { m_i } else { m_i * m_j / (m_i + m_j) };
    law.begin_impact(m_eff, v_n).unwrap();
    let length = law.overlap_scale(m_eff, v_n).unwrap();
    let mut scale = [1.0; N];
    for k in 0..3 {
        scale[E + k] = length;
        scale[U + k] = v;
        scale[WI + k] = v / r_i;
        scale[WJ + k] = v / r_i;
        scale[XT + k] = length;
        scale[XR + k] = length;
    }
    scale[XW] = length / r_i;
    for k in 0..8 {
        scale[EN + k] = m_eff * v * v;
    }
    let s = Setup {
        imp,
        flat,
        r_sum,
        r_eff,
        m_eff,
        m_i,
        m_j,
        inv_i_i: 1.0 / imp.sphere.moment_of_inertia,
        inv_i_j: if flat {
            0.0
        } else {
            1.0 / imp.target.moment_of_inertia
        },
        u0: Vector3::new(v_n, v * alpha.sin(), 0.0),
        d_touch: -Vector3::x() * r_sum,
        v,
        v_n,
        scale,
        time: length / v_n,
        length,
        force: m_eff * v_n * v_n / length,
        bed: imp.micro_slip_bed(&law, r_eff, length, v_n, None),
        normal_cache: Cell::new(None),
        step_hint: Cell::new(None),
    };
    (law, s)
}

/// A random planar SI state at a random time of the contact (overlap between
/// 0.05 and 0.95 of the overlap scale on the undisturbed path): deviations and
/// displacements up to 10⁻² of the overlap scale, velocities within 30 % of
/// the impact speed, spins up to the impact speed over the radius, energies.
fn random_state(s: &Setup, seed: &mut u64) -> (f64, [f64; N]) {
    let t = (0.5 + 0.45 * uniform(seed)) * s.time;
    let mut y = [0.0; N];
    for k in 0..2 {
        y[E + k] = 1e-2 * s.length * uniform(seed);
        y[U + k] = s.u0[k] + 0.3 * s.v * uniform(seed);
        y[XT + k] = 1e-2 * s.length * uniform(seed);
        y[XR + k] = 1e-2 * s.length * uniform(seed);
    }
    y[WI + 2] = s.v / s.imp.sphere.radius * uniform(seed);
    if !s.flat {
        y[WJ + 2] = s.v / s.imp.sphere.radius * uniform(seed);
    }
    for k in 0..8 {
        y[EN + k] = s.scale[EN] * uniform(seed);
    }
    (t, y)
}

/// Every mode of a planar state: free flight, warmup, loading or unloading,
/// tangential and rolling stick or slip, none, some or all elements frozen, the
/// normal force of a damped contact without adhesion above or below 0.
fn planar_modes() -> Vec<Modes> {
    let mut all = Vec::new();
    let base = Modes {
        in_contact: true,
        frozen: [false; 3],
        thaw: [f64::INFINITY; 3],
        warmup: false,
        loading: true,
        tangential: Mode::Stick,
        rolling: Mode::Stick,
        twisting: Mode::Stick,
        twist_sign: 1.0,
        tensile: false,
        doomed: false,
    };
    all.push(Modes {
        in_contact: false,
        ..base
    });
    all.push(Modes {
        doomed: true,
        ..base
    });
    all.push(Modes {
        warmup: true,
        ..base
    });
    for loading in [true, false] {
        for tangential in [Mode::Stick, Mode::Slip] {
            for rolling in [Mode::Stick, Mode::Slip] {
                for frozen in [
                    [false; 3],
                    [true, false, false],
                    [false, true, true],
                    [true; 3],
                ] {
                    for tensile in [false, true] {
                        all.push(Modes {
                            loading,
                            tangential,
                            rolling,
                            frozen,
                            tensile,
                            ..base
                        });
                    }
                }
            }
        }
    }
    all
}

/// `a` and `b` agree to 4 ulps of the larger (the 2-D forms do the 3-D
/// operations without their exact zeros, in the same order: equal up to the
/// sign of a zero, so any difference is a defect; 4 ulps leaves room for a
/// reordering of one sum, not for a different term).
fn agree(a: f64, b: f64, what: &str) {
    assert!(
        a == b || (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs()),
        "{what}: 2-D {a:e}, 3-D {b:e}"
    );
}

/// At 40 random planar states of each scene (pair or flat; every tangential
/// model; twisting `marshall` or `sds`; with and without damping) and in every
/// planar mode, the 2-D rates, slip rates and event values equal the 3-D ones,
/// the 3-D rates of every out-of-plane component are exactly 0 (the premise
/// of the reduced state), and so are those of the energies a segment leaves out
/// ([`Setup::active_energies`]).
#[test]
fn planar_rates_match_the_full_ones() {
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let models = [
        TangentialModel::LinearHistory,
        TangentialModel::Mindlin,
        TangentialModel::MindlinRescale,
        TangentialModel::MindlinDeresiewicz,
    ];
    let twistings = [
        Twisting::Marshall,
        Twisting::sds(1e-9, 1e-15, 0.05).unwrap(),
    ];
    let mut compared = 0usize;
    for flat in [false, true] {
        for model in models {
            for twisting in twistings {
                for contact in [(false, true), (true, true), (true, false)] {
                    let imp = impact(flat, model, twisting, contact);
                    let (law, s) = setup(&imp, flat);
                    for _ in 0..40 {
                        let (t, y) = random_state(&s, &mut seed);
                        if let Some(bed) = &s.bed {
                            let (n, overlap, rate, _) = s.geometry(t, &y);
                            let a = law.contact_radius(overlap, rate).unwrap();
                            let mut onset = v3(&y, XT);
                            onset[1] += 3e-3 * s.length * uniform(&mut seed);
                            bed.borrow_mut().reset(&onset, &n, 0.8 * a);
                        }
                        let z: [f64; PM] = Setup::planar_of(&y);
                        for modes in planar_modes() {
                            compare(&s, &law, t, &y, &z, &modes);
                            compared += 1;
                        }
                    }
                }
            }
        }
    }
    assert!(compared > 10_000, "{compared} comparisons");
}

/// One comparison of [`planar_rates_match_the_full_ones`]. The law's root is
/// warm-started from its last solve (the force at one overlap differs by ~10⁻¹⁴
/// with the history of the calls), so each side starts from a copy of the law
/// in one state, with the normal point forgotten.
fn compare(s: &Setup, law: &JkrForceLaw, t: f64, y: &[f64; N], z: &[f64; PM], modes: &Modes) {
    let fresh = || {
        s.forget_normal();
        law.clone()
    };
    let full = s.evaluate(&fresh(), t, y, modes).unwrap();
    let plane = s.planar_evaluate(&fresh(), t, z, modes).unwrap();
    for (k, &i) in PLANAR.iter().enumerate() {
        agree(plane.dz[k], full.dy[i], &format!("rate {i} in {modes:?}"));
    }
    for i in (0..N).filter(|i| !PLANAR.contains(i)) {
        assert_eq!(full.dy[i], 0.0, "out-of-plane rate {i} in {modes:?}");
    }
    assert_eq!(full.dy[EN + 6], 0.0, "twisting power in {modes:?}");
    // the energies a planar segment leaves out do not move
    for (k, active) in s.active_energies(modes).iter().enumerate() {
        if !active {
            assert_eq!(plane.dz[P_EN + k], 0.0, "energy {k} in {modes:?}");
        }
    }
    agree(plane.slip_rate_t, full.slip_rate_t, "tangential slip rate");
    agree(plane.slip_rate_r, full.slip_rate_r, "rolling slip rate");
    let g_full = s.full_event_values(&fresh(), t, y, modes).unwrap();
    let g_plane = s.planar_event_values(&fresh(), t, z, modes).unwrap();
    for (k, (a, b)) in g_plane.iter().zip(g_full.iter()).enumerate() {
        agree(*a, *b, &format!("event value {k} in {modes:?}"));
    }
}
