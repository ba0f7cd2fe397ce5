# The third-party packages of hinf_core, all from Debian (see scripts/setup.sh), found through
# their CMake config files: the one list. The build calls hinf_find_dependencies(find_package);
# the installed package config (hinf_cppConfig.cmake, this file installed beside it) calls
# hinf_find_dependencies(find_dependency), since hinf_core is static and its dependencies link
# into the consumer's program.
macro(hinf_find_dependencies find)
  if("${find}" STREQUAL "find_package")
    set(_hinf_required REQUIRED)
  else()
    set(_hinf_required "")
  endif()
  cmake_language(CALL ${find} Eigen3 3.4 ${_hinf_required} NO_MODULE)
  cmake_language(CALL ${find} SUNDIALS 6.4 ${_hinf_required} COMPONENTS cvode nvecserial sunmatrixdense
                 sunlinsoldense sunnonlinsolfixedpoint)
  cmake_language(CALL ${find} tomlplusplus 3.3 ${_hinf_required})
  cmake_language(CALL ${find} nlohmann_json 3.11 ${_hinf_required})
  # LAPACK: the real Schur form (dgees) of the Riccati equations' Newton systems
  # (cpp/src/numerics/lyapunov_newton.cpp).
  cmake_language(CALL ${find} LAPACK ${_hinf_required})
  unset(_hinf_required)
endmacro()
