# ctest script (test installed_package_consumer, tests/cpp/CMakeLists.txt): installs the built
# project into a fresh prefix, checks the installed package, then configures, builds and runs
# the consumer project (tests/consumer) against it in a separate build tree.
#
# Variables (-D): BUILD_DIR, SOURCE_DIR (the project's), WORK_DIR (scratch, emptied first),
# CONFIG, GENERATOR, MAKE_PROGRAM, CXX_COMPILER (the project's, so that the consumer compiles
# and links like it), INCLUDEDIR and BINDIR (relative to the prefix), VERSION.
cmake_minimum_required(VERSION 3.20)
set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/consumer")
# A fresh prefix every run: a file left by an earlier install must not stand in for one that
# the install rules no longer install.
file(REMOVE_RECURSE "${WORK_DIR}")

execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}" --config "${CONFIG}"
                OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)

# The public headers are all installed, and every header they include ("hinf/...") is
# installed as well: none needs a private header of cpp/src.
# (cpp/include: one folder per layer; cpp/deprecated: the forwarding headers of the 0.1 paths).
file(GLOB_RECURSE public_headers RELATIVE "${SOURCE_DIR}/cpp/include" "${SOURCE_DIR}/cpp/include/hinf/*.hpp")
file(GLOB_RECURSE deprecated_headers RELATIVE "${SOURCE_DIR}/cpp/deprecated" "${SOURCE_DIR}/cpp/deprecated/hinf/*.hpp")
list(APPEND public_headers ${deprecated_headers})
file(GLOB_RECURSE installed_headers RELATIVE "${prefix}/${INCLUDEDIR}" "${prefix}/${INCLUDEDIR}/hinf/*.hpp")
set(not_installed "")
foreach(header IN LISTS public_headers)
  if(NOT header IN_LIST installed_headers)
    list(APPEND not_installed "${header}")
  endif()
endforeach()
if(not_installed)
  list(JOIN not_installed ", " not_installed)
  message(FATAL_ERROR "public headers of cpp/include not installed in ${prefix}/${INCLUDEDIR}: "
                      "${not_installed}")
endif()
foreach(header IN LISTS installed_headers)
  file(STRINGS "${prefix}/${INCLUDEDIR}/${header}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*$" "\\1" included "${line}")
    if(NOT EXISTS "${prefix}/${INCLUDEDIR}/${included}")
      message(FATAL_ERROR "${header} includes \"${included}\", which is not installed (a private header?)")
    endif()
  endforeach()
endforeach()

# The installed CMake files name nothing in the source or build tree: the package is whole
# without them, and relocatable (the wheel is unpacked anywhere).
file(GLOB_RECURSE cmake_files "${prefix}/*.cmake")
if(NOT cmake_files)
  message(FATAL_ERROR "no CMake package files installed under ${prefix}")
endif()
foreach(file IN LISTS cmake_files)
  file(READ "${file}" text)
  foreach(tree IN ITEMS "${SOURCE_DIR}" "${BUILD_DIR}")
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${file} refers to ${tree}")
    endif()
  endforeach()
endforeach()

execute_process(COMMAND "${prefix}/${BINDIR}/hinf-sim" --version OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)

# The consumer asks for C++14: hinf_cpp::hinf_core must raise it to the C++17 its headers need
# (the compile feature cxx_std_17 travels with the target).
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/tests/consumer" -B "${consumer_build}"
                        -G "${GENERATOR}" "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}"
                        "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${CONFIG}"
                        -DCMAKE_CXX_STANDARD=14 "-DCMAKE_PREFIX_PATH=${prefix}"
                        "-DHINF_CPP_VERSION=${VERSION}"
                COMMAND_ERROR_IS_FATAL ANY)
# find_package took the package just installed (not one installed elsewhere on the machine).
file(STRINGS "${consumer_build}/CMakeCache.txt" found REGEX "^hinf_cpp_DIR:")
string(REGEX REPLACE "^[^=]*=" "" found "${found}")
file(REAL_PATH "${found}" found)
file(REAL_PATH "${prefix}" real_prefix)
string(FIND "${found}" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "find_package(hinf_cpp) found ${found}, not the package installed in ${prefix}")
endif()

execute_process(COMMAND "${CMAKE_COMMAND}" --build "${consumer_build}" --config "${CONFIG}"
                COMMAND_ERROR_IS_FATAL ANY)
set(consumer "${consumer_build}/hinf_consumer")
if(NOT EXISTS "${consumer}")  # multi-configuration generators build into a folder per configuration
  set(consumer "${consumer_build}/${CONFIG}/hinf_consumer")
endif()
execute_process(COMMAND "${consumer}" COMMAND_ERROR_IS_FATAL ANY)
