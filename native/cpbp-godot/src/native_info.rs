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

    /// True when ODE is double precision with thread-local collision data, as the
    /// parallel rollouts require.
    #[func]
    fn ode_is_suitable() -> bool {
        cpbp_core::build_info().ode_is_suitable()
    }
}
