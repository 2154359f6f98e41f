//! What was built and linked, for the title screen, bug reports and the smoke tests.

/// Versions and configuration of the native module.
#[derive(Clone, Debug)]
pub struct BuildInfo {
    /// Version of the native crates (the workspace version).
    pub version: &'static str,
    /// `dGetConfiguration()` of the linked ODE.
    pub ode: crate::ode::Configuration,
}

impl BuildInfo {
    /// Whether ODE was built the way the simulation needs it (double precision, OU).
    pub fn ode_is_suitable(&self) -> bool {
        self.ode.double_precision() && self.ode.thread_local_collision()
    }
}

/// Describes this build.
pub fn build_info() -> BuildInfo {
    BuildInfo {
        version: env!("CARGO_PKG_VERSION"),
        ode: crate::ode::configuration(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn build_is_suitable_for_parallel_rollouts() {
        let info = build_info();
        assert!(!info.version.is_empty());
        assert!(
            info.ode_is_suitable(),
            "ODE configuration: {}",
            info.ode.raw
        );
    }
}
