#!/usr/bin/env bash
# Installs the host tools the build needs, only when missing: apt packages (debootstrap
# for the Godot root, cmake and dpkg-dev for ODE, libclang for bindgen, Xvfb for
# screenshots, patchelf for the export check) and the Rust components clippy and rustfmt.
source "$(dirname "$0")/common.sh"

ensure_host_packages debootstrap cmake dpkg-dev patch libclang-dev clang xvfb xauth patchelf ca-certificates

command -v cargo >/dev/null || die "Rust is missing: install it with rustup (https://rustup.rs)"
for component in clippy rustfmt; do
  if ! cargo "${component/rustfmt/fmt}" --version >/dev/null 2>&1; then
    log "adding the Rust component $component"
    rustup component add "$component" >/dev/null
  fi
done
