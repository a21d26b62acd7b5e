# Cross toolchain: 64-bit ARM Linux (Debian arm64), tuned for the Cortex-A53
# (Raspberry Pi 3, Zero 2 W; runs on Pi 4/5 too) running a 64-bit OS.
#
# Debian packages: crossbuild-essential-arm64 (compiler + sysroot in /usr/aarch64-linux-gnu)
# and qemu-user (runs the tests; the non-static qemu can load plugins, which
# tests/bench/insncount/arm-insncount needs). Use via the `aarch64` preset.

set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(NONEUCLID_TARGET_TRIPLE aarch64-linux-gnu)
set(CMAKE_C_COMPILER ${NONEUCLID_TARGET_TRIPLE}-gcc)    # only for C code pulled in (GoogleTest)
set(CMAKE_CXX_COMPILER ${NONEUCLID_TARGET_TRIPLE}-g++)

set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-a53")
set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-a53")

# Libraries, headers and CMake packages come from the target sysroot only; programs
# (tools run at build time) from the host.
set(CMAKE_FIND_ROOT_PATH /usr/${NONEUCLID_TARGET_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# pkg-config answers for the target: Debian's multiarch .pc files (e.g. libgpiod-dev:<arch>,
# installed after `dpkg --add-architecture <arch>`), never the host's.
set(ENV{PKG_CONFIG_LIBDIR} /usr/lib/${NONEUCLID_TARGET_TRIPLE}/pkgconfig:/usr/share/pkgconfig)

# Run target programs (tests, gtest discovery) under qemu-user with the sysroot's loader and
# libraries. Prefer qemu-aarch64 (qemu-user) over qemu-aarch64-static (qemu-user-static).
find_program(NONEUCLID_QEMU_AARCH64 NAMES qemu-aarch64 qemu-aarch64-static
    DOC "qemu user-mode emulator for aarch64")
if(NONEUCLID_QEMU_AARCH64)
    set(CMAKE_CROSSCOMPILING_EMULATOR ${NONEUCLID_QEMU_AARCH64} -L /usr/${NONEUCLID_TARGET_TRIPLE})
endif()
