//! `NativeInfo`: what native module is loaded, for the title screen and smoke tests.

use godot::prelude::*;

/// Describes the loaded native module: its version and the ODE build inside it.
#[derive(GodotClass)]
#[class(init, base=RefCounted)]
pub struct NativeInfo {
    base: Base<RefCounted>,
}

#[godot_api]
impl NativeInfo {
    /// Version of the native module.
    #[func]
    fn version() -> GString {
        GString::from(cpbp_core::build_info().version)
    }

    /// `dGetConfiguration()` of the linked ODE: space-separated feature tokens.
    #[func]
    fn ode_configuration() -> GString {
        GString::from(cpbp_core::build_info().ode.raw.as_str())
    }

    /// What this build is and runs on, for bug reports and the platform fingerprint of
    /// experiment results: `native_version`, `rustc`, `ode_configuration`, `c_library`
    /// (whose `libm` the simulation calls), `cpu_model` and `math_path` ("fma" where
    /// that `libm` takes its FMA paths).
    #[func]
    fn platform() -> Dictionary<GString, GString> {
        let info = cpbp_core::build_info();
        let platform = cpbp_core::platform();
        let mut d = Dictionary::new();
        for (key, value) in [
            ("native_version", info.version),
            ("rustc", info.rustc),
            ("ode_configuration", info.ode.raw.as_str()),
            ("c_library", platform.c_library.as_str()),
            ("cpu_model", platform.cpu_model.as_str()),
            ("math_path", platform.math_path),
        ] {
            d.set(&GString::from(key), &GString::from(value));
        }
        d
    }

    /// True when ODE is double precision with thread-local collision data, as the
    /// parallel rollouts require.
    #[func]
    fn ode_is_suitable() -> bool {
        cpbp_core::build_info().ode_is_suitable()
    }
}
