//! The constants of the oblique integration's regularizations and of the inputs it
//! accepts (one home: the driver, the state and the friction elements read them).

/// The largest rate (per time unit of the impact) of the relaxations that diverge
/// where a contact without adhesion vanishes: the turning of a slip direction
/// (`elements::turn_rate`) and `mindlin_rescale`'s shrinking of ξ.
pub(super) const RATE_CAP: f64 = 1e4;

/// The step of the central differences of the normal law, relative to the
/// distance to its branch end (`Setup::difference_step`).
pub(super) const DIFFERENCE_STEP: f64 = 1e-5;

/// The overlap (in units of the overlap scale) up to which a contact that starts
/// without a Coulomb limit runs without friction (`ObliqueImpact::simulate`).
pub(super) const WARMUP: f64 = 1e-6;

/// The contact radius, in units of the Hertz radius `√(R* d)` at the overlap
/// scale `d`, up to which a branch end is where the contact has no area
/// (Maugis-Dugdale's junction with its no-contact part: 0 up to the rounding
/// of the law's solve, 9·10⁻¹⁶ m = 5·10⁻⁸ of the unit seen for a 0.7 µm sphere;
/// `Setup::release_without_area`).
pub(super) const NO_AREA: f64 = 1e-6;

/// The largest surface speed of an initial spin, in units of the impact speed.
pub(super) const MAX_SURFACE_SPEED_RATIO: f64 = 1e6;

/// The largest force of a friction spring at the overlap scale, in units of the
/// normal force scale.
pub(super) const MAX_SPRING_RATIO: f64 = 1e12;

/// The event values (in their units, O(1)) within which of 0 an event function
/// counts as at its zero: a few ulps of their terms, where the location to 4 ε
/// in time ends anyway (`Setup::segment`).
pub(super) const EVENT_ZERO: f64 = 1e-15;

/// The slack of the micro-slip beds' frame, in units of the last step's change
/// (path length of `s` plus the bound on the change of the limits): springs with
/// more slack than this many steps' change are kept in the frame (both beds).
pub(super) const FRAME_STEPS: f64 = 16.0;

/// The straight pieces of the return map along an accepted step of the planar
/// micro-slip bed where its state depends on the step's path
/// (`Setup::commit_bed_along`): the error of the values where springs froze or
/// entered stuck falls as the square of a piece's length. Four pieces take the
/// silica impact's tangential restitution at accuracy 1e-10 from 1.0e-5 / 1.4e-5
/// (10° / 40°) of its converged value to 3.8e-7 / 2.5e-7, at the same steps.
pub(super) const PATH_CHORDS: usize = 4;

/// How long (in time units L/v) an element that chatters stays frozen the first
/// time (`ObliqueImpact::simulate`; twice as long at each further freeze): the
/// chattering at a tangency of a trial force and its limit passes within a
/// fraction of the contact (the transient of a Maugis-Dugdale jump-in with
/// tangential damping), and a freeze that outlasts it holds the element in a
/// mode the motion has left.
pub(super) const FROZEN_FIRST: f64 = 1e-3;

/// The number of event functions of a segment (`Setup::event_values`).
pub(super) const EVENTS: usize = 11;

/// The index of the zero of a damped contact's normal force among them.
pub(super) const NORMAL_FORCE_ZERO: usize = 9;

/// The index of a damped contact's capture among them (`Setup::capture_value`).
pub(super) const CAPTURE: usize = 10;

/// The normal kinetic energy, in units of its value before the impact, below
/// which a damped contact that started without the energy to separate has come
/// to rest (`Setup::capture_value`): it ends there (ḋ = 10⁻³ v cos α), just
/// before its first turning point, or in an overdamped creep.
pub(super) const DOOMED_REST: f64 = 1e-6;

/// The event values (relative, as [`IDENTIFIED_EVENT_VALUE`]) at which the normal force's zero is
/// taken as the event that ended a segment, before an element whose limit
/// touches 0 with it: the margin by which a segment starts above a zero
/// (`Setup::segment`).
pub(super) const ZERO_EVENT_VALUE: f64 = 1e-12;

/// The largest event value at the end of a segment, relative to its size at the
/// segment's start (at least 1 of its unit), that identifies the segment's
/// event. The located zero is within a few ulps of time of the crossing: that
/// leaves a value of ~10⁻¹⁵, up to ~10⁻⁹ where the values change fast in their
/// units (a grazing impact, the units scaled by v cos α: 1.6e-9 at 89.995°).
/// Where every value is still above 0 at the located point, the value that
/// reaches 0 within 256 ulps of time beyond it is the event, however large it
/// is at the point (a steep crossing, `Setup::crossing_ahead`: 0.016 at
/// 89.999999°, refused until stop 38; a slip rate as Maugis-Dugdale's contact
/// radius vanishes). A segment whose values neither are near 0 nor reach it
/// just beyond (one jumped across it: 0.05 and more where a damped contact's
/// limits touched 0 before stop 37) ends in an error, not a guess.
pub(super) const IDENTIFIED_EVENT_VALUE: f64 = 1e-6;
