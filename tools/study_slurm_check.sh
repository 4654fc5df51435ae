#!/usr/bin/env bash
# study_slurm_check.sh: does the study split over Slurm give the one-process table? Runs the study
# in one process into OUT/one/, then as N shards and a merge through tools/study_slurm.sh (real
# sbatch) into OUT/slurm/, waits for the merge job, and compares the two study.csv column by column
# (by name), every row, all but the cost columns, cost_method and reused (they depend on the run).
#   tools/study_slurm_check.sh SHADOWLAB SCENE OUT N [shadowlab study options...]
# Needs sbatch, squeue and scontrol; waits at most ${SHADOWLAB_SLURM_TIMEOUT:-3600} s for the jobs.
# Exit status 1 if a row or column differs, or if a job failed or did not finish in time.
set -euo pipefail
BIN="$(readlink -f "$1")"; SCENE="$(readlink -f "$2")"; OUT="$3"; N="$4"; shift 4
HERE="$(dirname "$(readlink -f "$0")")"
for c in sbatch squeue scontrol; do
  command -v "$c" > /dev/null || { echo "study_slurm_check: $c not found (no Slurm here)" >&2; exit 2; }
done
mkdir -p "$OUT"; OUT="$(readlink -f "$OUT")"
rm -rf "$OUT/one" "$OUT/slurm"

t0=$(date +%s)
"$BIN" study --scene "$SCENE" --out "$OUT/one" --no-progress "$@" > "$OUT/one.log" 2>&1
t1=$(date +%s)
echo "one process: $((t1 - t0)) s (log $OUT/one.log)"

sub=$(SHADOWLAB_SLURM= "$HERE/study_slurm.sh" "$BIN" "$SCENE" "$OUT/slurm" "$N" "$@")
echo "$sub"
array=$(sed -n 's/.*array job \([0-9]*\).*/\1/p' <<< "$sub")
merge=$(sed -n 's/.*merge job \([0-9]*\).*/\1/p' <<< "$sub")
[ -n "$array" ] && [ -n "$merge" ] || { echo "study_slurm_check: no job ids in: $sub" >&2; exit 1; }
limit=${SHADOWLAB_SLURM_TIMEOUT:-3600}
while [ -n "$(squeue -h -j "$array,$merge" -o %i 2> /dev/null)" ]; do
  if squeue -h -j "$merge" -o %r 2> /dev/null | grep -q DependencyNeverSatisfied; then
    echo "study_slurm_check: a shard failed, the merge job $merge can never run (see $OUT/slurm/shard_*.log)" >&2
    scancel "$merge"; exit 1
  fi
  if [ $(( $(date +%s) - t1 )) -gt "$limit" ]; then
    echo "study_slurm_check: jobs $array and $merge not done after $limit s" >&2
    scancel "$array" "$merge"; exit 1
  fi
  sleep 2
done
t2=$(date +%s)
echo "slurm ($N shards + merge): $((t2 - t1)) s (logs $OUT/slurm/shard_*.log, $OUT/slurm/merge.log)"
# The jobs' end states, while slurmctld still remembers them (MinJobAge).
scontrol show job "$array" 2> /dev/null | grep -Eo '^JobId=[^ ]+|ArrayTaskId=[^ ]+|JobState=[^ ]+|ExitCode=[^ ]+' |
  paste -sd' ' | sed 's/ JobId=/\nJobId=/g' || true
scontrol show job "$merge" 2> /dev/null | grep -Eo '^JobId=[^ ]+|Dependency=[^ ]+|JobState=[^ ]+|ExitCode=[^ ]+' |
  paste -sd' ' || true
[ -f "$OUT/slurm/study.csv" ] || { echo "study_slurm_check: no merged table (see $OUT/slurm/merge.log)" >&2; exit 1; }

python3 - "$OUT/one/study.csv" "$OUT/slurm/study.csv" <<'EOF'
import csv, sys
IGNORED = {"frame_cost_min", "frame_cost_median", "frame_cost_max", "frame_wall_ms_median",
           "pass_cost", "copy_cost", "frame_over_copy", "cost_method", "reused"}
def load(path):
    with open(path, newline="") as f:
        r = csv.DictReader(f)
        return r.fieldnames or [], list(r)
hone, one = load(sys.argv[1])
hsl, sl = load(sys.argv[2])
bad = []
for c in hone:
    if c not in hsl: bad.append(f"column {c} only in the one-process table")
for c in hsl:
    if c not in hone: bad.append(f"column {c} only in the merged table")
cols = [c for c in hone if c in hsl and c not in IGNORED]
if len(one) != len(sl):
    bad.append(f"{len(one)} rows in the one-process table, {len(sl)} in the merged one")
for i, (a, b) in enumerate(zip(one, sl), start=1):
    diff = [c for c in cols if a[c] != b[c]]
    if diff:
        bad.append(f"row {i}: " + ", ".join(f"{c} {a[c]!r} vs {b[c]!r}" for c in diff))
if bad:
    print(f"the merged table differs from the one-process table ({len(bad)} differences):")
    for line in bad[:20]: print("  " + line)
    if len(bad) > 20: print(f"  ... and {len(bad) - 20} more")
    sys.exit(1)
print(f"{len(one)} rows: the merged table equals the one-process table in every column but cost "
      f"and reused ({len(cols)} columns compared)")
EOF
