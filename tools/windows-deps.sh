# The libraries the Windows release template links statically, cross-built with
# MinGW-w64 from their Debian source packages into /build/deps: the same ones, configured
# the same way, as for the Linux template (tools/template-common.sh). Sourced inside the
# Windows root by tools/windows-build-inside.sh, which calls `build_windows_dependency`.
MINGW=x86_64-w64-mingw32
MINGW_TOOLCHAIN=/build/mingw.cmake

# A CMake toolchain for MinGW-w64 that finds libraries in MinGW's sysroot and /build/deps.
write_mingw_toolchain() {
  cat >"$MINGW_TOOLCHAIN" <<TOOLCHAIN
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER $MINGW-gcc-posix)
set(CMAKE_CXX_COMPILER $MINGW-g++-posix)
set(CMAKE_RC_COMPILER $MINGW-windres)
set(CMAKE_FIND_ROOT_PATH /usr/$MINGW /build/deps)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
TOOLCHAIN
}

mingw_cmake() {
  local src=$1; shift
  rm -rf "$src/build-windows"
  cmake -S "$src" -B "$src/build-windows" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$MINGW_TOOLCHAIN" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/build/deps -DCMAKE_INSTALL_LIBDIR=lib \
    -DBUILD_SHARED_LIBS=OFF -DCMAKE_POLICY_VERSION_MINIMUM=3.5 -Wno-dev -Wno-deprecated "$@" >/dev/null
  cmake --build "$src/build-windows" >/dev/null
  cmake --install "$src/build-windows" >/dev/null
}

build_windows_dependency() {
  local name=$1 src=$2 deps=/build/deps zlib_args
  zlib_args=(-DZLIB_LIBRARY=$deps/lib/libz.a -DZLIB_INCLUDE_DIR=$deps/include)
  case "$name" in
    zlib)
      # Debian's zlib source has no Windows makefile; the library is its fifteen C files.
      (cd "$src" && rm -f ./*.o \
        && for f in adler32 compress crc32 deflate gzclose gzlib gzread gzwrite infback \
                    inffast inflate inftrees trees uncompr zutil; do
             $MINGW-gcc-posix -O2 -c "$f.c"
           done \
        && $MINGW-ar rcs libz.a ./*.o)
      install -D -m644 "$src/libz.a" "$deps/lib/libz.a"
      install -D -m644 -t "$deps/include" "$src/zlib.h" "$src/zconf.h" ;;
    libpng1.6) mingw_cmake "$src" "${PNG_OPTIONS[@]}" "${zlib_args[@]}" ;;
    brotli) mingw_cmake "$src" "${BROTLI_OPTIONS[@]}" && keep_static_brotli "$deps/lib" ;;
    freetype)
      mingw_cmake "$src" "${FREETYPE_OPTIONS[@]}" "${zlib_args[@]}" -DBROTLIDEC_INCLUDE_DIRS=$deps/include \
        -DBROTLIDEC_LIBRARIES="$deps/lib/libbrotlidec.a;$deps/lib/libbrotlicommon.a" ;;
    libzstd)
      mingw_cmake "$src/build/cmake" -DZSTD_BUILD_SHARED=OFF -DZSTD_BUILD_STATIC=ON \
        -DZSTD_BUILD_PROGRAMS=OFF -DZSTD_BUILD_TESTS=OFF -DZSTD_MULTITHREAD_SUPPORT=ON ;;
    libwebp) mingw_cmake "$src" "${WEBP_OPTIONS[@]}" ;;
    mbedtls) mingw_cmake "$src" "${MBEDTLS_OPTIONS[@]}" ;;
    libsdl3) mingw_cmake "$src" "${SDL_OPTIONS[@]}" ;;
    *) echo "no Windows recipe for $name" >&2; return 1 ;;
  esac
}
