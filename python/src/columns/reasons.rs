//! The strings stored as a template and numbers (a scene's effect reasons), so
//! that a sweep keeps one template per kind of reason.

/// Whether the strings of column `name` are split into a template and numbers:
/// a scene's effect reasons, which quote the numbers that decided them (a speed,
/// a yield onset), so that a sweep stores one template per kind of reason, not
/// one string per point.
pub(super) fn templated(name: &str) -> bool {
    name.ends_with(".reason")
}

/// `text` with each number in Rust's `{:e}` notation (`1.25e-3`, `-4e0`: a token
/// with an exponent, not inside a word; `tabor::numerics::readable::exponent_numbers`)
/// replaced by `{}` and appended to `numbers`; braces already in the text doubled
/// (so that Python's `str.format` with the numbers gives the text back, the
/// numbers printed Python's way).
pub(super) fn split_numbers(text: &str, numbers: &mut Vec<f64>) -> String {
    let escape = |t: &str| t.replace('{', "{{").replace('}', "}}");
    let mut out = String::with_capacity(text.len());
    let mut copied = 0;
    for (range, value) in tabor::numerics::readable::exponent_numbers(text) {
        out.push_str(&escape(&text[copied..range.start]));
        out.push_str("{}");
        numbers.push(value);
        copied = range.end;
    }
    out.push_str(&escape(&text[copied..]));
    out
}

#[cfg(test)]
mod tests {
    use super::split_numbers;

    #[test]
    fn reasons_split_into_a_template_and_numbers() {
        let mut x = Vec::new();
        let t = split_numbers(
            "impact speed 1.2617695852173827e-1 m/s does not exceed the adhesive yield onset (5.111) 1.9449639560565972e0 m/s: {below}",
            &mut x,
        );
        assert_eq!(
            t,
            "impact speed {} m/s does not exceed the adhesive yield onset (5.111) {} m/s: {{below}}"
        );
        assert_eq!(x, [1.2617695852173827e-1, 1.9449639560565972e0]);
        // no exponent, inside a word, or a bare sign: not a number
        let mut y = Vec::new();
        let t = split_numbers("case 1, (5.44), x2e5, Q = 5, -e3, -5e-2.", &mut y);
        assert_eq!(t, "case 1, (5.44), x2e5, Q = 5, -e3, {}.");
        assert_eq!(y, [-5e-2]);
        assert_eq!(split_numbers("", &mut y), "");
    }
}
