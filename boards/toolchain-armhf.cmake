# Cross toolchain: 32-bit ARM Linux, hard-float (Debian armhf), tuned for the Cortex-A53 in
# AArch32 mode (Raspberry Pi 3 / Zero 2 W running a 32-bit OS; runs on Pi 4/5 too).
#
# NOTE: Debian armhf is ARMv7 (its libraries assume ARMv7-A + VFPv3-D16 + Thumb-2), so these
# binaries do NOT run on a Raspberry Pi Zero / Zero W / 1 (ARMv6, ARM1176). And because of
# -mcpu=cortex-a53 below (ARMv8-A AArch32, NEON) they also need an ARMv8 core: not a Pi 2 v1.1
# (Cortex-A7). For those, change the tuning to -mcpu=cortex-a7 -mfpu=neon-vfpv4; for ARMv6 a
# different toolchain and sysroot (Raspberry Pi OS's armhf) are needed.
#
# Debian packages: crossbuild-essential-armhf (compiler + sysroot in /usr/arm-linux-gnueabihf)
# and qemu-user. Use via the `armhf` preset.

set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(NONEUCLID_TARGET_TRIPLE arm-linux-gnueabihf)
set(CMAKE_C_COMPILER ${NONEUCLID_TARGET_TRIPLE}-gcc)    # only for C code pulled in (GoogleTest)
set(CMAKE_CXX_COMPILER ${NONEUCLID_TARGET_TRIPLE}-g++)

set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-a53 -mfpu=neon-fp-armv8 -mfloat-abi=hard")
set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-a53 -mfpu=neon-fp-armv8 -mfloat-abi=hard -Wno-psabi")  # psabi: notes about a GCC 7.1 ABI change, not ours

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
# libraries. Prefer qemu-arm (qemu-user) over qemu-arm-static (qemu-user-static).
find_program(NONEUCLID_QEMU_ARM NAMES qemu-arm qemu-arm-static
    DOC "qemu user-mode emulator for 32-bit ARM")
if(NONEUCLID_QEMU_ARM)
    set(CMAKE_CROSSCOMPILING_EMULATOR ${NONEUCLID_QEMU_ARM} -L /usr/${NONEUCLID_TARGET_TRIPLE})
endif()
