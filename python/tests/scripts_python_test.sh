#!/bin/sh
# scripts/python runs the interpreter the module was built for, whatever python3 comes first on PATH: here a
# stand-in for a pyenv or virtualenv python3 without NumPy, which fails if it is the one run (ctest
# python.script). Usage: scripts_python_test.sh SOURCE_DIR BUILD_DIR
set -u
source_dir="$1"
build_dir="$2"
fake="$(mktemp -d)"
trap 'rm -rf "$fake"' EXIT
printf '#!/bin/sh\necho "the python3 first on PATH ran: not the module'"'"'s" >&2\nexit 7\n' > "$fake/python3"
chmod +x "$fake/python3"
cd "$source_dir" || exit 1
ran="$(PATH="$fake:$PATH" ROLLWEAR_BUILD_DIR="$build_dir" "$source_dir/scripts/python" -c \
  'import sys, numpy, rollwear; r = rollwear.contact("cases/paper.yaml", fields=False); print(sys.executable)')" || exit 1
# the interpreter CMake recorded, which has NumPy, ran
recorded="$(cat "$build_dir/python/interpreter")"
if [ "$ran" != "$recorded" ]; then
  echo "scripts/python ran '$ran', not the interpreter the module was built for, '$recorded'" >&2
  exit 1
fi
echo "scripts/python ran $ran"
