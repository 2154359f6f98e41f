# The libraries a portable Godot release template links statically, each built from its
# Debian source package into one prefix (static, position-independent, nothing else).
# Debian's godot source is repacked without Godot's bundled copies of these (its `+ds`
# strips thirdparty/), so the template is built against these instead, with `builtin_*=no`,
# as Debian builds it against its shared ones. Sourced by tools/build-template.sh, which
# sets $deps (the prefix) and calls `build_dependency NAME SOURCE_DIR`.

# Debian source package of each library, in link order for the template.
TEMPLATE_DEPENDENCIES="zlib libpng1.6 brotli freetype libzstd libwebp mbedtls libsdl3"

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
    libpng1.6)
      dep_cmake "$src" -DPNG_SHARED=OFF -DPNG_STATIC=ON -DPNG_TESTS=OFF -DPNG_TOOLS=OFF \
        -DPNG_FRAMEWORK=OFF -DZLIB_ROOT="$deps" ;;
    brotli)
      # Brotli 1.0 builds its static libraries as lib*-static.a beside shared ones and its
      # pkg-config files name the shared ones: keep the static ones under the plain names.
      dep_cmake "$src" -DBROTLI_DISABLE_TESTS=ON
      for lib in common dec enc; do
        [ -f "$deps/lib/libbrotli$lib-static.a" ] && mv "$deps/lib/libbrotli$lib-static.a" "$deps/lib/libbrotli$lib.a"
      done
      rm -f "$deps"/lib/libbrotli*.so* ;;
    freetype)
      # Zlib and Brotli for WOFF and WOFF2 fonts (Godot's default font is WOFF2).
      dep_cmake "$src" -DFT_REQUIRE_ZLIB=ON -DFT_REQUIRE_BROTLI=ON -DFT_DISABLE_PNG=ON \
        -DFT_DISABLE_HARFBUZZ=ON -DFT_DISABLE_BZIP2=ON ;;
    libzstd)
      make -s -C "$src/lib" libzstd.a-mt >/dev/null
      make -s -C "$src/lib" install-static install-includes install-pc PREFIX="$deps" LIBDIR="$deps/lib" >/dev/null ;;
    libwebp)
      dep_cmake "$src" -DWEBP_BUILD_ANIM_UTILS=OFF -DWEBP_BUILD_CWEBP=OFF -DWEBP_BUILD_DWEBP=OFF \
        -DWEBP_BUILD_GIF2WEBP=OFF -DWEBP_BUILD_IMG2WEBP=OFF -DWEBP_BUILD_VWEBP=OFF \
        -DWEBP_BUILD_WEBPINFO=OFF -DWEBP_BUILD_WEBPMUX=OFF -DWEBP_BUILD_EXTRAS=OFF ;;
    mbedtls)
      dep_cmake "$src" -DENABLE_TESTING=OFF -DENABLE_PROGRAMS=OFF -DUSE_STATIC_MBEDTLS_LIBRARY=ON \
        -DUSE_SHARED_MBEDTLS_LIBRARY=OFF -DMBEDTLS_FATAL_WARNINGS=OFF ;;
    libsdl3)
      # Godot uses SDL for game controllers only; SDL loads whatever else it finds at run
      # time, so nothing it needs is linked in.
      dep_cmake "$src" -DSDL_STATIC=ON -DSDL_SHARED=OFF -DSDL_TEST_LIBRARY=OFF -DSDL_TESTS=OFF \
        -DSDL_EXAMPLES=OFF -DSDL_DEPS_SHARED=ON -DSDL_VIDEO=OFF -DSDL_RENDER=OFF -DSDL_AUDIO=OFF \
        -DSDL_CAMERA=OFF -DSDL_GPU=OFF -DSDL_DIALOG=OFF -DSDL_UNIX_CONSOLE_BUILD=ON ;;
    *) die "no recipe for $name" ;;
  esac
}
