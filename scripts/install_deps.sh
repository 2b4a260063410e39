#!/usr/bin/env bash
# Installs the Debian packages lrsvo needs to build, test and plot, and only the
# missing ones: when everything is present it touches nothing (no apt-get at all),
# so it is safe to run before every build.
#
# Usage: scripts/install_deps.sh [extra-package ...]   (e.g. clang-format for `make format`)
set -euo pipefail

packages=(
  build-essential cmake ninja-build
  libeigen3-dev libsuitesparse-dev libceres-dev libopencv-dev
  libnlopt-dev libnlopt-cxx-dev
  libcli11-dev nlohmann-json3-dev libyaml-cpp-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-matplotlib python3-numpy
  python3-dev pybind11-dev python3-pybind11 python3-pytest
  "$@"
)

if ! command -v dpkg >/dev/null 2>&1; then
  echo "install_deps: not a Debian system; install these (or their equivalents) yourself: ${packages[*]}" >&2
  exit 0
fi

missing=()
for package in "${packages[@]}"; do
  # `dpkg -s` also succeeds for removed packages whose config files remain, so check the status line.
  if ! dpkg -s "$package" 2>/dev/null | grep -q '^Status: install ok installed$'; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install_deps: all ${#packages[@]} Debian packages are installed"
  exit 0
fi

# sudo drops the environment, so the non-interactive frontend goes on the command line.
apt=(env DEBIAN_FRONTEND=noninteractive apt-get)
if ((EUID != 0)); then
  if ! command -v sudo >/dev/null 2>&1; then
    echo "install_deps: missing packages ${missing[*]}; run this script as root to install them" >&2
    exit 1
  fi
  apt=(sudo "${apt[@]}")
fi

echo "install_deps: installing ${missing[*]}"
"${apt[@]}" update </dev/null
"${apt[@]}" install -y --no-install-recommends "${missing[@]}" </dev/null
