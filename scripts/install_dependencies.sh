#!/usr/bin/env bash
# Installs the Debian 12 packages needed to build, test, benchmark and document
# Triangular_spline. Prints nothing when everything is already installed.
# With --fuzz, also clang and libFuzzer (`make fuzz`): libclang-rt-14-dev holds
# libclang_rt.fuzzer and the sanitizer runtimes; clang only recommends it.
set -euo pipefail

packages=(cmake g++ make libcgal-dev libeigen3-dev libgtest-dev libbenchmark-dev libpng-dev
          libcli11-dev nlohmann-json3-dev
          python3-dev python3-numpy pybind11-dev python3-pybind11 python3-pytest
          doxygen libjs-mathjax clang-format)
if [[ ${1:-} == --fuzz ]]; then
  packages+=(clang libclang-rt-14-dev)
elif [[ $# -gt 0 ]]; then
  echo "usage: install_dependencies.sh [--fuzz]" >&2
  exit 2
fi

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  if [[ "$status" != "install ok installed" ]]; then
    missing+=("$package")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

if [[ $(id -u) -eq 0 ]]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "install_dependencies.sh: missing packages (${missing[*]}) and neither root nor sudo available" >&2
  exit 1
fi

echo "install_dependencies.sh: installing ${missing[*]}"
"${as_root[@]}" apt-get update
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"
