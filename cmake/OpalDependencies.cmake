# Every dependency of Opal's libraries, tools and tests, found once, here. A missing one
# stops the configure step with a message naming the Debian package that provides it
# (scripts/setup installs them). The viewer's own dependencies (OpenGL, GLFW, Dear ImGui,
# glad) are not among them: OpalViewerDependencies.cmake looks for them where the viewer's
# target is defined, so a headless build needs none of them.

function(opal_require found name package)
  if(NOT ${found})
    message(FATAL_ERROR "Opal needs ${name}: install the Debian package '${package}' (or run scripts/setup)")
  endif()
endfunction()

# Opal::<name>, an imported target for a library found by its header and library file (for
# packages whose CMake config is missing or broken); sets <name>_FOUND.
function(opal_import_library name header library)
  find_path(${name}_INCLUDE_DIR ${header})
  find_library(${name}_LIBRARY ${library})
  if(${name}_INCLUDE_DIR AND ${name}_LIBRARY)
    add_library(Opal::${name} UNKNOWN IMPORTED GLOBAL)
    set_target_properties(Opal::${name} PROPERTIES
      IMPORTED_LOCATION "${${name}_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${${name}_INCLUDE_DIR}")
    set(${name}_FOUND TRUE PARENT_SCOPE)
  endif()
endfunction()

find_package(PkgConfig QUIET)
opal_require(PkgConfig_FOUND "pkg-config" "pkg-config")

# OpenSubdiv: its packaged CMake config names static libraries that Debian does not ship,
# so find_package fails fatally; find the header and library ourselves.
opal_import_library(OpenSubdiv opensubdiv/far/topologyRefiner.h osdCPU)
opal_require(OpenSubdiv_FOUND "OpenSubdiv" "libosd-dev")

# OpenColorIO: the CMake config computes a wrong include prefix; pkg-config is right.
pkg_check_modules(OCIO QUIET IMPORTED_TARGET OpenColorIO)
opal_require(OCIO_FOUND "OpenColorIO" "libopencolorio-dev")
add_library(Opal::OpenColorIO ALIAS PkgConfig::OCIO)

# OpenImageIO: its target lists /usr/include/opencv4 although OpenCV is not a dependency.
find_package(OpenImageIO CONFIG QUIET)
opal_require(OpenImageIO_FOUND "OpenImageIO" "libopenimageio-dev")
foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  get_target_property(dirs OpenImageIO::OpenImageIO ${prop})
  if(dirs)
    list(FILTER dirs EXCLUDE REGEX "opencv4")
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${prop} "${dirs}")
  endif()
endforeach()

find_package(Imath CONFIG QUIET)
opal_require(Imath_FOUND "Imath" "libimath-dev")
find_package(OpenEXR CONFIG QUIET)
opal_require(OpenEXR_FOUND "OpenEXR" "libopenexr-dev")

find_package(embree 3.13 CONFIG QUIET)
opal_require(embree_FOUND "Embree 3" "libembree-dev")

# oneTBB: link TBB::tbb only; TBB::tbbbind has a broken hwloc dependency on Debian 12.
find_package(TBB CONFIG QUIET COMPONENTS tbb)
opal_require(TBB_FOUND "oneTBB" "libtbb-dev")

find_package(Eigen3 CONFIG QUIET)
opal_require(Eigen3_FOUND "Eigen" "libeigen3-dev")
find_package(zstd CONFIG QUIET)
opal_require(zstd_FOUND "zstd" "libzstd-dev")

# xxHash (the sidecar's XXH64 checksums) ships no CMake config: find its header and library.
opal_import_library(xxhash xxhash.h xxhash)
opal_require(xxhash_FOUND "xxHash" "libxxhash-dev")
find_package(nlohmann_json CONFIG QUIET)
opal_require(nlohmann_json_FOUND "nlohmann-json" "nlohmann-json3-dev")
find_package(CLI11 CONFIG QUIET)
opal_require(CLI11_FOUND "CLI11" "libcli11-dev")
find_package(assimp CONFIG QUIET)
opal_require(assimp_FOUND "Assimp" "libassimp-dev")

find_package(GTest CONFIG QUIET)
opal_require(GTest_FOUND "GoogleTest" "libgtest-dev")

if(TARGET zstd::libzstd_shared)
  add_library(Opal::zstd ALIAS zstd::libzstd_shared)
else()
  add_library(Opal::zstd ALIAS zstd::libzstd_static)
endif()
