//! Numbers for people: the human-readable form of the command line's reports and
//! of the library's messages (warnings, reasons), rounded to the digits that mean
//! something, with SI prefixes ([`human`], and [`humanize`] for the numbers in a
//! library message); and the shortest round-trip form ([`plain`]) that error
//! messages use to echo a value as given. The library's messages quote exact
//! numbers in `{:e}` notation ([`exponent_numbers`] finds them); JSON and CSV
//! outputs keep every digit.

use std::ops::Range;

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
/// the plain decimal (`-1`, `0.6`, `300`, `2650`, `0.001`) unless the exponent
/// form is shorter by two characters or more (`1e9`, `5.4e10`, `1e-4`, `1e300`).
/// Error messages echo values so, and the CSV outputs write them so.
pub fn plain(value: f64) -> String {
    if !value.is_finite() {
        return format!("{value}");
    }
    let decimal = format!("{value}");
    let exponent = format!("{value:e}");
    if decimal.len() <= exponent.len() + 1 {
        decimal
    } else {
        exponent
    }
}

/// The numbers written in Rust's `{:e}` notation in `text` (`1.25e-3`, `-4e0`: a
/// token with an exponent, not inside a word), each as its byte range and value.
/// The library's messages quote exact numbers so; [`humanize`] rounds them for
/// people and the Python package stores them apart from their template.
pub fn exponent_numbers(text: &str) -> Vec<(Range<usize>, f64)> {
    let bytes = text.as_bytes();
    let word = |b: u8| b.is_ascii_alphanumeric() || b == b'_' || b == b'.';
    let digits_from = |mut j: usize| {
        while j < bytes.len() && bytes[j].is_ascii_digit() {
            j += 1;
        }
        j
    };
    let mut found = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts = (bytes[i].is_ascii_digit()
            || (bytes[i] == b'-' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit)))
            && (i == 0 || !word(bytes[i - 1]));
        if !starts {
            i += 1;
            continue;
        }
        let mut j = digits_from(i + 1);
        if j + 1 < bytes.len() && bytes[j] == b'.' && bytes[j + 1].is_ascii_digit() {
            j = digits_from(j + 1);
        }
        if j < bytes.len() && bytes[j] == b'e' {
            let sign = usize::from(bytes.get(j + 1) == Some(&b'-'));
            let k = digits_from(j + 1 + sign);
            let ends = k == bytes.len() || !bytes[k].is_ascii_alphanumeric();
            if k > j + 1 + sign && ends {
                if let Ok(x) = text[i..k].parse::<f64>() {
                    found.push((i..k, x));
                    i = k;
                    continue;
                }
            }
        }
        i = j;
    }
    found
}

/// `text` (a library message: a warning, an effect's reason) with every number
/// in `{:e}` notation shown by [`human`] with `digits` digits, the unit that
/// follows it (` m/s`, ` J`, …) taking the SI prefix: `1.2617695852173827e-1 m/s`
/// becomes `0.126177 m/s`, `2.08e-17 J` becomes `20.8 aJ`.
pub fn humanize(text: &str, digits: usize) -> String {
    let mut out = String::with_capacity(text.len());
    let mut copied = 0;
    for (range, value) in exponent_numbers(text) {
        out.push_str(&text[copied..range.start]);
        let rest = &text[range.end..];
        let unit = rest.strip_prefix(' ').and_then(|r| {
            PREFIXED_UNITS
                .iter()
                .filter(|u| {
                    r.strip_prefix(**u)
                        .is_some_and(|after| !after.starts_with(|c: char| c.is_alphanumeric()))
                })
                .max_by_key(|u| u.len())
        });
        match unit {
            Some(unit) => {
                out.push_str(&human(value, unit, digits));
                copied = range.end + 1 + unit.len();
            }
            None => {
                out.push_str(&human(value, "", digits));
                copied = range.end;
            }
        }
    }
    out.push_str(&text[copied..]);
    out
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
    fn messages_are_humanized_number_by_number() {
        assert_eq!(
            humanize(
                "impact speed 1.2617695852173827e-1 m/s does not exceed 1.9449639560565972e0 m/s (5.111)",
                6
            ),
            "impact speed 0.126177 m/s does not exceed 1.94496 m/s (5.111)"
        );
        assert_eq!(
            humanize("loss 2.0810900231214864e-17 J, ratio -6.468e-3", 6),
            "loss 20.8109 aJ, ratio -0.006468"
        );
        // a unit that is a prefix of a word is not a unit; a number inside a word is not a number
        assert_eq!(
            humanize("d = 1e-9 mm and x1e5 at 3e5 Pa s", 3),
            "d = 1e-9 mm and x1e5 at 300 kPa s"
        );
        assert_eq!(humanize("no numbers (5.36)", 6), "no numbers (5.36)");
        let found = exponent_numbers("a -4e0 b 1.25e-3}");
        assert_eq!(found, vec![(2..6, -4.0), (9..16, 1.25e-3)]);
    }

    #[test]
    fn plain_numbers_round_trip_as_people_write_them() {
        assert_eq!(plain(-1.0), "-1");
        assert_eq!(plain(0.6), "0.6");
        assert_eq!(plain(1e300), "1e300");
        assert_eq!(plain(-3e-7), "-3e-7");
        assert_eq!(plain(300.0), "300");
        assert_eq!(plain(2650.0), "2650");
        assert_eq!(plain(0.001), "0.001");
        assert_eq!(plain(1e-4), "1e-4");
        assert_eq!(plain(-1e9), "-1e9");
        assert_eq!(plain(54e9), "5.4e10");
        assert_eq!(plain(0.0), "0");
        for x in [
            0.1,
            1.0 / 3.0,
            6.02214076e23,
            5e-324,
            -2.2250738585072014e-308,
        ] {
            assert_eq!(plain(x).parse::<f64>().ok(), Some(x));
        }
    }
}
