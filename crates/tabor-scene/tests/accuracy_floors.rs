//! The accuracy floors of `tabor_numerics::tolerance` reach the outcome: a scene
//! whose `accuracy` is finer than a path computes gets a warning with the code
//! `accuracy-floor` naming the floor (issue 32 item 5); at the floor, none.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use tabor_scene::{Format, Scene};

/// The bundled scene `file` with the top-level `accuracy` set to `accuracy`.
fn bundled_at(file: &str, accuracy: &str) -> Scene {
    let path = format!(
        "{}/../../examples/scenes/{file}",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(path).unwrap();
    let text: String = text
        .lines()
        .filter(|l| !l.starts_with("accuracy"))
        .map(|l| {
            if l.starts_with("name =") {
                format!("{l}\naccuracy = {accuracy}\n")
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    Scene::from_str(&text, Format::Toml).unwrap()
}

/// The messages of the outcome's `accuracy-floor` warnings.
fn floors(scene: &Scene) -> Vec<String> {
    scene
        .outcome()
        .unwrap()
        .warnings
        .into_iter()
        .filter(|w| w.code == "accuracy-floor")
        .map(|w| w.message)
        .collect()
}

#[test]
fn a_viscoelastic_model_finer_than_its_floor_is_named() {
    assert!(floors(&bundled_at("rubber_viscoelastic.toml", "1e-12")).is_empty());
    let named = floors(&bundled_at("rubber_viscoelastic.toml", "1e-13"));
    assert_eq!(named.len(), 1, "{named:?}");
    assert!(
        named[0].contains("MODEL_ACCURACY_FLOOR") && named[0].contains("1e-12"),
        "{named:?}"
    );
}

#[test]
fn a_sticking_search_finer_than_its_floor_is_named() {
    assert!(floors(&bundled_at("silica.toml", "1e-14")).is_empty());
    let named = floors(&bundled_at("silica.toml", "1e-15"));
    assert_eq!(named.len(), 1, "{named:?}");
    assert!(
        named[0].contains("STICKING_ACCURACY_FLOOR") && named[0].contains("1e-14"),
        "{named:?}"
    );
}
