#!/usr/bin/env bash
# Installs the Debian packages rollwear needs, and nothing else. Quiet when all are present.
#   bash scripts/deps.sh        check and install (as root), or print the command to run
#   source scripts/deps.sh      defines rollwear_deps; scripts/test and scripts/run call it
# Root runs apt-get itself; anyone else gets the exact sudo command and exit status 1.
# Nothing is downloaded except Debian packages.

ROLLWEAR_DEB_PACKAGES=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev libsundials-dev libyaml-cpp-dev libspdlog-dev libcli11-dev
  libfftw3-dev                   # half-space normal solver (found through pkg-config)
  gnuplot-nox                    # rollwear plot
  libgtest-dev libbenchmark-dev  # tests; benchmarks (tests/bench)
  clang libclang-rt-14-dev       # the YAML fuzzer (scripts/fuzz: clang's libFuzzer)
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib  # the Python bindings (python/)
)

rollwear_deps() {
  local missing=() pkg status
  for pkg in "${ROLLWEAR_DEB_PACKAGES[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
  done
  ((${#missing[@]} == 0)) && return 0

  echo "rollwear: missing Debian packages: ${missing[*]}" >&2
  if [[ $(id -u) -eq 0 ]]; then
    apt-get update
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
  else
    echo "rollwear: run this, then try again:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y --no-install-recommends ${missing[*]}" >&2
    return 1
  fi
}

# run directly: do the check; sourced: only define the function
if [[ "${BASH_SOURCE[0]}" == "$0" ]]; then
  set -euo pipefail
  rollwear_deps
fi
