//! Library-wide initialisation and per-thread data.

use std::cell::Cell;
use std::ffi::CStr;
use std::sync::Once;

use crate::ffi;

static INIT: Once = Once::new();

thread_local! {
    static THREAD_READY: Cell<bool> = const { Cell::new(false) };
}

/// Initialises ODE once per process and allocates this thread's ODE data
/// (collision caches live in thread-local storage in an OU build).
///
/// Every entry point that touches ODE calls this first, so users never have to.
pub fn ensure_thread_data() {
    INIT.call_once(|| {
        // SAFETY: dInitODE2 is called exactly once, before any other ODE call.
        unsafe { ffi::dInitODE2(0) };
    });
    THREAD_READY.with(|ready| {
        if !ready.get() {
            // SAFETY: ODE is initialised above; allocating data for the calling thread is
            // what the OU build requires before that thread collides or steps.
            let ok = unsafe { ffi::dAllocateODEDataForThread(ffi::dAllocateMaskAll as u32) };
            assert!(ok != 0, "ODE could not allocate its per-thread data");
            ready.set(true);
        }
    });
}

/// What the linked ODE library was built with.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Configuration {
    /// The space-separated feature tokens reported by `dGetConfiguration()`.
    pub raw: String,
}

impl Configuration {
    /// Whether a token such as `ODE_EXT_ou` appears in the configuration.
    pub fn has(&self, token: &str) -> bool {
        self.raw.split_whitespace().any(|t| t == token)
    }

    /// Double precision is required: the planner compares many near-identical rollouts.
    pub fn double_precision(&self) -> bool {
        self.has("ODE_double_precision")
    }

    /// Thread-local collision data is required for collision from several threads at once.
    ///
    /// ODE 0.16 has no `ODE_EXT_ou` token: a build with OU's thread-local storage
    /// (`-DODE_WITH_OU=ON`, which defines `dTLS_ENABLED`) reports `ODE_EXT_mt_collisions`.
    pub fn thread_local_collision(&self) -> bool {
        self.has("ODE_EXT_mt_collisions")
    }
}

/// Returns the configuration string of the linked ODE library.
pub fn configuration() -> Configuration {
    ensure_thread_data();
    // SAFETY: dGetConfiguration returns a pointer to a static NUL-terminated string.
    let raw = unsafe { CStr::from_ptr(ffi::dGetConfiguration()) };
    Configuration {
        raw: raw.to_string_lossy().into_owned(),
    }
}

/// Version of the C library this process runs with (its `libm` computes `exp`, `sin` and
/// friends, so it is part of what makes a ride repeat), e.g. "glibc 2.43".
pub fn c_library_version() -> String {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    {
        extern "C" {
            fn gnu_get_libc_version() -> *const std::ffi::c_char;
        }
        // SAFETY: glibc returns a pointer to a static NUL-terminated string.
        let version = unsafe { CStr::from_ptr(gnu_get_libc_version()) };
        format!("glibc {}", version.to_string_lossy())
    }
    #[cfg(not(all(target_os = "linux", target_env = "gnu")))]
    {
        String::from("unknown C library")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linked_ode_is_double_precision_with_thread_local_collision() {
        let config = configuration();
        assert!(config.double_precision(), "{}", config.raw);
        assert!(config.thread_local_collision(), "{}", config.raw);
    }

    #[test]
    fn the_c_library_names_its_version() {
        let version = c_library_version();
        assert!(version.starts_with("glibc 2."), "{version}");
    }

    #[test]
    fn every_thread_can_allocate_its_data() {
        let handles: Vec<_> = (0..4)
            .map(|_| std::thread::spawn(|| configuration().thread_local_collision()))
            .collect();
        for handle in handles {
            assert!(handle.join().unwrap());
        }
    }
}
