//! Generates the C header of the ABI with cbindgen into `$OUT_DIR/tabor_ffi.h`;
//! the committed copy is `include/tabor_ffi.h` (the test `header_is_current`
//! fails when the two differ; `TABOR_FFI_WRITE_HEADER=1 cargo build -p tabor-ffi`
//! refreshes the committed copy).
use std::path::PathBuf;

fn main() {
    println!("cargo:rerun-if-changed=src/lib.rs");
    println!("cargo:rerun-if-changed=src/law.rs");
    println!("cargo:rerun-if-changed=src/contact.rs");
    println!("cargo:rerun-if-changed=cbindgen.toml");
    println!("cargo:rerun-if-env-changed=TABOR_FFI_WRITE_HEADER");
    let crate_dir = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default());
    let out = PathBuf::from(std::env::var("OUT_DIR").unwrap_or_default()).join("tabor_ffi.h");
    let config = match cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")) {
        Ok(c) => c,
        Err(e) => {
            println!("cargo:warning=cbindgen.toml: {e}");
            return;
        }
    };
    match cbindgen::Builder::new()
        .with_crate(&crate_dir)
        .with_config(config)
        .generate()
    {
        Ok(bindings) => {
            bindings.write_to_file(&out);
            if std::env::var_os("TABOR_FFI_WRITE_HEADER").is_some() {
                bindings.write_to_file(crate_dir.join("include/tabor_ffi.h"));
            }
        }
        Err(e) => println!("cargo:warning=cbindgen could not generate the header: {e}"),
    }
}
