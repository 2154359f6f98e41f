//! What was built and linked, and what it runs on: for the title screen, bug reports, the
//! smoke tests and the platform fingerprint every experiment result carries.

/// Versions and configuration of the native module.
#[derive(Clone, Debug)]
pub struct BuildInfo {
    /// Version of the native crates (the workspace version).
    pub version: &'static str,
    /// The compiler that built them (`rustc --version`).
    pub rustc: &'static str,
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
        rustc: env!("CPBP_RUSTC_VERSION"),
        ode: crate::ode::configuration(),
    }
}

/// What a ride's floating-point results depend on beyond the code: the C library whose
/// `libm` the simulation and planner call, and the CPU, because glibc's `libm` picks its
/// FMA variants of `exp`, `log`, `sin`, `cos`, `pow` and `atan2` on CPUs with FMA and AVX2,
/// and those round differently in the last bit (docs/experiment.md, "Reproducibility").
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Platform {
    /// For example "glibc 2.43".
    pub c_library: String,
    /// The CPU's model name, as the kernel reports it.
    pub cpu_model: String,
    /// "fma" where glibc's `libm` takes its FMA paths, "baseline" where it does not.
    pub math_path: &'static str,
}

/// The platform this process runs on.
pub fn platform() -> Platform {
    Platform {
        c_library: crate::ode::c_library_version(),
        cpu_model: cpu_model().unwrap_or_else(|| "unknown CPU".into()),
        math_path: if fma_math() { "fma" } else { "baseline" },
    }
}

fn cpu_model() -> Option<String> {
    let info = std::fs::read_to_string("/proc/cpuinfo").ok()?;
    info.lines()
        .find(|line| line.starts_with("model name"))
        .and_then(|line| line.split_once(':'))
        .map(|(_, name)| name.trim().to_string())
}

fn fma_math() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("fma") && std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn build_is_suitable_for_parallel_rollouts() {
        let info = build_info();
        assert!(!info.version.is_empty());
        assert!(info.rustc.starts_with("rustc "), "{}", info.rustc);
        assert!(
            info.ode_is_suitable(),
            "ODE configuration: {}",
            info.ode.raw
        );
    }

    #[test]
    fn the_platform_names_its_c_library_and_cpu() {
        let platform = platform();
        assert!(platform.c_library.starts_with("glibc "), "{platform:?}");
        assert!(!platform.cpu_model.is_empty());
        assert!(["fma", "baseline"].contains(&platform.math_path));
    }
}
