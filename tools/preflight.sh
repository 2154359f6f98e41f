#!/usr/bin/env bash
# The first step of every make target that provisions or builds: checks everything this
# project needs of the machine, installs with apt what apt can, and when something is
# still missing lists all of it at once, each with the command that installs it, before
# anything is downloaded or built. The README's "Requirements" say the same.
source "$(dirname "$0")/common.sh"

# Python: the pinned scipy (1.17) and statsmodels (0.15) in tools/requirements.txt need 3.11.
PYTHON_MIN=3.11
# Free disk a cold `make test` needs: the Godot root, ODE, the Python tools and the pip
# and cargo downloads in the cache, native/target and build/ in the checkout, 5.6 GB
# (docs/benchmarks.md, "A cold make test"), with room to spare.
DISK_MIN_GB=8
# Debian packages the build and the checks use: debootstrap makes the private Godot root,
# dpkg-dev and patch unpack and patch ODE's source package, cmake and the C/C++ compilers
# build it, clang and libclang generate its Rust bindings, Xvfb draws the screenshots,
# patchelf checks the export; python3-venv gives the Python tools their venv.
APT_PACKAGES=(debootstrap cmake dpkg-dev patch gcc g++ make libclang-dev clang xvfb xauth
              patchelf ca-certificates git python3 python3-venv)

missing=()     # one line each: what is missing, then how to install it
apt_wanted=()  # Debian packages that would mend something missing

need() { missing+=("$1"$'\n'"      $2"); }

version_at_least() {  # version_at_least HAVE WANT: dotted versions, numerically
  [ "$(printf '%s\n%s\n' "$2" "$1" | sort -V | head -n1)" = "$2" ]
}

rust_wanted() {
  sed -n 's/^rust-version *= *"\([0-9.]*\)".*/\1/p' "$PROJECT_ROOT/native/Cargo.toml" | head -n1
}

# The distribution's own Rust is enough where its candidate version meets rust-version.
distribution_rust_enough() {
  command -v apt-cache >/dev/null || return 1
  local candidate
  candidate=$(apt-cache policy rustc 2>/dev/null | sed -n 's/^ *Candidate: *\([0-9.]*\).*/\1/p')
  [ -n "$candidate" ] && version_at_least "$candidate" "$1"
}

check_rust() {
  local wanted have install
  wanted=$(rust_wanted)
  if distribution_rust_enough "$wanted"; then
    install="sudo apt-get install rustc cargo rust-clippy rustfmt"
  else
    install="install rustup (rustup.rs, or 'sudo apt-get install rustup' where the distribution has it), then: rustup default stable"
  fi
  if ! command -v cargo >/dev/null || ! command -v rustc >/dev/null; then
    need "Rust $wanted or newer (cargo and rustc are not on PATH)" "$install"
    return
  fi
  have=$(rustc --version | awk '{print $2}')
  if ! version_at_least "${have%%-*}" "$wanted"; then
    if command -v rustup >/dev/null; then install="rustup update stable && rustup default stable"; fi
    need "Rust $wanted or newer (native/Cargo.toml's rust-version); this machine has $have" "$install"
  fi
}

check_python() {
  local have
  if ! command -v python3 >/dev/null; then
    need "Python $PYTHON_MIN or newer (python3 is not on PATH)" "sudo apt-get install python3 python3-venv"
    apt_wanted+=(python3 python3-venv)
    return
  fi
  have=$(python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])')
  if ! version_at_least "$have" "$PYTHON_MIN"; then
    need "Python $PYTHON_MIN or newer (the pinned scipy and statsmodels); python3 is $have" \
      "Debian 12 and Ubuntu 24.04 ship a new enough python3; elsewhere install one and put it first on PATH"
    return
  fi
  if ! python3 -c 'import venv, ensurepip' 2>/dev/null; then
    need "Python's venv module with pip (python3 -m venv fails without it)" \
      "sudo apt-get install python3-venv"
    apt_wanted+=(python3-venv)
  fi
}

check_packages() {
  local absent
  if ! command -v dpkg-query >/dev/null; then
    need "a Debian or Ubuntu system (the provisioning uses apt and debootstrap)" \
      "on another system install the equivalents of: ${APT_PACKAGES[*]}"
    return
  fi
  mapfile -t absent < <(absent_host_packages "${APT_PACKAGES[@]}")
  [ ${#absent[@]} -eq 0 ] && return
  need "Debian packages: ${absent[*]}" "sudo apt-get install ${absent[*]}"
  apt_wanted+=("${absent[@]}")
}

check_disk() {
  local place free_gb
  for place in "$CACHE_ROOT" "$PROJECT_ROOT"; do
    free_gb=$(df -P --block-size=1G "$place" | awk 'NR == 2 {print $4}')
    if [ "${free_gb:-0}" -lt "$DISK_MIN_GB" ]; then
      need "$DISK_MIN_GB GB of free disk at $place (it has ${free_gb} GB)" \
        "free some space, or point COUNTER_STEER_CACHE at a larger disk"
    fi
  done
}

check_all() {
  missing=() apt_wanted=()
  check_packages
  check_python
  check_rust
  check_disk
}

# As root, through passwordless sudo, or through sudo asking at a terminal.
can_use_apt() {
  command -v apt-get >/dev/null || return 1
  [ "$(id -u)" -eq 0 ] || sudo -n true 2>/dev/null || { [ -t 0 ] && command -v sudo >/dev/null; }
}

report_missing() {
  printf '\033[1;31m[setup] this machine is missing what the build needs:\033[0m\n' >&2
  local item
  for item in "${missing[@]}"; do printf '  - %s\n' "$item" >&2; done
  printf 'Nothing was built. Install the above, then run the same make command again.\n' >&2
}

check_all
if [ ${#apt_wanted[@]} -gt 0 ] && can_use_apt; then
  mapfile -t apt_wanted < <(printf '%s\n' "${apt_wanted[@]}" | sort -u)
  log "installing with apt: ${apt_wanted[*]}"
  apt_install "${apt_wanted[@]}" 2>/dev/null || log "apt could not install everything (below)"
  hash -r
  check_all
fi
if [ ${#missing[@]} -gt 0 ]; then
  report_missing
  exit 1
fi

# Rust's linter and formatter: rustup adds them; the distribution's come as packages.
for component in clippy rustfmt; do
  if ! cargo "${component/rustfmt/fmt}" --version >/dev/null 2>&1; then
    command -v rustup >/dev/null \
      || die "cargo $component is missing: sudo apt-get install ${component/clippy/rust-clippy}"
    log "adding the Rust component $component"
    rustup component add "$component" >/dev/null
  fi
done
