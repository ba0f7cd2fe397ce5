# ctest script (tests/cpp/CMakeLists.txt): `hinf-sim --version` exits 0 and prints
# "hinf-sim <the VERSION file>" and nothing else.
#   cmake -DHINF_SIM=<hinf-sim> -DVERSION_FILE=<VERSION> -P HinfSimVersionTest.cmake
cmake_minimum_required(VERSION 3.20)
file(READ "${VERSION_FILE}" expected)
string(STRIP "${expected}" expected)
execute_process(COMMAND "${HINF_SIM}" --version RESULT_VARIABLE status OUTPUT_VARIABLE output
                ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "hinf-sim --version exited with ${status}: ${errors}")
endif()
if(NOT output STREQUAL "hinf-sim ${expected}\n")
  message(FATAL_ERROR "hinf-sim --version printed '${output}', expected 'hinf-sim ${expected}' (VERSION)")
endif()
