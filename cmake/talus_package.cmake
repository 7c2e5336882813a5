# cpack -G DEB in the build folder: two Debian packages for /usr, from the install components
# of cmake/talus_install.cmake:
#   talus      the command line, the Python module, the tools, examples and docs;
#   talus-dev  the library, headers and CMake package config; it depends on talus and on the
#              -dev packages whose targets Talus::core links.
# The library dependencies of the executables and the Python extension come from
# dpkg-shlibdeps (Debian dpkg-dev; CPack picks the files for it with `file`) when both are
# there; without them they are written out below as Debian 12 names them.
set(CPACK_PACKAGE_NAME talus)
set(CPACK_PACKAGE_VENDOR "Talus")
set(CPACK_PACKAGE_CONTACT "Talus developers <talus@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Discrete element method engine for granular flows")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)  # the benchmarks stay out (cmake/talus_install.cmake)
set(CPACK_COMPONENT_DEV_DEPENDS runtime)  # talus-dev: Depends talus (= version)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # talus_0.1.0_amd64.deb, talus-dev_0.1.0_amd64.deb
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "Discrete element method engine for granular flows
Talus simulates spheres and rigid non-spherical bodies with spring-dashpot contacts over
walls, rough bases and periodic boxes, on threads (OpenMP) and ranks (MPI), and measures
collapsing columns, hoppers and chute flows. This package holds the talus command line, the
talus Python module, the example scenarios and the documentation.")
set(CPACK_COMPONENT_DEV_DESCRIPTION "Discrete element method engine for granular flows - C++ library
The Talus engine as a static library with its headers and a CMake package:
find_package(Talus) and target_link_libraries(app PRIVATE Talus::core).")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME talus)
set(CPACK_DEBIAN_DEV_PACKAGE_NAME talus-dev)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)

find_program(TALUS_DPKG_SHLIBDEPS dpkg-shlibdeps)
find_program(TALUS_FILE_COMMAND file)
if(TALUS_DPKG_SHLIBDEPS AND TALUS_FILE_COMMAND)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
  set(talus_library_depends "")
else()
  set(talus_library_depends "libc6, libstdc++6, libgcc-s1, libgomp1, libhdf5-103-1, libopenmpi3, libqhull-r8.0")
endif()
# Beyond the libraries: the interpreter and NumPy of the Python module (python/CMakeLists.txt),
# matplotlib for `talus plot`.
set(talus_runtime_depends ${talus_library_depends} ${TALUS_PYTHON_DEB_DEPENDS} "python3-matplotlib")
list(FILTER talus_runtime_depends EXCLUDE REGEX "^$")
list(JOIN talus_runtime_depends ", " CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS)
# `talus render` (VTK), `talus fit` (SciPy), runs over ranks (mpirun) and studies over ranks (mpi4py).
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "python3-vtk9, python3-scipy, openmpi-bin, python3-mpi4py")
# What find_package(Talus) finds for Talus::core (cmake/TalusConfig.cmake.in).
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "libeigen3-dev, nlohmann-json3-dev, libqhull-dev, libhdf5-dev, libopenmpi-dev, pkg-config")
set(CPACK_DEBIAN_DEV_PACKAGE_SUGGESTS "cmake, g++")

include(CPack)
