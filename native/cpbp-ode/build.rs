//! Links the static, PIC, double-precision, OU build of ODE made by `tools/build-ode.sh`
//! and generates bindings for the part of its C API the simulation uses.

use std::env;
use std::path::PathBuf;

fn main() {
    for variable in [
        "ODE_PREFIX",
        "COUNTER_STEER_CACHE",
        "XDG_CACHE_HOME",
        "HOME",
    ] {
        println!("cargo:rerun-if-env-changed={variable}");
    }
    println!("cargo:rerun-if-changed=wrapper.h");
    let prefix = env::var("ODE_PREFIX")
        .map(PathBuf::from)
        .unwrap_or_else(|_| cached_build());
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
    // ODE is C++ inside. On Linux its runtime comes from the system's libstdc++; a Windows
    // build links MinGW's in, so the DLL needs nothing beside it that Windows lacks.
    if env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("windows") {
        println!("cargo:rustc-link-lib=static:-bundle=stdc++");
    } else {
        println!("cargo:rustc-link-lib=dylib=stdc++");
    }

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

/// The ODE that tools/build-ode.sh built last for this checkout, through the cache's
/// `ode-current` link, for builds started without the Makefile (which sets ODE_PREFIX).
fn cached_build() -> PathBuf {
    let cache = env::var("COUNTER_STEER_CACHE")
        .map(PathBuf::from)
        .or_else(|_| env::var("XDG_CACHE_HOME").map(|x| PathBuf::from(x).join("counter-steer")))
        .or_else(|_| env::var("HOME").map(|h| PathBuf::from(h).join(".cache/counter-steer")))
        .unwrap_or_default();
    let current = cache.join("ode-current");
    assert!(
        current.join("lib/libode.a").exists(),
        "no ODE build at {} and ODE_PREFIX is not set: run `make build` (or tools/build-ode.sh) \
         once, or set ODE_PREFIX to an ODE 0.16 install built with -DODE_DOUBLE_PRECISION=ON \
         -DODE_WITH_OU=ON and PIC",
        current.display()
    );
    current
}
