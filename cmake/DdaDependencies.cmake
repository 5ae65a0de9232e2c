# All dependencies come from Debian packages (scripts/install-deps.sh).
# Target names and the pitfalls below are explained in docs/toolchain.md.

# Eigen before CGAL and with NO_MODULE: CGAL's find-modules shadow Eigen's config.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(CGAL 5.5 REQUIRED)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(OpenMP REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(tinyxml2 REQUIRED)

# CHOLMOD has no CMake config in Debian 12; find_package(SuiteSparse) is
# answered wrongly by CGAL's old module, so build a small imported target.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
if(NOT TARGET dda::cholmod)
  add_library(dda::cholmod INTERFACE IMPORTED)
  set_target_properties(dda::cholmod PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARY};${SUITESPARSECONFIG_LIBRARY}")
endif()

if(DDA_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(DDA_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
