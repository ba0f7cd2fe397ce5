"""The C++ package that the wheel carries, for CMake projects building against it.

The wheel installs the C++ library next to this module: the headers (``include/hinf``), the
static library ``lib/libhinf_core.a`` and its CMake package (``lib/cmake/hinf_cpp``), so that

    find_package(hinf_cpp CONFIG REQUIRED)
    target_link_libraries(app PRIVATE hinf_cpp::hinf_core)

works with ``-Dhinf_cpp_DIR="$(python -m hinf_cpp.cmake)"`` (or with CMAKE_PREFIX_PATH set to
the package folder). The library's dependencies (Eigen, SUNDIALS, toml++, nlohmann-json) are
not in the wheel: the package config finds them on the system, as the build did
(scripts/setup.sh installs them on Debian)."""

from __future__ import annotations

import pathlib


def get_cmake_dir() -> str:
    """The folder holding hinf_cppConfig.cmake (the value for hinf_cpp_DIR).

    Raises FileNotFoundError when the package was not installed from a wheel (a source
    checkout on PYTHONPATH has no built library)."""
    cmake_dir = pathlib.Path(__file__).resolve().parent / "lib" / "cmake" / "hinf_cpp"
    if not (cmake_dir / "hinf_cppConfig.cmake").is_file():
        raise FileNotFoundError(f"no hinf_cppConfig.cmake in {cmake_dir}: the C++ package comes with "
                                "the installed wheel (pip install .), not with the source tree")
    return str(cmake_dir)


if __name__ == "__main__":
    print(get_cmake_dir())
