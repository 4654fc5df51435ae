#!/usr/bin/env bash
# grade_slurm_check.sh: does a batch graded through Slurm give the one-process grades? Grades DIR
# in one process into OUT/one/, then as N shards and a merge through tools/grade_slurm.sh (real
# sbatch) into OUT/slurm/, waits for the merge job, and compares: scores.csv byte for byte, and
# every submission's results.json test by test (name, score, status).
#   tools/grade_slurm_check.sh SHADOWLAB DIR OUT N [shadowlab grade options...]
# Needs sbatch, squeue and scontrol; waits at most ${SHADOWLAB_SLURM_TIMEOUT:-3600} s for the jobs.
# Exit status 1 if anything differs, or if a job failed or did not finish in time.
set -euo pipefail
BIN="$(readlink -f "$1")"; DIR="$(readlink -f "$2")"; OUT="$3"; N="$4"; shift 4
HERE="$(dirname "$(readlink -f "$0")")"
for c in sbatch squeue scontrol; do
  command -v "$c" > /dev/null || { echo "grade_slurm_check: $c not found (no Slurm here)" >&2; exit 2; }
done
mkdir -p "$OUT"; OUT="$(readlink -f "$OUT")"
rm -rf "$OUT/one" "$OUT/slurm"

t0=$(date +%s)
"$BIN" grade --batch "$DIR" --out "$OUT/one" "$@" > "$OUT/one.log" 2>&1
t1=$(date +%s)
echo "one process: $((t1 - t0)) s (log $OUT/one.log)"

sub=$(SHADOWLAB_SLURM= "$HERE/grade_slurm.sh" "$BIN" "$DIR" "$OUT/slurm" "$N" "$@")
echo "$sub"
array=$(sed -n 's/.*array job \([0-9]*\).*/\1/p' <<< "$sub")
merge=$(sed -n 's/.*merge job \([0-9]*\).*/\1/p' <<< "$sub")
[ -n "$array" ] && [ -n "$merge" ] || { echo "grade_slurm_check: no job ids in: $sub" >&2; exit 1; }
limit=${SHADOWLAB_SLURM_TIMEOUT:-3600}
while [ -n "$(squeue -h -j "$array,$merge" -o %i 2> /dev/null)" ]; do
  if squeue -h -j "$merge" -o %r 2> /dev/null | grep -q DependencyNeverSatisfied; then
    echo "grade_slurm_check: a shard failed, the merge job $merge can never run (see $OUT/slurm/shard_*.log)" >&2
    scancel "$merge"; exit 1
  fi
  if [ $(( $(date +%s) - t1 )) -gt "$limit" ]; then
    echo "grade_slurm_check: jobs $array and $merge not done after $limit s" >&2
    scancel "$array" "$merge"; exit 1
  fi
  sleep 2
done
t2=$(date +%s)
echo "slurm ($N shards + merge): $((t2 - t1)) s (logs $OUT/slurm/shard_*.log, $OUT/slurm/merge.log)"
scontrol show job "$array" 2> /dev/null | grep -Eo '^JobId=[^ ]+|ArrayTaskId=[^ ]+|JobState=[^ ]+|ExitCode=[^ ]+' |
  paste -sd' ' | sed 's/ JobId=/\nJobId=/g' || true
scontrol show job "$merge" 2> /dev/null | grep -Eo '^JobId=[^ ]+|Dependency=[^ ]+|JobState=[^ ]+|ExitCode=[^ ]+' |
  paste -sd' ' || true
[ -f "$OUT/slurm/scores.csv" ] || { echo "grade_slurm_check: no merged scores.csv (see $OUT/slurm/merge.log)" >&2; exit 1; }

python3 - "$OUT/one" "$OUT/slurm" <<'PY'
import json, os, sys
one, sl = sys.argv[1], sys.argv[2]
bad = []
a, b = (open(os.path.join(d, "scores.csv"), "rb").read() for d in (one, sl))
if a != b: bad.append("scores.csv differs")
names = sorted(n for n in os.listdir(one) if os.path.isfile(os.path.join(one, n, "results.json")))
for n in names:
    def tests(d):
        try:
            with open(os.path.join(d, n, "results.json")) as f: r = json.load(f)
        except (OSError, ValueError): return None
        return r.get("score"), [(t["name"], t["score"], t.get("status")) for t in r.get("tests", [])]
    if tests(one) != tests(sl): bad.append(f"{n}: results.json differs")
if bad:
    print(f"the Slurm grades differ from the one-process grades ({len(bad)}):")
    for line in bad[:20]: print("  " + line)
    sys.exit(1)
print(f"{len(names)} submissions: scores.csv identical, every results.json's tests equal")
PY
