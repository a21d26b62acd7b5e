# The library for other projects (docs/library.md), included from src/CMakeLists.txt. A plain
# `cmake --install` installs it with the program; everything here is the component dev, so that
# `cmake --install BUILD --component dev` installs it alone, and the Debian packages keep it
# apart: noneuclid-dev holds it, noneuclid (the program, boards, service) is as it was.
#
#   include/noneuclid.h                         the C interface
#   include/noneuclid/{fixed,geometry,...}/     the engine's headers ("world/world.hpp", ...)
#   lib/<triple>/libnoneuclid_*.a               the engine's static libraries
#   lib/<triple>/noneuclid/libnoneuclid.so      the C interface, shared (NONEUCLID_CAPI_SHARED)
#   lib/<triple>/cmake/noneuclid/               noneuclidConfig.cmake, its version file, targets
include(CMakePackageConfigHelpers)

# noneuclid::engine: the portable layers, in the order they link.
set(noneuclid_engine_layers noneuclid_render noneuclid_files noneuclid_world noneuclid_lang noneuclid_geometry
    noneuclid_fixed)
add_library(noneuclid_engine INTERFACE)
target_link_libraries(noneuclid_engine INTERFACE ${noneuclid_engine_layers})
target_compile_features(noneuclid_engine INTERFACE cxx_std_20)
set_target_properties(noneuclid_engine PROPERTIES EXPORT_NAME engine)
add_library(noneuclid::engine ALIAS noneuclid_engine)
foreach(layer ${noneuclid_engine_layers})
    string(REPLACE "noneuclid_" "" short ${layer})
    set_target_properties(${layer} PROPERTIES EXPORT_NAME ${short})
endforeach()

# libnoneuclid.so links the layers: they are compiled position-independent for it (and so can go
# into any other shared library too). Without semantic interposition, g++ inlines and calls
# within a library as it does in an executable.
if(NONEUCLID_CAPI_SHARED)
    set_target_properties(${noneuclid_engine_layers} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    foreach(layer ${noneuclid_engine_layers})
        target_compile_options(${layer} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-fno-semantic-interposition>)
    endforeach()
endif()

set(noneuclid_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/noneuclid)
# The header-only libraries and the warning flags are in the export too: the static libraries
# name them (privately: a user's build sees no flag of theirs and needs no toml++).
install(TARGETS noneuclid_engine ${noneuclid_engine_layers} noneuclid_capi noneuclid_glm noneuclid_tomlpp noneuclid_warnings
        EXPORT noneuclidTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev)
if(NONEUCLID_CAPI_SHARED)
    install(TARGETS noneuclid_capi_shared EXPORT noneuclidTargets
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/noneuclid COMPONENT dev
                    PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ)  # (a library is not run)
endif()
install(FILES ${CMAKE_CURRENT_SOURCE_DIR}/capi/noneuclid.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT dev)
foreach(layer fixed geometry world files render lang)
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/${layer} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/noneuclid
            COMPONENT dev FILES_MATCHING PATTERN "*.hpp" PATTERN "toml_reader.hpp" EXCLUDE)  # (toml++'s, inside)
endforeach()
install(EXPORT noneuclidTargets NAMESPACE noneuclid:: DESTINATION ${noneuclid_cmake_dir}
        COMPONENT dev)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/noneuclidConfig.cmake.in
    ${PROJECT_BINARY_DIR}/noneuclidConfig.cmake INSTALL_DESTINATION ${noneuclid_cmake_dir})
# SameMinorVersion while the major version is 0 (a minor version may change the interface:
# docs/library.md), SameMajorVersion from 1.0.
if(PROJECT_VERSION_MAJOR EQUAL 0)
    set(noneuclid_compatibility SameMinorVersion)
else()
    set(noneuclid_compatibility SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/noneuclidConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY ${noneuclid_compatibility})
install(FILES ${PROJECT_BINARY_DIR}/noneuclidConfig.cmake ${PROJECT_BINARY_DIR}/noneuclidConfigVersion.cmake
        DESTINATION ${noneuclid_cmake_dir} COMPONENT dev)
