//! The wall of a flat-target export to `fix wall/tabor`: the wallstyles and the
//! check of a `--wall` value.

use crate::report::ExportError;

/// The wallstyles of `fix wall/tabor` and how many arguments each takes.
const WALLSTYLES: [(&str, usize); 4] = [
    ("xplane", 2),
    ("yplane", 2),
    ("zplane", 2),
    ("zcylinder", 1),
];

/// Checks a `--wall` value: a wallstyle of `fix wall/tabor` with its arguments
/// (numbers, or NULL for a plane's missing side); returns it with single spaces.
pub(crate) fn wall_style(wall: &str) -> Result<String, ExportError> {
    let words: Vec<&str> = wall.split_whitespace().collect();
    let bad = |why: String| ExportError::Model(format!("--wall {wall:?}: {why}"));
    let Some((style, rest)) = words.split_first() else {
        return Err(bad(
            "empty: give a wallstyle and its arguments, e.g. zplane 0.0 NULL".into(),
        ));
    };
    let Some(&(_, n)) = WALLSTYLES.iter().find(|(w, _)| w == style) else {
        return Err(bad(format!(
            "unknown wallstyle {style} (xplane|yplane|zplane lo hi, zcylinder radius)"
        )));
    };
    if rest.len() != n {
        return Err(bad(format!(
            "{style} takes {n} argument(s), got {}",
            rest.len()
        )));
    }
    for a in rest {
        let null_ok = n == 2 && *a == "NULL";
        if !null_ok && a.parse::<f64>().map_or(true, |x| !x.is_finite()) {
            return Err(bad(format!(
                "{a} is not a number{}",
                if n == 2 { " or NULL" } else { "" }
            )));
        }
    }
    if n == 2 && rest.iter().all(|a| *a == "NULL") {
        return Err(bad("lo and hi cannot both be NULL".into()));
    }
    Ok(words.join(" "))
}
