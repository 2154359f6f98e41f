# The libraries the portable Linux release template links statically, each built from its
# Debian source package into one prefix (static, position-independent, nothing else); the
# list and their options are in tools/template-common.sh. Sourced by
# tools/build-template.sh, which sets $deps (the prefix) and calls
# `build_dependency NAME SOURCE_DIR`.

dep_cmake() {
  local src=$1; shift
  cmake -S "$src" -B "$src/build-static" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$deps" -DCMAKE_PREFIX_PATH="$deps" -DCMAKE_INSTALL_LIBDIR=lib \
    -DCMAKE_POSITION_INDEPENDENT_CODE=ON -DBUILD_SHARED_LIBS=OFF "$@" >/dev/null
  cmake --build "$src/build-static" >/dev/null
  cmake --install "$src/build-static" >/dev/null
}

build_dependency() {
  local name=$1 src=$2
  export CFLAGS="-O2 -fPIC" CXXFLAGS="-O2 -fPIC" PKG_CONFIG_PATH="$deps/lib/pkgconfig"
  case "$name" in
    zlib)
      (cd "$src" && ./configure --static --prefix="$deps" >/dev/null && make -s install >/dev/null) ;;
    libpng1.6) dep_cmake "$src" "${PNG_OPTIONS[@]}" -DZLIB_ROOT="$deps" ;;
    brotli) dep_cmake "$src" "${BROTLI_OPTIONS[@]}" && keep_static_brotli "$deps/lib" ;;
    freetype) dep_cmake "$src" "${FREETYPE_OPTIONS[@]}" ;;
    libzstd)
      make -s -C "$src/lib" libzstd.a-mt >/dev/null
      make -s -C "$src/lib" install-static install-includes install-pc PREFIX="$deps" LIBDIR="$deps/lib" >/dev/null ;;
    libwebp) dep_cmake "$src" "${WEBP_OPTIONS[@]}" ;;
    mbedtls) dep_cmake "$src" "${MBEDTLS_OPTIONS[@]}" ;;
    libsdl3)
      # SDL loads whatever else it finds at run time, so nothing it needs is linked in.
      dep_cmake "$src" "${SDL_OPTIONS[@]}" -DSDL_DEPS_SHARED=ON -DSDL_UNIX_CONSOLE_BUILD=ON ;;
    *) die "no recipe for $name" ;;
  esac
}
