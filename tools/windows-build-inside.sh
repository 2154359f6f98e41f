#!/usr/bin/env bash
# Runs inside the Windows root, in /build (see tools/build-windows.sh, which copies the
# sources and this project's native code there first). Cross-builds with MinGW-w64, each
# step skipped when its stamp says it is built by the current recipe:
#   ODE (the same patched 0.16 as on Linux), the eight static libraries, the native module
#   as cpbp.dll (Rust's standard library cross-built from Debian's rust-src, since Debian
#   ships no prebuilt one for Windows), and unless SKIP_TEMPLATE is set, the release
#   template. Results go to /build/out.
set -euo pipefail
cd /build
source tools/windows-deps.sh
source tools/template-common.sh
mkdir -p stamps out
write_mingw_toolchain
step() { printf '[windows] %s\n' "$*"; }

ode_recipe=$(cat tools/windows-build-inside.sh tools/ode-patches/*.patch | sha256sum | cut -c1-12)
if [ "$(cat stamps/ode 2>/dev/null)" != "$ode_recipe" ]; then
  step "ODE"
  rm -rf ode-src ode-build ode && cp -a src/ode ode-src
  for patch in tools/ode-patches/*.patch; do (cd ode-src && patch -p1 --forward --quiet) <"$patch"; done
  # MinGW's headers are named in lower case, as Windows does not mind but Linux does.
  sed -i 's/<Windows.h>/<windows.h>/' ode-src/ode/src/threading_pool_win.cpp
  cmake -S ode-src -B ode-build -G Ninja -DCMAKE_TOOLCHAIN_FILE="$MINGW_TOOLCHAIN" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/build/ode -DBUILD_SHARED_LIBS=OFF \
    -DCMAKE_POLICY_VERSION_MINIMUM=3.5 -Wno-dev -Wno-deprecated -DODE_DOUBLE_PRECISION=ON -DODE_WITH_OU=ON \
    -DODE_WITH_DEMOS=OFF -DODE_WITH_TESTS=OFF -DODE_WITH_LIBCCD=ON -DODE_WITH_LIBCCD_SYSTEM=OFF >/dev/null
  cmake --build ode-build >/dev/null && cmake --install ode-build >/dev/null
  ln -sf libode_doubles.a /build/ode/lib/libode.a
  echo "$ode_recipe" >stamps/ode
fi

deps_recipe=$(cat tools/windows-deps.sh tools/template-common.sh | sha256sum | cut -c1-12)
for name in $TEMPLATE_DEPENDENCIES; do
  [ "$(cat "stamps/built-$name" 2>/dev/null)" = "$deps_recipe" ] && continue
  step "static $name"
  build_windows_dependency "$name" "src/$name"
  echo "$deps_recipe" >"stamps/built-$name"
done

step "native module (cpbp.dll)"
(cd native && ODE_PREFIX=/build/ode RUSTC_BOOTSTRAP=1 CARGO_HOME=/build/cargo-home \
  CARGO_TARGET_X86_64_PC_WINDOWS_GNU_LINKER=$MINGW-gcc-posix \
  CC_x86_64_pc_windows_gnu=$MINGW-gcc-posix CXX_x86_64_pc_windows_gnu=$MINGW-g++-posix \
  AR_x86_64_pc_windows_gnu=$MINGW-ar \
  BINDGEN_EXTRA_CLANG_ARGS_x86_64_pc_windows_gnu="--target=$MINGW -I/usr/$MINGW/include" \
  cargo build --quiet --release -p cpbp-godot --target x86_64-pc-windows-gnu -Zbuild-std=std,panic_abort)
cp native/target/x86_64-pc-windows-gnu/release/cpbp.dll out/

[ -n "${SKIP_TEMPLATE:-}" ] && exit 0
step "release template (the long part; progress in /build/scons.log)"
rm -rf custom_modules && mkdir -p custom_modules
cp -r tools/windows-static-libraries custom_modules/static_libraries
mkdir -p src/godot/thirdparty/certs && touch src/godot/thirdparty/certs/ca-bundle.crt
# Windows' own certificate store stands in for the bundle the repack strips.
(cd src/godot && scons platform=windows use_mingw=yes "-j$(nproc)" "${TEMPLATE_COMMON_OPTIONS[@]}" \
  d3d12=no accesskit=no builtin_certs=no custom_modules=/build/custom_modules >/build/scons.log 2>&1) \
  || { tail -30 /build/scons.log; exit 1; }
cp src/godot/bin/godot.windows.template_release.x86_64.exe out/
