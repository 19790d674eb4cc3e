//! Numbers for people: the human-readable form of the command line's reports and
//! of the library's messages (warnings, reasons), rounded to the digits that mean
//! something, with SI prefixes ([`human`], [`Readable`]); and the shortest
//! round-trip form ([`plain`]) that error messages use to echo a value as given.
//! JSON and CSV outputs keep every digit and do not use this module.

use std::fmt;

/// The significant digits of human-readable output: as many as the scene's
/// `accuracy` (relative) makes meaningful, `⌈−log10 accuracy⌉`, between 3 and
/// [`READABLE_DIGITS`]. The JSON and CSV outputs keep every digit.
pub fn meaningful_digits(accuracy: f64) -> usize {
    if !(accuracy.is_finite() && accuracy > 0.0) {
        return READABLE_DIGITS;
    }
    // a digit count from a finite positive accuracy: at most ~324
    let digits = (-accuracy.log10()).ceil().max(0.0) as usize;
    digits.clamp(3, READABLE_DIGITS)
}

/// The most significant digits human-readable output prints (a person reads
/// `1.49214 m/s`, not `1.4921419222696275e0 m/s`).
pub const READABLE_DIGITS: usize = 6;

/// The SI prefixes from 10⁻²⁴ to 10²⁴, by exponent / 3 + 8.
const SI_PREFIXES: [&str; 17] = [
    "y", "z", "a", "f", "p", "n", "µ", "m", "", "k", "M", "G", "T", "P", "E", "Z", "Y",
];

/// The units that take an SI prefix in human-readable output.
const PREFIXED_UNITS: [&str; 7] = ["m/s", "J", "N", "m", "s", "Pa", "rad/s"];

/// `text` without trailing zeros after a decimal point (and without the point).
fn trim_zeros(text: &str) -> &str {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        text
    }
}

/// `value` in `unit` for people, rounded to `digits` significant digits: a plain
/// decimal for magnitudes in [10⁻³, 10⁴) (`0.1 m/s`, `1.49214 m/s`; to 10⁶ for a
/// bare number), else an SI
/// prefix for a unit that takes one (`20.8109 aJ`, `86.5981 mm/s`) and the
/// exponent form otherwise (`2.5e-5`, `1e-30 J` beyond the prefixes); `0` for
/// zero. `unit` may be empty.
pub fn human(value: f64, unit: &str, digits: usize) -> String {
    let digits = digits.max(1);
    let with_unit = |number: &str, prefix: &str| {
        if unit.is_empty() {
            number.to_owned()
        } else {
            format!("{number} {prefix}{unit}")
        }
    };
    if !value.is_finite() || value == 0.0 {
        return with_unit(&format!("{value}"), "");
    }
    // rounded once, in exponent form: its exponent decides the layout
    let rounded = format!("{value:.*e}", digits - 1);
    let (mantissa, exponent) = rounded.split_once('e').unwrap_or((&rounded, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let r: f64 = rounded.parse().unwrap_or(value);
    let decimals = |e: i32| usize::try_from(digits as i32 - 1 - e).unwrap_or(0);
    // a unit with a prefix goes to it from 10⁴ on (`54 GPa`); a bare number
    // stays plain to 10⁶ (`-21453.2`)
    let prefixed = PREFIXED_UNITS.contains(&unit);
    if (-3..if prefixed { 4 } else { 6 }).contains(&exponent) {
        return with_unit(trim_zeros(&format!("{r:.*}", decimals(exponent))), "");
    }
    if prefixed && (-24..27).contains(&exponent) {
        let power = exponent.div_euclid(3) * 3;
        let scaled = r / 10f64.powi(power);
        let text = format!("{scaled:.*}", decimals(exponent - power));
        let prefix = SI_PREFIXES[(power / 3 + 8) as usize];
        return with_unit(trim_zeros(&text), prefix);
    }
    with_unit(&format!("{}e{exponent}", trim_zeros(mantissa)), "")
}

/// The shortest form that reads back as the same `f64`, as a person writes it:
/// a plain decimal for magnitudes in [10⁻⁵, 10¹⁶) (`-1`, `0.6`, `300`), the
/// exponent form otherwise (`1e300`, `2.5e-7`). Error messages echo values so.
pub fn plain(value: f64) -> String {
    let magnitude = value.abs();
    if magnitude == 0.0 || (1e-5..1e16).contains(&magnitude) || !value.is_finite() {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}

/// A value and its unit shown by [`human`] with [`READABLE_DIGITS`] digits in
/// `{}`: `format!("{}", Readable(2.08e-17, "J"))` is `20.8 aJ`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Readable(pub f64, pub &'static str);

impl fmt::Display for Readable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&human(self.0, self.1, READABLE_DIGITS))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn human_numbers_are_rounded_and_prefixed() {
        // the cases of issue 33 and the boundaries of each layout
        assert_eq!(human(0.1, "m/s", 6), "0.1 m/s");
        assert_eq!(human(1.4921419222696275, "m/s", 6), "1.49214 m/s");
        assert_eq!(human(0.0, "J", 6), "0 J");
        assert_eq!(human(2.0810900231214864e-17, "J", 6), "20.8109 aJ");
        assert_eq!(human(8.659806493097254e-2, "m/s", 6), "0.0865981 m/s");
        assert_eq!(human(8.659806493097254e-4, "m/s", 6), "865.981 µm/s");
        assert_eq!(human(-21453.236888244377, "rad/s", 6), "-21.4532 krad/s");
        assert_eq!(human(0.5000775090134594, "", 6), "0.500078");
        assert_eq!(human(-21453.236888244377, "", 6), "-21453.2");
        assert_eq!(human(2.1e6, "", 6), "2.1e6");
        assert_eq!(human(2.5e-5, "", 6), "2.5e-5");
        assert_eq!(human(9999.996, "m/s", 6), "10 km/s");
        assert_eq!(human(9.99996, "", 5), "10");
        assert_eq!(human(1e-30, "J", 3), "1e-30 J");
        assert_eq!(human(f64::NAN, "J", 6), "NaN J");
        assert_eq!(human(54e9, "Pa", 6), "54 GPa");
        assert_eq!(meaningful_digits(1e-10), 6);
        assert_eq!(meaningful_digits(1e-4), 4);
        assert_eq!(meaningful_digits(0.5), 3);
    }

    #[test]
    fn plain_numbers_round_trip_as_people_write_them() {
        assert_eq!(plain(-1.0), "-1");
        assert_eq!(plain(0.6), "0.6");
        assert_eq!(plain(1e300), "1e300");
        assert_eq!(plain(-3e-7), "-3e-7");
        for x in [
            0.1,
            1.0 / 3.0,
            6.02214076e23,
            5e-324,
            -2.2250738585072014e-308,
        ] {
            assert_eq!(plain(x).parse::<f64>().ok(), Some(x));
        }
        assert_eq!(
            format!("{}", Readable(2.0810900231214864e-17, "J")),
            "20.8109 aJ"
        );
    }
}
