# A Godot module that only links libraries: those Debian's repack strips from the engine's
# thirdparty/ folder, cross-built statically into /build/deps (tools/windows-deps.sh).
# Godot's Windows build has no pkg-config step for `builtin_*=no`; a module's configure()
# can add to the whole build, and libraries appended here come after the engine's own
# archives on the link line, as static archives need.

DEPS = "/build/deps"


def can_build(env, platform):
    return platform == "windows"


def configure(env):
    env.Prepend(CPPPATH=[DEPS + "/include", DEPS + "/include/freetype2"])
    env.Append(LIBPATH=[DEPS + "/lib"])
    # Each library before the ones it needs; then what SDL and Mbed TLS need of Windows
    # (Mbed TLS parses addresses in certificates with Winsock).
    env.Append(
        LIBS=[
            "freetype", "png16", "brotlidec", "brotlicommon", "webp", "sharpyuv", "zstd", "z",
            "mbedtls", "mbedx509", "mbedcrypto", "SDL3",
            "setupapi", "winmm", "imm32", "version", "ole32", "oleaut32", "cfgmgr32", "uuid",
            "bcrypt", "hid", "ws2_32",
        ]
    )
