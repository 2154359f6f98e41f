//! Links the static, PIC, double-precision, OU build of ODE made by `tools/build-ode.sh`
//! and generates bindings for the part of its C API the simulation uses.

use std::env;
use std::path::PathBuf;

fn main() {
    println!("cargo:rerun-if-env-changed=ODE_PREFIX");
    println!("cargo:rerun-if-changed=wrapper.h");
    let prefix = PathBuf::from(env::var("ODE_PREFIX").unwrap_or_else(|_| {
        panic!(
            "ODE_PREFIX is not set. Build through the Makefile (`make build`), which builds ODE \
             with tools/build-ode.sh and exports ODE_PREFIX, or set it to an ODE 0.16 install \
             built with -DODE_DOUBLE_PRECISION=ON -DODE_WITH_OU=ON and PIC."
        )
    }));
    let lib_dir = prefix.join("lib");
    let include_dir = prefix.join("include");
    assert!(
        lib_dir.join("libode.a").exists(),
        "no libode.a in {}: run tools/build-ode.sh",
        lib_dir.display()
    );

    println!(
        "cargo:rerun-if-changed={}",
        lib_dir.join("libode.a").display()
    );
    println!("cargo:rustc-link-search=native={}", lib_dir.display());
    println!("cargo:rustc-link-lib=static=ode");
    // ODE is C++ inside; its runtime comes from the system's libstdc++.
    println!("cargo:rustc-link-lib=dylib=stdc++");

    let bindings = bindgen::Builder::default()
        .header("wrapper.h")
        .clang_arg(format!("-I{}", include_dir.display()))
        .clang_arg("-DdDOUBLE")
        .allowlist_function("d.*")
        .allowlist_type("d.*")
        .allowlist_var("d.*")
        .prepend_enum_name(false)
        .derive_default(true)
        .layout_tests(false)
        .generate()
        .expect("bindgen could not read ODE's headers");
    let out = PathBuf::from(env::var("OUT_DIR").unwrap()).join("ode_bindings.rs");
    bindings
        .write_to_file(out)
        .expect("could not write ODE bindings");
}
