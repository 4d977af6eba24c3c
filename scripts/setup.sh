#!/usr/bin/env bash
# Shared set-up: installs the Debian packages the build needs (only the missing ones),
# then configures and builds Release into build/. Quiet when all is well; prints the
# errors (and where the full log is) when something fails. Idempotent and fast when
# everything is present: packages are checked with dpkg-query, configuration is reused,
# and the build is incremental.
#
# Environment:
#   DYNCONTACT_BUILD_DIR   build folder (default: build)
#   DYNCONTACT_JOBS        parallel build jobs (default: nproc)
#   DYNCONTACT_SKIP_APT=1  do not check or install packages
#   DYNCONTACT_WITH_FUZZ=1 also clang and libFuzzer (FUZZ_PACKAGES; scripts/fuzz.sh)
#   DYNCONTACT_BUILD_TARGET  what to build (default: all; scripts/run.sh builds dyncontact_programs,
#                          the program and the Python module, and leaves the tests to scripts/test.sh)
# Argument --packages-only: install the packages, do not configure or build.
#   DYNCONTACT_SKIP_PYTHON_INSTALL=1  do not install the Python module (cmake --install --component python,
#                                     then scripts/install_python_module.sh for the python3 on PATH)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${DYNCONTACT_BUILD_DIR:-build}"
JOBS="${DYNCONTACT_JOBS:-$(nproc 2>/dev/null || echo 2)}"

PACKAGES=(
  coinor-libipopt-dev libeigen3-dev libnlopt-dev libnlopt-cxx-dev libfftw3-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev gnuplot-nox
  pkg-config cmake g++ make
  libopenmpi-dev openmpi-bin
  python3-dev python3-pybind11 python3-numpy python3-pytest python3-matplotlib
  python3-vtk9  # VTK's Python (ParaView's reader): the tests open subsurface.vti as a user would
  libgmsh-dev libsuitesparse-dev  # finite-element bodies (DYNCONTACT_WITH_FE)
  libmetis-dev  # METIS orders the sparse saddle form for MUMPS (nlp/mumps_ordering_hook.hpp)
  libopenblas0-pthread  # an optimised BLAS for CHOLMOD and MUMPS (reference BLAS: 6x slower factorisations)
  time  # /usr/bin/time: peak memory in scripts/bench.sh finite
  ccache  # rebuilds reuse compiled objects (CMakeLists.txt uses it when found)
)
FUZZ_PACKAGES=(clang libclang-rt-dev)
if [[ "${DYNCONTACT_WITH_FUZZ:-0}" == 1 ]]; then PACKAGES+=("${FUZZ_PACKAGES[@]}"); fi

say() { printf 'setup: %s\n' "$*" >&2; }
die() { say "error: $*"; exit 1; }

install_missing_packages() {
  command -v dpkg-query >/dev/null 2>&1 || die "dpkg-query not found: this script expects Debian (or a derivative)"
  local missing=() p
  for p in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
      missing+=("$p")
    fi
  done
  [[ ${#missing[@]} -eq 0 ]] && return 0

  local sudo=()
  if [[ $(id -u) -ne 0 ]]; then
    if command -v sudo >/dev/null 2>&1; then
      # Without a terminal (CI) sudo must not wait for a password that nobody types.
      if [[ -t 0 ]]; then sudo=(sudo); else sudo=(sudo -n); fi
    else
      die "missing packages: ${missing[*]}; run as root or install sudo (apt-get install ${missing[*]})"
    fi
  fi
  say "installing missing packages: ${missing[*]}"
  local log
  log="$(mktemp)"
  if ! "${sudo[@]}" apt-get update -q >"$log" 2>&1 </dev/null; then
    cat "$log" >&2; rm -f "$log"; die "apt-get update failed"
  fi
  if ! "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${missing[@]}" \
      >"$log" 2>&1 </dev/null; then
    cat "$log" >&2; rm -f "$log"; die "apt-get install failed"
  fi
  rm -f "$log"
}

# Prints the interesting part of a failed configure/build log.
show_errors() {
  local log="$1"
  if [[ $(wc -l <"$log") -le 80 ]]; then
    cat "$log" >&2
  else
    grep -n -E -B2 -A8 '(error|Error|ERROR|undefined reference|No such file)' "$log" | head -n 200 >&2 || true
    echo '...' >&2
    tail -n 15 "$log" >&2
  fi
  say "full log: $log"
}

if [[ "${DYNCONTACT_SKIP_APT:-0}" != 1 ]]; then
  install_missing_packages
fi
if [[ "${1:-}" == --packages-only ]]; then exit 0; fi

mkdir -p "$BUILD_DIR"
LOG="$BUILD_DIR/setup.log"

# Configure once (again when the last configuration failed, or the cache belongs to another
# source tree or build type); later builds re-run CMake by themselves when a CMakeLists.txt
# or a globbed folder changes.
needs_configure=1
if [[ -f "$BUILD_DIR/CMakeCache.txt" && ( -f "$BUILD_DIR/Makefile" || -f "$BUILD_DIR/build.ninja" ) ]]; then
  home="$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$BUILD_DIR/CMakeCache.txt")"
  type="$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$BUILD_DIR/CMakeCache.txt")"
  if [[ "$home" -ef "$PWD" && "$type" == Release ]]; then needs_configure=0; fi
fi
if [[ $needs_configure -eq 1 ]]; then
  say "configuring $BUILD_DIR (Release)"
  if ! cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >"$LOG" 2>&1; then
    say "configuration failed"
    show_errors "$LOG"
    exit 1
  fi
fi

start=$SECONDS
if ! cmake --build "$BUILD_DIR" -j"$JOBS" --target "${DYNCONTACT_BUILD_TARGET:-all}" >"$LOG" 2>&1; then
  say "build failed"
  show_errors "$LOG"
  exit 1
fi
if (( SECONDS - start > 5 )); then say "built $BUILD_DIR in $((SECONDS - start)) s"; fi

# The Python module (when it was built) where python3 finds it: `import dyncontact` works
# afterwards (as root, or with write access to the prefix; DYNCONTACT_SKIP_PYTHON_INSTALL=1 skips).
if [[ "${DYNCONTACT_SKIP_PYTHON_INSTALL:-0}" != 1 ]] && grep -q '^DYNCONTACT_WITH_PYTHON:BOOL=ON' "$BUILD_DIR/CMakeCache.txt"; then
  if ! cmake --install "$BUILD_DIR" --component python >"$BUILD_DIR/install-python.log" 2>&1; then
    say "note: the Python module was not installed (see $BUILD_DIR/install-python.log); use PYTHONPATH=$BUILD_DIR/python"
  fi
  scripts/install_python_module.sh "$BUILD_DIR"
fi
