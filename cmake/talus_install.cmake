# What `cmake --install build --prefix P` puts under P, by component (cpack -G DEB makes a
# package of runtime and one of dev, cmake/talus_package.cmake):
#   runtime  bin/talus                                    the command line
#            lib/python3/dist-packages/talus/             the Python module, figures and studies
#                                                         included (python/CMakeLists.txt)
#            share/talus/examples/, share/doc/talus/      scenarios, the guide and the README
#   dev      lib/libtalus_core.a, include/talus/...       the engine for C++ users
#            lib/cmake/Talus/                             find_package(Talus) -> Talus::core
#   bench    bin/talus-bench, bin/talus-mpi-bench, bin/talus-comm-bench
include(CMakePackageConfigHelpers)

set(TALUS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Talus CACHE STRING "Where the Talus CMake package config is installed")

install(TARGETS talus RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
# Measuring tools for developers, left out of the packages: talus-bench caches its states
# beside the executable unless given --cache DIR.
if(TALUS_BUILD_BENCH)
  install(TARGETS talus-bench talus-mpi-bench talus-comm-bench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT bench)
endif()

# The engine: the static library and every header of src/talus but the three of the scenario
# reader that include toml++ (only its .cpp files use them), so that a program built against
# the installed headers needs no toml++.
set_target_properties(talus_core PROPERTIES EXPORT_NAME core)
install(TARGETS talus_core EXPORT TalusTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev)
install(DIRECTORY src/talus DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev
        FILES_MATCHING PATTERN "*.h"
        PATTERN "toml_include.h" EXCLUDE
        PATTERN "scenario_values.h" EXCLUDE
        PATTERN "scenario_file_impl.h" EXCLUDE)
install(EXPORT TalusTargets NAMESPACE Talus:: DESTINATION ${TALUS_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(cmake/TalusConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/TalusConfig.cmake
                              INSTALL_DESTINATION ${TALUS_CMAKE_DIR})
# 0.x: a minor version may change the engine's interface.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/TalusConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/TalusConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/TalusConfigVersion.cmake
        DESTINATION ${TALUS_CMAKE_DIR} COMPONENT dev)

install(DIRECTORY examples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/talus/examples COMPONENT runtime)
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(DIRECTORY docs DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)  # docs/: the README's links hold
