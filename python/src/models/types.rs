//! The shape of a model's table: its keywords ([`Input`], [`Kind`]), the model
//! ([`Model`]) and, for a model whose record splits into a shared part and each
//! element's own fields, [`Split`].

use crate::failure::Failure;
use tabor::restitution::UnknownChoice;

/// How a keyword is given.
pub enum Kind<A> {
    /// A number (array_like); required when `default` is None.
    Number {
        /// The default value.
        default: Option<f64>,
        /// Stores the element's value.
        set: fn(&mut A, f64),
    },
    /// An optional number (array_like or None).
    Optional {
        /// Stores the element's value.
        set: fn(&mut A, Option<f64>),
    },
    /// A bool (strictly `True`/`False`), default False.
    Flag {
        /// Stores the value.
        set: fn(&mut A, bool),
    },
    /// One of a menu of the model crates (a str: its `as_str` name; underscores
    /// may stand for hyphens); required when `default` is None.
    Choice {
        /// The menu: each choice's name and description (from the crate's `ALL`,
        /// `as_str`, `description`).
        menu: fn() -> Vec<(&'static str, &'static str)>,
        /// The default choice's name.
        default: Option<fn() -> &'static str>,
        /// Parses a name of `menu` (the menu's `FromStr`) and stores it.
        set: fn(&mut A, &str) -> Result<(), UnknownChoice>,
    },
}

/// One keyword of a model function.
pub struct Input<A> {
    /// The keyword (snake_case, the CLI flag without `--`).
    pub name: &'static str,
    /// The help line (with the unit).
    pub help: &'static str,
    /// How it is given.
    pub kind: Kind<A>,
}

/// A model function: its keywords and its computation.
pub struct Model<A: 'static, R> {
    /// The function's name (= the CLI subcommand).
    pub name: &'static str,
    /// The keywords, in the order of the signature.
    pub inputs: &'static [Input<A>],
    /// The inputs before the keywords are applied.
    pub blank: fn() -> A,
    /// Validates and computes one element.
    pub compute: fn(&A) -> Result<R, Failure>,
}

/// The own fields of one element of a [`Split`] model: from the prepared part,
/// the varying input and the previous element's own fields.
pub type OwnFn<P, V> = fn(&P, Option<f64>, Option<&V>) -> Result<Option<V>, Failure>;

/// A model whose record splits into a part that depends on all inputs but
/// `varying` (computed once per distinct set of them: a batch over speeds pays for
/// the model once) and the fields of each element's own.
pub struct Split<A: 'static, P: 'static, R: 'static, V: 'static> {
    /// The keyword of the element's own fields (a number or optional number).
    pub varying: &'static str,
    /// Validates the other inputs and computes the shared part.
    pub prepare: fn(&A) -> Result<P, Failure>,
    /// The shared part's record (the own fields unset).
    pub record: fn(&P) -> &R,
    /// The element's own fields from the varying input (None when it is not
    /// given) and the previous element's own fields when it shares the prepared
    /// part (a warm start).
    pub own: OwnFn<P, V>,
}
