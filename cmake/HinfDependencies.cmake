# Third-party packages, all from Debian (see scripts/setup.sh), found through their CMake config files.
# The installed package config (cmake/hinf_cppConfig.cmake.in) finds the same ones for consumers
# of the static hinf_core: keep the two lists in step.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(SUNDIALS 6.4 REQUIRED COMPONENTS cvode nvecserial sunmatrixdense sunlinsoldense
             sunnonlinsolfixedpoint)
find_package(tomlplusplus 3.3 REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
# LAPACK: the real Schur form (dgees) and the triangular Sylvester solve (dtrsyl) of the
# Riccati equations' Newton systems (cpp/src/lyapunov_newton.cpp).
find_package(LAPACK REQUIRED)
