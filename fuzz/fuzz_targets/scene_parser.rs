//! Fuzz target: arbitrary UTF-8 fed to the scene parser in both formats; on a scene
//! that parses and validates, its outcome and sticking velocity are computed
//! (errors ignored). Any panic is a bug.
//!
//! Run (needs a nightly toolchain): `cargo +nightly fuzz run scene_parser` from the
//! workspace root; `cargo check --manifest-path fuzz/Cargo.toml` builds it on stable.
#![no_main]

use libfuzzer_sys::fuzz_target;
use tabor_scene::{Format, Scene};

fuzz_target!(|text: &str| {
    for format in [Format::Toml, Format::Json] {
        if let Ok(scene) = Scene::from_str(text, format) {
            let _ = scene.outcome();
            let _ = scene.sticking_velocity();
        }
    }
});
