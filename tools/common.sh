# Shared settings for the provisioning scripts; sourced, never run.
# Everything downloaded or built lives in one per-user cache so a second
# setup is instant and the host system is never modified beyond apt packages.

set -euo pipefail

PROJECT_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CACHE_ROOT="${COUNTER_STEER_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/counter-steer}"
mkdir -p "$CACHE_ROOT"

# Packages of the private Debian-unstable root that carries Godot 4.6.
# Changing this list changes the root's key, so a new root is built beside the old one.
GODOT_ROOT_PACKAGES="godot,godot-template-release,godot-template-debug,libgl1-mesa-dri,libglx-mesa0,libegl-mesa0,libgl1,libegl1,libx11-6,libxcursor1,libxinerama1,libxrandr2,libxi6,libxext6,libxrender1,libxkbcommon0,libasound2t64,ca-certificates"
GODOT_ROOT_KEY="$(printf '%s' "sid:$GODOT_ROOT_PACKAGES" | sha256sum | cut -c1-12)"
GODOT_ROOT="$CACHE_ROOT/godot-root-$GODOT_ROOT_KEY"

# The exact upstream version: the committed rows re-ride bit for bit only on it.
ODE_VERSION_WANTED="0.16.2"
# Keyed by the build recipe, so changing tools/build-ode.sh or a patch rebuilds ODE.
ODE_RECIPE_KEY="$(cat "$PROJECT_ROOT/tools/build-ode.sh" "$PROJECT_ROOT"/tools/ode-patches/*.patch \
  | sha256sum | cut -c1-12)"
ODE_PREFIX="$CACHE_ROOT/ode-$ODE_VERSION_WANTED-$ODE_RECIPE_KEY"

# The portable release template the export ships (tools/build-template.sh), keyed by its
# recipe.
TEMPLATE_RECIPE_KEY="$(cat "$PROJECT_ROOT/tools/build-template.sh" "$PROJECT_ROOT/tools/template-deps.sh" \
  "$PROJECT_ROOT/tools/template-common.sh" | sha256sum | cut -c1-12)"
TEMPLATE_DIR="$CACHE_ROOT/godot-template-$TEMPLATE_RECIPE_KEY"

# The Windows build (tools/build-windows.sh): a private Debian-unstable root with MinGW-w64
# and a Rust whose standard library source is there to be cross-built, and the Windows
# release template it makes, keyed by the recipe.
WINDOWS_ROOT_PACKAGES="rustc,cargo,rust-src,gcc-mingw-w64-x86-64-posix,g++-mingw-w64-x86-64-posix,cmake,make,ninja-build,scons,pkgconf,libclang-dev,clang,ca-certificates,patch"
WINDOWS_ROOT="$CACHE_ROOT/windows-root-$(printf '%s' "sid:$WINDOWS_ROOT_PACKAGES" | sha256sum | cut -c1-12)"
WINDOWS_RECIPE_KEY="$(cat "$PROJECT_ROOT"/tools/windows-*.sh "$PROJECT_ROOT/tools/build-windows.sh" \
  "$PROJECT_ROOT/tools/template-common.sh" \
  "$PROJECT_ROOT"/tools/windows-static-libraries/* | sha256sum | cut -c1-12)"
WINDOWS_TEMPLATE_DIR="$CACHE_ROOT/godot-windows-template-$WINDOWS_RECIPE_KEY"

# Serialises provisioning: two setups at once (say `make test` and `make play` in two
# terminals) would otherwise build into the same cache directories and break each other.
# The lock is held until the calling script exits.
lock_cache() {
  exec 9>"$CACHE_ROOT/.provision.lock"
  flock 9
}

# Godot keeps user:// (settings, records, ghosts, its own logs) under
# $XDG_DATA_HOME/godot/app_userdata/Counter-Steer, and the editor its settings under
# $XDG_CONFIG_HOME/godot. Every tool that starts Godot for a check, an import or a
# measurement gives it data and config homes of its own, emptied for that run under
# build/scratch/NAME, so it never reads what an earlier run or the player left there and
# never writes into the player's files. The folder stays after the run (Godot's logs in it
# help when a check fails); `make clean` removes it. COUNTER_STEER_SCRATCH tells the game's
# test runner which folder that is, so it can refuse to run anywhere else. Only `make play`
# runs the game in the player's own folder.
use_scratch_user_data() {
  local dir="$PROJECT_ROOT/build/scratch/$1"
  rm -rf "$dir" && mkdir -p "$dir/data" "$dir/config"
  export XDG_DATA_HOME="$dir/data" XDG_CONFIG_HOME="$dir/config" COUNTER_STEER_SCRATCH="$dir"
}

# The folder where Godot keeps the player's user:// for this project (project.godot's name).
player_user_data_dir() {
  local name
  name=$(sed -n 's|^config/name="\(.*\)"$|\1|p' "$PROJECT_ROOT/project.godot")
  printf '%s\n' "${XDG_DATA_HOME:-$HOME/.local/share}/godot/app_userdata/$name"
}

log() { printf '\033[1;34m[setup]\033[0m %s\n' "$*" >&2; }
die() { printf '\033[1;31m[setup] error:\033[0m %s\n' "$*" >&2; exit 1; }

# Run a command as root: directly when we are root, through sudo otherwise.
as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# Installs the Debian packages named that are missing from the host (apt, as root).
ensure_host_packages() {
  local missing
  mapfile -t missing < <(absent_host_packages "$@")
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing host packages: ${missing[*]}"
  if [ "$(id -u)" -ne 0 ] && ! command -v sudo >/dev/null; then
    die "need root (or sudo) to install: ${missing[*]}"
  fi
  apt_install "${missing[@]}"
}

# The Debian packages named that are not installed on the host, one a line.
absent_host_packages() {
  local package
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
      || printf '%s\n' "$package"
  done
}

# Installs the Debian packages named with apt, as root.
apt_install() {
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq >/dev/null
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@" >/dev/null
}

# The Debian mirror the host already uses, so nothing outside the configured registry is contacted.
debian_mirror() {
  local uri
  uri=$(grep -rhoE '^(URIs:|deb) +https?://[^ ]*debian[^ ]*' /etc/apt/sources.list /etc/apt/sources.list.d/ 2>/dev/null \
        | grep -v security | head -n1 | awk '{print $2}')
  printf '%s\n' "${uri:-http://deb.debian.org/debian}"
}
