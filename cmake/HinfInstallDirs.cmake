# Where `cmake --install` puts the C++ package (headers, libhinf_core.a, the CMake package
# config) and hinf-sim, as paths relative to the install prefix.
#
# A plain install uses the GNU layout: include/hinf/, lib/libhinf_core.a,
# lib/cmake/hinf_cpp/ and bin/hinf-sim (lib/ may be lib64/ or lib/<multiarch>/, as
# GNUInstallDirs decides; find_package searches all of them).
#
# The wheel (scikit-build-core installs into the wheel's site-packages root) keeps the same
# tree inside the Python package, next to the extension: hinf_cpp/include/,
# hinf_cpp/lib/ and hinf_cpp/lib/cmake/hinf_cpp/, so that the package folder is an install
# prefix for CMAKE_PREFIX_PATH and hinf_cpp.cmake.get_cmake_dir() finds the config without
# searching. hinf-sim goes to the scripts folder, onto the environment's PATH.
include(GNUInstallDirs)
if(SKBUILD)
  set(HINF_INSTALL_INCLUDEDIR hinf_cpp/include)
  set(HINF_INSTALL_LIBDIR hinf_cpp/lib)
  set(HINF_INSTALL_BINDIR "${SKBUILD_SCRIPTS_DIR}")
else()
  set(HINF_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}")
  set(HINF_INSTALL_LIBDIR "${CMAKE_INSTALL_LIBDIR}")
  set(HINF_INSTALL_BINDIR "${CMAKE_INSTALL_BINDIR}")
endif()
set(HINF_INSTALL_CMAKEDIR "${HINF_INSTALL_LIBDIR}/cmake/hinf_cpp")
