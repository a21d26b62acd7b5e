# Kiosk input (included from platform/CMakeLists.txt): noneuclid_input = GPIO buttons through
# libgpiod + evdev key devices + the board's buttons opened + `noneuclid buttons`.
#
# libgpiod has two incompatible APIs and no version macro, so the major version from pkg-config
# picks the backend: gpio_v1.cpp (1.x: Debian 12's libgpiod-dev) or gpio_v2.cpp (2.x: Debian 13,
# or bookworm-backports unpacked by platform/debian/gpiod2-prefix.sh and named with
# -DNONEUCLID_GPIOD_PREFIX=<dir>/usr, see the static-gpiod2 preset). Without libgpiod (a cross
# build without libgpiod-dev:<arch>) gpio_none.cpp says so at run time; evdev still works.
# Static builds (NONEUCLID_STATIC, or -static in CMAKE_EXE_LINKER_FLAGS) link libgpiod.a; so do
# cross builds when the .a is there (the -dev package has it), so the Pi needs no libgpiod2.

if(NOT CMAKE_SYSTEM_NAME STREQUAL "Linux")
    return()
endif()

set(NONEUCLID_GPIOD_PREFIX "" CACHE PATH
    "A libgpiod prefix to use instead of the system's (e.g. build/gpiod2/root/usr from platform/debian/gpiod2-prefix.sh)")
option(NONEUCLID_GPIOD "Use libgpiod for GPIO buttons when it is found" ON)

set(noneuclid_gpiod_static OFF)
if(NONEUCLID_STATIC OR CMAKE_EXE_LINKER_FLAGS MATCHES "(^| )-static( |$)")
    set(noneuclid_gpiod_static ON)
endif()

set(noneuclid_gpiod_found OFF)
if(NONEUCLID_GPIOD)
    find_package(PkgConfig QUIET)
    if(PKG_CONFIG_FOUND)
        if(NONEUCLID_GPIOD_PREFIX)
            # Its .pc first; a separate result prefix so that switching never reuses the system's.
            file(GLOB noneuclid_gpiod_pc_dirs LIST_DIRECTORIES true
                "${NONEUCLID_GPIOD_PREFIX}/lib/*/pkgconfig" "${NONEUCLID_GPIOD_PREFIX}/lib/pkgconfig")
            if(NOT noneuclid_gpiod_pc_dirs)
                message(FATAL_ERROR "NONEUCLID_GPIOD_PREFIX=${NONEUCLID_GPIOD_PREFIX} has no lib/*/pkgconfig: "
                                    "run platform/debian/gpiod2-prefix.sh first (it fills build/gpiod2/root/usr)")
            endif()
            list(JOIN noneuclid_gpiod_pc_dirs ":" noneuclid_gpiod_pc_path)
            set(ENV{PKG_CONFIG_PATH} "${noneuclid_gpiod_pc_path}:$ENV{PKG_CONFIG_PATH}")
            set(noneuclid_gpiod_pkg NONEUCLID_GPIOD_PFX)
        else()
            set(noneuclid_gpiod_pkg NONEUCLID_GPIOD_SYS)
        endif()
        pkg_check_modules(${noneuclid_gpiod_pkg} QUIET libgpiod)
        if(${noneuclid_gpiod_pkg}_FOUND)
            set(noneuclid_gpiod_version ${${noneuclid_gpiod_pkg}_VERSION})
            string(REGEX MATCH "^[0-9]+" noneuclid_gpiod_major "${noneuclid_gpiod_version}")
            # Resolve the files ourselves: the .pc's directories are real paths (multiarch
            # /usr/lib/<triple> in cross builds), outside CMAKE_FIND_ROOT_PATH; and a static build
            # must get the .a even where the .so exists.
            set(noneuclid_gpiod_libdirs ${${noneuclid_gpiod_pkg}_LIBDIR} ${${noneuclid_gpiod_pkg}_LIBRARY_DIRS})
            if(noneuclid_gpiod_static)
                set(noneuclid_gpiod_names libgpiod.a)
            elseif(CMAKE_CROSSCOMPILING)
                # A binary built to be copied to a Pi: libgpiod inside it, one package fewer there.
                set(noneuclid_gpiod_names libgpiod.a gpiod)
            else()
                set(noneuclid_gpiod_names gpiod)
            endif()
            unset(NONEUCLID_GPIOD_LIBRARY CACHE)
            find_library(NONEUCLID_GPIOD_LIBRARY NAMES ${noneuclid_gpiod_names}
                HINTS ${noneuclid_gpiod_libdirs} NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
            unset(NONEUCLID_GPIOD_INCLUDE_DIR CACHE)
            find_path(NONEUCLID_GPIOD_INCLUDE_DIR gpiod.h
                HINTS ${${noneuclid_gpiod_pkg}_INCLUDEDIR} ${${noneuclid_gpiod_pkg}_INCLUDE_DIRS}
                NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
            if(NOT noneuclid_gpiod_major MATCHES "^[12]$")
                message(WARNING "libgpiod ${noneuclid_gpiod_version} has an API this code does not know "
                                "(1.x and 2.x are supported): GPIO buttons disabled")
            elseif(NOT NONEUCLID_GPIOD_LIBRARY OR NOT NONEUCLID_GPIOD_INCLUDE_DIR)
                message(WARNING "libgpiod ${noneuclid_gpiod_version}'s pkg-config file names "
                                "${noneuclid_gpiod_libdirs}, but ${noneuclid_gpiod_names} or gpiod.h is not there: "
                                "GPIO buttons disabled (reinstall libgpiod-dev)")
            else()
                set(noneuclid_gpiod_found ON)
            endif()
        endif()
    endif()
endif()

if(noneuclid_gpiod_found)
    add_library(noneuclid_input STATIC linux/gpio_v${noneuclid_gpiod_major}.cpp)
    # The library's own directory only, never a whole system include directory in a cross build.
    if(NOT NONEUCLID_GPIOD_INCLUDE_DIR IN_LIST CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES)
        target_include_directories(noneuclid_input SYSTEM PRIVATE ${NONEUCLID_GPIOD_INCLUDE_DIR})
    endif()
    target_link_libraries(noneuclid_input PRIVATE ${NONEUCLID_GPIOD_LIBRARY})
    # The API's major version, for the tests that report it (tests/platform/linux): not a
    # definition every user of the library compiles with, so that the program's objects are the
    # same whichever libgpiod it links, and ccache serves one tree's to another.
    set_target_properties(noneuclid_input PROPERTIES NONEUCLID_GPIOD_MAJOR ${noneuclid_gpiod_major})
    set(noneuclid_gpiod_kind shared)
    if(NONEUCLID_GPIOD_LIBRARY MATCHES "\\.a$")
        set(noneuclid_gpiod_kind static)
    endif()
    message(STATUS "libgpiod ${noneuclid_gpiod_version} (v${noneuclid_gpiod_major} API, ${noneuclid_gpiod_kind}): "
                   "${NONEUCLID_GPIOD_LIBRARY}")
else()
    add_library(noneuclid_input STATIC linux/gpio_none.cpp)
    if(NOT NONEUCLID_GPIOD)
        message(STATUS "NONEUCLID_GPIOD=OFF: GPIO buttons disabled, evdev only")
    else()
        message(STATUS "libgpiod not found for the target: GPIO buttons disabled, evdev only "
                       "(Debian: libgpiod-dev, or libgpiod-dev:<arch> for a cross build)")
    endif()
endif()
target_sources(noneuclid_input PRIVATE linux/gpio_common.cpp linux/evdev.cpp linux/input.cpp linux/input_set.cpp)
target_include_directories(noneuclid_input PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(noneuclid_input PUBLIC noneuclid_files PRIVATE noneuclid_posix noneuclid_warnings)
# 64-bit directory offsets on 32-bit ARM: readdir() of a large-offset directory (ext4 hashes,
# and every directory under qemu-arm on a 64-bit host) fails with EOVERFLOW without it.
target_compile_definitions(noneuclid_input PUBLIC _FILE_OFFSET_BITS=64)


# The system test's proof that read() allocates nothing (tests/system/input.sh): statically
# linked, malloc and friends wrapped. Built on request only (tests/system/input-test does).
if(noneuclid_gpiod_static)
    add_executable(input_alloc_probe EXCLUDE_FROM_ALL ${PROJECT_SOURCE_DIR}/tests/platform/linux/alloc_probe.cpp)
    target_link_libraries(input_alloc_probe PRIVATE noneuclid_input noneuclid_warnings)
    target_link_options(input_alloc_probe PRIVATE
        -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free)
endif()
