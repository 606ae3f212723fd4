#!/usr/bin/env bash
# A shipped sweep on a real Slurm as docs/sweeps.md ("On a Slurm cluster") says to run it, checked byte for
# byte against the single-process run. Runs inside scripts/slurm-local (scripts/test slurm):
#   scripts/slurm-local bash tests/sweep_slurm_test.sh build/release/app/rollwear .
# cases/sweep-grid.yaml (64 cases) as an array of 4 tasks (shards) with scripts/sweep-slurm.sh, one CPU
# each (the node has 2: two tasks at a time). Task 3 is cancelled with scancel while it runs, after its
# first case (its rollwear is held stopped until then, in slices of 20 ms, so that it cannot finish first),
# submitted again as the docs say (sbatch --array=3 ...), and the shards merged: results.csv and
# summary.txt are the single-process run's, and the resubmitted task ran only the cases not finished.
set -euo pipefail
exe=$(realpath "$1")
src=$(realpath "$2")
: "${SLURM_CONF:?run inside scripts/slurm-local}"
dir=$(mktemp -d /tmp/rollwear-slurm.XXXXXX)
trap 'rm -rf "$dir"' EXIT
fail() { echo "sweep_slurm_test: $*" >&2; for f in "$dir"/logs/*; do echo "--- $f" >&2; cat "$f" >&2; done; exit 1; }
# waits until the array job $1 has left the queue (every task ended), at most $2 s
wait_job() {
  local k
  for ((k = 0; k < $2 * 5; ++k)); do
    [[ -z "$(squeue -h -j "$1" 2>/dev/null)" ]] && return 0
    sleep 0.2
  done
  squeue >&2
  fail "job $1 still in the queue after $2 s"
}

# rollwear on the PATH of the jobs (sbatch passes its environment on), as the docs say
PATH="$(dirname "$exe"):$PATH"
export PATH
sweep="$src/cases/sweep-grid.yaml"
out="$dir/out/sweep-grid"
mkdir -p "$dir/logs" "$out"
cd "$dir"

rollwear --log-level warn sweep "$sweep" -o "$dir/whole" -j 2 -q > /dev/null

# the program task 3 runs on its first submission: rollwear, held stopped but for 20 ms slices until its
# first case has finished, then stopped for good (scancel ends it; Slurm sends SIGCONT before SIGTERM)
cat > "$dir/rollwear-held" <<'END'
#!/usr/bin/env bash
[[ "${SLURM_ARRAY_TASK_ID:-}" == 3 ]] || exec rollwear "$@"
shard=
for ((i = 1; i < $#; ++i)); do [[ "${!i}" == -o ]] && { j=$((i + 1)); shard="${!j}"; }; done
rollwear "$@" &
pid=$!
kill -STOP "$pid"
for ((k = 0; k < 1500; ++k)); do
  compgen -G "$shard/case_*/row.csv" > /dev/null && break
  kill -CONT "$pid"; sleep 0.02; kill -STOP "$pid"
done
touch "$ROLLWEAR_HELD_MARK"
wait "$pid"
END
chmod +x "$dir/rollwear-held"

t0=$SECONDS
job=$(ROLLWEAR="$dir/rollwear-held" ROLLWEAR_HELD_MARK="$dir/task3.held" sbatch --parsable --array=1-4 --cpus-per-task=1 --output="$dir/logs/%A_%a.log" \
  "$src/scripts/sweep-slurm.sh" "$sweep" "$out" 4)
echo "sweep_slurm_test: submitted job array $job (4 tasks)"
for ((k = 0; k < 600; ++k)); do  # task 3 stopped after its first case (at most 120 s)
  [[ -e "$dir/task3.held" ]] && break
  sleep 0.2
done
[[ -e "$dir/task3.held" ]] || fail "task 3 did not start or finish a case in 120 s"
[[ "$(squeue -h -j "${job}_3" -o %T)" == RUNNING ]] || fail "task 3 is not running"
scancel "${job}_3"
wait_job "$job" 120
finished=$(compgen -G "$out/shard_3/case_*/row.csv" | wc -l)
[[ ! -e "$out/shard_3/results.csv" ]] || fail "task 3 finished its shard before it was cancelled"
((finished >= 1 && finished < 16)) || fail "task 3 cancelled with $finished of its 16 cases finished"
for k in 1 2 4; do [[ -e "$out/shard_$k/results.csv" ]] || fail "task $k did not finish its shard"; done
echo "sweep_slurm_test: task 3 cancelled by scancel with $finished of its 16 cases finished; tasks 1, 2, 4 done"

# submitted again as the docs say; rollwear from the PATH
again=$(sbatch --parsable --array=3 --cpus-per-task=1 --output="$dir/logs/%A_%a.log" \
  "$src/scripts/sweep-slurm.sh" "$sweep" "$out" 4)
wait_job "$again" 120
log="$dir/logs/${again}_3.log"
grep -q "16 cases in this shard, $((16 - finished)) run now, $finished finished before" "$log" \
  || fail "the resubmitted task 3 did not continue its shard"
[[ ! -e "$out/shard_1/case_0002" ]] || fail "the resubmitted task ran into shard_1"

rollwear --log-level warn sweep --merge "$out"/shard_* -o "$out"
cmp "$dir/whole/results.csv" "$out/results.csv" || fail "the merged results.csv differs from the single-process run's"
cmp "$dir/whole/summary.txt" "$out/summary.txt" || fail "the merged summary.txt differs from the single-process run's"
echo "sweep_slurm_test: array of 4, task 3 cancelled and resubmitted, merged: results.csv and summary.txt" \
  "identical to the single-process run's ($((SECONDS - t0)) s from the first sbatch)"
