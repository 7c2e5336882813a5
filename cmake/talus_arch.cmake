# The CPU the binaries are built for. The default is the compiler's portable baseline
# (x86-64 here): the build runs on any CPU of its architecture, so a package built on one
# machine starts on every other. Two ways to ask for more:
# - TALUS_ARCH=x86-64-v2|x86-64-v3|x86-64-v4 builds for a micro-architecture level
#   (-march=LEVEL; v3 brings AVX2 and FMA, v4 AVX-512), e.g. a package for the machines of
#   one cluster;
# - TALUS_NATIVE=ON tunes for the building machine (-march=native).
# The sphere batch, the step end and the pair listing take their AVX2 or AVX-512 paths only
# when the level allows them. A binary built for a level does not start on an older CPU, and
# bit-exact restarts need the same binary (its floating-point operations may be fused).
option(TALUS_NATIVE "Tune for this machine's CPU (-march=native)" OFF)
set(TALUS_ARCH "" CACHE STRING "Micro-architecture level to build for: empty (portable), x86-64-v2, x86-64-v3 or x86-64-v4")
set(TALUS_ARCH_LEVELS x86-64 x86-64-v2 x86-64-v3 x86-64-v4)
set_property(CACHE TALUS_ARCH PROPERTY STRINGS "" ${TALUS_ARCH_LEVELS})

if(TALUS_NATIVE AND NOT TALUS_ARCH STREQUAL "")
  message(FATAL_ERROR "TALUS_NATIVE=ON and TALUS_ARCH=${TALUS_ARCH} ask for two CPUs; set one of them")
endif()
if(TALUS_NATIVE)
  add_compile_options(-march=native)
elseif(NOT TALUS_ARCH STREQUAL "")
  if(NOT TALUS_ARCH IN_LIST TALUS_ARCH_LEVELS)
    list(JOIN TALUS_ARCH_LEVELS ", " levels)
    message(FATAL_ERROR "TALUS_ARCH=${TALUS_ARCH} is not a level Talus builds for; use one of: ${levels} (or leave it empty for the portable baseline)")
  endif()
  include(CheckCXXCompilerFlag)
  string(MAKE_C_IDENTIFIER "TALUS_COMPILER_HAS_${TALUS_ARCH}" accepted)
  check_cxx_compiler_flag(-march=${TALUS_ARCH} ${accepted})
  if(NOT ${accepted})
    message(FATAL_ERROR "TALUS_ARCH=${TALUS_ARCH}: ${CMAKE_CXX_COMPILER} does not accept -march=${TALUS_ARCH} (GCC 11 and Clang 12 are the first that do)")
  endif()
  add_compile_options(-march=${TALUS_ARCH})
endif()
