#!/bin/bash
# scripts/deps.sh as root with a package missing, against stand-ins for dpkg-query, id and apt-get (nothing is
# installed): it says how many packages and how large before the install, prints a line per step, and keeps
# apt-get's output (here 1300 lines) in its log; a failing step shows the log's last lines (ctest scripts.deps).
# Usage: deps_test.sh SOURCE_DIR
set -u
source_dir="$1"
fake="$(mktemp -d)"
trap 'rm -rf "$fake"' EXIT
cat > "$fake/dpkg-query" <<'X'
#!/bin/sh
for a; do last="$a"; done
[ "$last" = gnuplot-nox ] && { echo "unknown ok not-installed"; exit 0; }
echo "install ok installed"
X
cat > "$fake/id" <<'X'
#!/bin/sh
echo 0
X
cat > "$fake/apt-get" <<'X'
#!/bin/sh
case "$*" in
  update) i=0; while [ $i -lt 300 ]; do echo "Get:$i http://deb.debian.org bookworm InRelease"; i=$((i+1)); done ;;
  "-s install"*) echo "Reading package lists..."; echo "Inst gnuplot-nox (5.4)"; echo "Inst libcairo2 (1.16)";
                 echo "Inst liblua5.4-0 (5.4)"; echo "Conf gnuplot-nox (5.4)" ;;
  *--assume-no*) echo "Need to get 12.3 MB of archives."
                 echo "After this operation, 45.6 MB of additional disk space will be used."; echo "Abort."; exit 1 ;;
  *install\ -y*) [ -n "${FAIL_INSTALL:-}" ] && { echo "E: Unable to fetch some archives"; exit 100; }
                 i=0; while [ $i -lt 1000 ]; do echo "Unpacking package $i ..."; i=$((i+1)); done ;;
esac
X
chmod +x "$fake"/*
log="$fake/deps.log"
out="$(PATH="$fake:$PATH" ROLLWEAR_DEPS_LOG="$log" bash "$source_dir/scripts/deps.sh" 2>&1)" || { echo "$out"; exit 1; }
echo "$out"
fail() { echo "deps_test: $*" >&2; exit 1; }
[ "$(printf '%s\n' "$out" | wc -l)" -le 6 ] || fail "more than 6 lines"
printf '%s\n' "$out" | grep -q "installing 3 packages (1 asked for, the rest their dependencies): download 12.3 MB, 45.6 MB on disk" ||
  fail "no size line before the install"
printf '%s\n' "$out" | grep -q "apt-get install: done" || fail "no install line"
[ "$(wc -l < "$log")" -ge 1300 ] || fail "the log lacks apt-get's output"
# a failing install: its message from the log, status 1
out="$(PATH="$fake:$PATH" FAIL_INSTALL=1 ROLLWEAR_DEPS_LOG="$log" bash "$source_dir/scripts/deps.sh" 2>&1)" && fail "a failed install gave status 0"
printf '%s\n' "$out" | grep -q "E: Unable to fetch some archives" || fail "the failure's message not shown: $out"
echo "deps_test: ok"
