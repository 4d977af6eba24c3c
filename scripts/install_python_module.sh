#!/usr/bin/env bash
# Makes `python3 -c "import dyncontact"` work for the python3 first on PATH, then checks it.
#   scripts/install_python_module.sh [BUILD_DIR]      (run by scripts/setup.sh)
# `cmake --install --component python` puts the module where the interpreter it was built for
# (Debian's /usr/bin/python3) finds it. When python3 on PATH is another interpreter (pyenv,
# a virtual environment) of the same Python version, or cannot import the module yet (the
# install folder was not writable), the module is copied into that interpreter's own
# site-packages (its sysconfig platlib, else its user site); without NumPy of its own, that
# interpreter imports the NumPy of the one the module was built for. Another Python version
# cannot load the module: the check says so and how to go on.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR="${1:-${DYNCONTACT_BUILD_DIR:-build}}"

say() { printf 'setup: %s\n' "$*" >&2; }

module="$(ls "$BUILD_DIR"/python/dyncontact.*.so 2>/dev/null | head -n 1 || true)"
[[ -n "$module" ]] || { say "note: no Python module in $BUILD_DIR/python (built without python3-dev, pybind11 or NumPy)"; exit 0; }
built_for="$(sed -n 's/^_\{0,1\}Python3_EXECUTABLE:[A-Z]*=//p' "$BUILD_DIR/CMakeCache.txt" | head -n 1)"
built_for="${built_for:-/usr/bin/python3}"
command -v python3 >/dev/null 2>&1 || { say "note: no python3 on PATH; the module is built for $built_for"; exit 0; }

# The interpreter behind `python3` (through shims), its extension suffix and install folders.
read -r py suffix platlib usersite < <(python3 -c '
import site, sys, sysconfig
print(sys.executable, sysconfig.get_config_var("EXT_SUFFIX"), sysconfig.get_paths()["platlib"],
      site.getusersitepackages() if site.ENABLE_USER_SITE else "-")')
# Another installation (its own prefix: pyenv, a virtual environment) needs its own copy; so does
# the same one when `cmake --install` could not write its folder (not root: the user site).
built_prefix="$("$built_for" -c 'import sys; print(sys.prefix)' 2>/dev/null || true)"
py_prefix="$(python3 -c 'import sys; print(sys.prefix)')"
needs_copy=0
if [[ "$module" == *"$suffix" ]]; then
  if [[ "$py_prefix" != "$built_prefix" ]] || ! (cd / && python3 -c 'import dyncontact' >/dev/null 2>&1); then
    needs_copy=1
  fi
fi

if [[ $needs_copy -eq 1 ]]; then
  dest="$platlib"
  if ! mkdir -p "$dest" 2>/dev/null || [[ ! -w "$dest" ]]; then dest="$usersite"; fi
  if [[ "$dest" != - ]] && mkdir -p "$dest" 2>/dev/null && cp -f "$module" "$dest/"; then
    say "installed the Python module for $py into $dest"
  else
    say "note: could not write the Python module into $platlib or the user site of $py"
  fi
fi

if ! err="$(cd / && python3 -c 'import dyncontact' 2>&1)"; then
  say "note: \`python3 -c \"import dyncontact\"\` fails for $py:"
  printf '%s\n' "$err" | tail -n 1 >&2
  if [[ "$module" != *"$suffix" ]]; then
    say "  the module is built for $built_for (${module##*/}), python3 on PATH is another Python version."
  fi
  say "  use $built_for, or PYTHONPATH=$BUILD_DIR/python with that interpreter, or rebuild for this one:"
  say "  cmake -S . -B $BUILD_DIR -DPython3_EXECUTABLE=\$(command -v python3) (needs its headers, NumPy 1.x and pybind11)"
  exit 0
fi
