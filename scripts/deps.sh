#!/usr/bin/env bash
# Installs the Debian packages rollwear needs, and nothing else. Quiet when all are present.
#   bash scripts/deps.sh        check and install (as root), or print the command to run
#   source scripts/deps.sh      defines rollwear_deps; scripts/test and scripts/run call it
# Root runs apt-get itself; anyone else gets the exact sudo command and exit status 1.
# Nothing is downloaded except Debian packages. Before installing it says how many packages (the missing
# ones and what they pull in: apt-get's simulation) and how large the download and the install are; then a
# line per step (update, install), apt-get's own output going to a log file (ROLLWEAR_DEPS_LOG, default
# ${TMPDIR:-/tmp}/rollwear-deps.log), whose last lines are shown if a step fails.

ROLLWEAR_DEB_PACKAGES=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev libsundials-dev libyaml-cpp-dev libspdlog-dev libcli11-dev
  libfftw3-dev                   # half-space normal solver (found through pkg-config)
  gnuplot-nox                    # rollwear plot
  libgtest-dev libbenchmark-dev  # tests; benchmarks (tests/bench)
  clang libclang-rt-14-dev       # the YAML fuzzer (scripts/fuzz: clang's libFuzzer)
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib  # the Python bindings (python/)
)

# one step of the set-up: its output to the log, one line on stderr; on failure the log's last lines
_rollwear_step() {
  local what="$1" log="$2" started=$SECONDS
  shift 2
  echo "== $what" >>"$log"
  if "$@" >>"$log" 2>&1; then
    echo "rollwear: $what: done ($((SECONDS - started)) s)" >&2
    return 0
  fi
  echo "rollwear: $what failed; the last lines of $log:" >&2
  tail -n 20 "$log" >&2
  return 1
}

rollwear_deps() {
  local missing=() pkg status
  for pkg in "${ROLLWEAR_DEB_PACKAGES[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
  done
  ((${#missing[@]} == 0)) && return 0

  echo "rollwear: missing Debian packages: ${missing[*]}" >&2
  if [[ $(id -u) -eq 0 ]]; then
    local log="${ROLLWEAR_DEPS_LOG:-${TMPDIR:-/tmp}/rollwear-deps.log}" started count sizes
    : > "$log" || { echo "rollwear: cannot write the log $log" >&2; return 1; }
    echo "rollwear: apt-get's output goes to $log" >&2
    _rollwear_step "apt-get update" "$log" apt-get update || return 1
    # the size before the install: the packages the simulation would unpack, apt's download and disk figures
    count=$(apt-get -s install --no-install-recommends "${missing[@]}" 2>>"$log" | grep -c '^Inst ' || true)
    sizes=$(apt-get install --assume-no --no-install-recommends "${missing[@]}" 2>>"$log" |
      sed -n -e 's/^Need to get \([^ ]* [^ ]*\).*/download \1/p' \
             -e 's/^After this operation, \([^ ]* [^ ]*\) of additional disk space.*/\1 on disk/p' | paste -sd, - |
      sed 's/,/, /g' || true)
    echo "rollwear: installing ${count:-?} packages (${#missing[@]} asked for, the rest their dependencies)${sizes:+: $sizes}" >&2
    started=$SECONDS
    _rollwear_step "apt-get install" "$log" env DEBIAN_FRONTEND=noninteractive \
      apt-get install -y --no-install-recommends "${missing[@]}" || return 1
    echo "rollwear: installed in $((SECONDS - started)) s" >&2
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
