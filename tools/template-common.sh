# What the Linux and Windows release templates share (tools/build-template.sh with
# tools/template-deps.sh; tools/windows-build-inside.sh with tools/windows-deps.sh): the
# libraries built statically for them, how each is configured, and the SCons options.
# Sourced.

# Debian source package of each library, in link order for the template. Debian's godot
# source is repacked without Godot's bundled copies of these (its `+ds` strips
# thirdparty/), so the templates are built against these instead, with `builtin_*=no`.
TEMPLATE_DEPENDENCIES="zlib libpng1.6 brotli freetype libzstd libwebp mbedtls libsdl3"

# CMake options of the libraries built with CMake, on either platform.
PNG_OPTIONS=(-DPNG_SHARED=OFF -DPNG_STATIC=ON -DPNG_TESTS=OFF -DPNG_TOOLS=OFF -DPNG_FRAMEWORK=OFF)
BROTLI_OPTIONS=(-DBROTLI_DISABLE_TESTS=ON)
# Zlib and Brotli for WOFF and WOFF2 fonts (Godot's default font is WOFF2).
FREETYPE_OPTIONS=(-DFT_REQUIRE_ZLIB=ON -DFT_REQUIRE_BROTLI=ON -DFT_DISABLE_PNG=ON
                  -DFT_DISABLE_HARFBUZZ=ON -DFT_DISABLE_BZIP2=ON)
WEBP_OPTIONS=(-DWEBP_BUILD_ANIM_UTILS=OFF -DWEBP_BUILD_CWEBP=OFF -DWEBP_BUILD_DWEBP=OFF
              -DWEBP_BUILD_GIF2WEBP=OFF -DWEBP_BUILD_IMG2WEBP=OFF -DWEBP_BUILD_VWEBP=OFF
              -DWEBP_BUILD_WEBPINFO=OFF -DWEBP_BUILD_WEBPMUX=OFF -DWEBP_BUILD_EXTRAS=OFF)
MBEDTLS_OPTIONS=(-DENABLE_TESTING=OFF -DENABLE_PROGRAMS=OFF -DUSE_STATIC_MBEDTLS_LIBRARY=ON
                 -DUSE_SHARED_MBEDTLS_LIBRARY=OFF -DMBEDTLS_FATAL_WARNINGS=OFF)
# Godot uses SDL for game controllers only.
SDL_OPTIONS=(-DSDL_STATIC=ON -DSDL_SHARED=OFF -DSDL_TEST_LIBRARY=OFF -DSDL_TESTS=OFF
             -DSDL_EXAMPLES=OFF -DSDL_VIDEO=OFF -DSDL_RENDER=OFF -DSDL_AUDIO=OFF
             -DSDL_CAMERA=OFF -DSDL_GPU=OFF -DSDL_DIALOG=OFF)

# Brotli 1.0 installs its static libraries as lib*-static.a beside shared ones, whose
# names its pkg-config files give: keep the static ones under the plain names.
keep_static_brotli() {
  local lib_dir=$1 lib
  for lib in common dec enc; do
    [ -f "$lib_dir/libbrotli$lib-static.a" ] && mv "$lib_dir/libbrotli$lib-static.a" "$lib_dir/libbrotli$lib.a"
  done
  rm -f "$lib_dir"/libbrotli*.so* "$lib_dir"/libbrotli*.dll.a
}

TEMPLATE_COMMON_OPTIONS=(
  target=template_release arch=x86_64 production=no debug_symbols=no use_static_cpp=yes
  vulkan=no engine_update_check=no
  builtin_zlib=no builtin_libpng=no builtin_brotli=no builtin_freetype=no builtin_zstd=no
  builtin_libwebp=no builtin_mbedtls=no builtin_sdl=no
  # What the game does not use and whose libraries the repack strips: complex text
  # shaping (the fallback text server draws the game's Latin text), JPEG, Ogg, Vorbis,
  # Theora, ENet, WebSocket, UPnP, OpenXR, RegEx, Embree and navigation.
  module_text_server_adv_enabled=no module_text_server_fb_enabled=yes
  module_jpg_enabled=no module_ogg_enabled=no module_vorbis_enabled=no module_theora_enabled=no
  module_enet_enabled=no module_websocket_enabled=no module_upnp_enabled=no
  module_openxr_enabled=no module_regex_enabled=no module_raycast_enabled=no
  module_navigation_2d_enabled=no module_navigation_3d_enabled=no
)
