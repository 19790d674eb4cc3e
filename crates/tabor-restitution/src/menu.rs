//! Choice menus: the enums a user picks from by name (the separation rule, the
//! plastic, viscoelastic and penalty models, the combination rules). Each lives
//! once, in its model crate, and gets from [`menu!`](crate::menu!) the same small
//! surface: `ALL` (every choice, in the order of the help texts), `as_str` (the
//! kebab-case name every front end uses: the command line's `--model thornton`, the
//! scene file's `model = "thornton"`, Python's `model="thornton"`), `description`
//! (one line with the equations), [`FromStr`](std::str::FromStr) and
//! [`Display`](std::fmt::Display). The fronts parse with `FromStr` and never spell
//! a name themselves.

use std::fmt;

/// A choice menu (implemented by [`menu!`](crate::menu!)).
pub trait Menu: Copy + Eq + fmt::Debug + Send + Sync + 'static {
    /// What is being chosen, for messages ("separation rule").
    const MENU: &'static str;
    /// Every choice, in the order of the help texts.
    const ALL: &'static [Self];
    /// The choice's name (kebab-case).
    fn as_str(self) -> &'static str;
    /// One line on the choice, with its equations.
    fn description(self) -> &'static str;

    /// The choice named `name`, or the error that lists the names.
    fn parse_choice(name: &str) -> Result<Self, UnknownChoice> {
        Self::ALL
            .iter()
            .copied()
            .find(|c| c.as_str() == name)
            .ok_or_else(|| UnknownChoice {
                menu: Self::MENU,
                value: name.to_string(),
                expected: Self::ALL.iter().map(|c| c.as_str()).collect(),
            })
    }
}

/// A name that is not on a menu.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown {menu} \"{value}\": expected {}", self.expected_list())]
pub struct UnknownChoice {
    /// What was being chosen ("separation rule").
    pub menu: &'static str,
    /// The name given.
    pub value: String,
    /// The names on the menu.
    pub expected: Vec<&'static str>,
}

impl UnknownChoice {
    /// The names on the menu, quoted: `"a", "b" or "c"`.
    pub fn expected_list(&self) -> String {
        let quoted: Vec<String> = self.expected.iter().map(|n| format!("\"{n}\"")).collect();
        match quoted.split_last() {
            Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
            Some((last, _)) => last.clone(),
            None => String::from("nothing"),
        }
    }
}

/// Gives a fieldless enum its menu: inherent `ALL`, `as_str`, `description`, the
/// [`Menu`] trait, `FromStr` (error [`UnknownChoice`]) and `Display` (the name).
///
/// ```
/// #[derive(Clone, Copy, Debug, PartialEq, Eq)]
/// enum Rule {
///     /// First.
///     A,
///     /// Second.
///     B,
/// }
/// tabor_restitution::menu! {
///     Rule, "rule";
///     A => "a", "the first rule";
///     B => "b", "the second rule";
/// }
/// assert_eq!(Rule::ALL, [Rule::A, Rule::B]);
/// assert_eq!("b".parse::<Rule>(), Ok(Rule::B));
/// assert_eq!(Rule::A.to_string(), "a");
/// assert_eq!(
///     "c".parse::<Rule>().unwrap_err().to_string(),
///     "unknown rule \"c\": expected \"a\" or \"b\""
/// );
/// ```
#[macro_export]
macro_rules! menu {
    (@unit $variant:ident) => { () };
    ($ty:ident, $menu:literal; $($variant:ident => $name:literal, $description:literal;)+) => {
        impl $ty {
            /// Every choice, in the order of the help texts.
            pub const ALL: [$ty; <[()]>::len(&[$($crate::menu!(@unit $variant)),+])] =
                [$($ty::$variant),+];

            /// The choice's name (kebab-case), as every front end spells it.
            pub fn as_str(self) -> &'static str {
                match self {
                    $($ty::$variant => $name,)+
                }
            }

            /// One line on the choice, with its equations.
            pub fn description(self) -> &'static str {
                match self {
                    $($ty::$variant => $description,)+
                }
            }
        }

        impl $crate::menu::Menu for $ty {
            const MENU: &'static str = $menu;
            const ALL: &'static [$ty] = &$ty::ALL;
            fn as_str(self) -> &'static str {
                $ty::as_str(self)
            }
            fn description(self) -> &'static str {
                $ty::description(self)
            }
        }

        impl ::std::str::FromStr for $ty {
            type Err = $crate::menu::UnknownChoice;
            fn from_str(name: &str) -> ::std::result::Result<Self, Self::Err> {
                <$ty as $crate::menu::Menu>::parse_choice(name)
            }
        }

        impl ::std::fmt::Display for $ty {
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.pad(self.as_str())
            }
        }
    };
}

#[cfg(test)]
mod tests {
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    enum Count {
        One,
        Two,
        Three,
    }
    crate::menu! {
        Count, "count";
        One => "one", "1";
        Two => "two", "2";
        Three => "three", "3";
    }

    #[test]
    fn names_round_trip_and_unknown_names_are_listed() {
        for c in Count::ALL {
            assert_eq!(c.as_str().parse::<Count>(), Ok(c));
            assert_eq!(c.to_string(), c.as_str());
        }
        let e = "four".parse::<Count>().unwrap_err();
        assert_eq!(
            e.to_string(),
            "unknown count \"four\": expected \"one\", \"two\" or \"three\""
        );
        assert_eq!(e.expected, vec!["one", "two", "three"]);
        assert_eq!(format!("{:>5}", Count::One), "  one");
        assert_eq!(Count::Two.description(), "2");
    }
}
