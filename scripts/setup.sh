#!/usr/bin/env bash
# Makes a fresh Debian 12 machine ready: the system packages (apt), a Python virtual
# environment in .venv with the build and test tools, and the hinf_cpp package itself
# (the Python module and the hinf-sim executable, installed into .venv/bin).
# Safe to run again: it installs only what is missing and rebuilds incrementally.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

APT_PACKAGES=(build-essential pkg-config libeigen3-dev libsundials-dev liblapack-dev libtomlplusplus-dev
              nlohmann-json3-dev libgtest-dev python3-venv)
missing=()
for package in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if ((${#missing[@]})); then
  echo "setup: installing system packages: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

PYTHON="${PYTHON:-python3.11}"
command -v "$PYTHON" >/dev/null 2>&1 || PYTHON=python3
if [ ! -x .venv/bin/python ]; then
  echo "setup: creating the virtual environment .venv ($("$PYTHON" --version))"
  "$PYTHON" -m venv .venv
fi
.venv/bin/python -m pip install -q --disable-pip-version-check -r requirements-dev.txt
echo "setup: building and installing hinf_cpp (incremental build in build/)"
.venv/bin/python -m pip install -q --disable-pip-version-check --no-build-isolation .
