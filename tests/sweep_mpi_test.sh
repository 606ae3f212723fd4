#!/bin/sh
# rollwear sweep under MPI (built with -DROLLWEAR_MPI=ON; docs/sweeps.md "MPI"): mpirun -np 2 and -np 3
# (--oversubscribe: more ranks than cores) give the table and summary the threaded run gives, byte for byte.
# With 2 ranks rank 0 only deals, so every case ran on rank 1: a table with every row shows the dealing.
#   sh tests/sweep_mpi_test.sh EXE SOURCE_DIR [SWEEP]
# Without SWEEP: a 6-case sweep of the paper's worn roller on a coarse grid (the suite's, 2.5 s); with it,
# that sweep file (scripts/test mpi: the shipped cases/sweep-grid.yaml and cases/sweep-contact.yaml).
set -eu
exe=$1
src=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # as root: mpirun --allow-run-as-root
if [ $# -ge 3 ]; then
  sweep=$3
else
  # the paper's worn roller on a coarse grid, to a 20 um depth (about 20 ms a life), 6 cases
  sed -e 's/nx: 80, ny: 80/nx: 16, ny: 16/' -e 's/max_depth_m: 1.0e-4/max_depth_m: 2.0e-5/' \
      -e '/snapshots_revolutions/d' -e '/^output/d' "$src/cases/paper-wear.yaml" > "$dir/base.yaml"
  cat > "$dir/sweep.yaml" <<'END'
base: base.yaml
axes:
  - { key: load.normal_load_N, values: [1000, 2000] }
  - { key: wear.body1.archard_k, log: { from: 1.0e-5, to: 1.0e-4, count: 3 } }
END
  sweep=$dir/sweep.yaml
fi
"$exe" --log-level warn sweep "$sweep" -o "$dir/threads" -j 2 -q > /dev/null
cases=$(($(wc -l < "$dir/threads/results.csv") - 1))
for n in 2 3; do
  mpirun -np $n --oversubscribe "$exe" --log-level info sweep "$sweep" -o "$dir/mpi$n" -q > /dev/null 2> "$dir/log$n"
  cmp "$dir/threads/results.csv" "$dir/mpi$n/results.csv"
  cmp "$dir/threads/summary.txt" "$dir/mpi$n/summary.txt"
  # the other ranks ran the cases between them (rank 0 deals only)
  ran=$(sed -n 's/.*sweep: rank [0-9]* ran \([0-9]*\) cases.*/\1/p' "$dir/log$n" | awk '{s += $1} END {print s + 0}')
  ranks=$(grep -c "sweep: rank [0-9]* ran" "$dir/log$n" || true)
  if [ "$ran" -ne "$cases" ] || [ "$ranks" -ne $((n - 1)) ]; then
    echo "mpirun -np $n: $ranks ranks ran $ran cases, expected $((n - 1)) ranks and $cases cases:"; cat "$dir/log$n"; exit 1
  fi
done
echo "mpirun -np 2 and -np 3: $cases cases of $(basename "$sweep"), results.csv and summary.txt identical to the threaded run's"
