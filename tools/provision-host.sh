#!/usr/bin/env bash
# Installs the host tools the build needs, only when missing: apt packages (debootstrap
# for the Godot root, cmake and dpkg-dev for ODE, libclang for bindgen, Xvfb for
# screenshots, patchelf for the export check) and the Rust components clippy and rustfmt.
source "$(dirname "$0")/common.sh"

HOST_PACKAGES=(debootstrap cmake dpkg-dev patch libclang-dev clang xvfb xauth patchelf ca-certificates)
missing=()
for package in "${HOST_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  log "installing host packages: ${missing[*]}"
  if [ "$(id -u)" -ne 0 ] && ! command -v sudo >/dev/null; then
    die "need root (or sudo) to install: ${missing[*]}"
  fi
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

command -v cargo >/dev/null || die "Rust is missing: install it with rustup (https://rustup.rs)"
for component in clippy rustfmt; do
  if ! cargo "${component/rustfmt/fmt}" --version >/dev/null 2>&1; then
    log "adding the Rust component $component"
    rustup component add "$component" >/dev/null
  fi
done
