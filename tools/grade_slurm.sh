#!/usr/bin/env bash
# grade_slurm.sh: a class's submissions graded as a Slurm array job of N shards, then the merge.
#   tools/grade_slurm.sh SHADOWLAB DIR OUT N [shadowlab grade options...]
# Submits an array of N tasks (task K runs `shadowlab grade --batch DIR --shard K/N --out OUT`:
# every N-th submission in name order, each stored in OUT/<name>/ as it ends) and a merge job
# after all of them (`grade --batch DIR --merge --out OUT`: grades nothing; writes scores.csv,
# index.html and class.html, and fails if a submission has no row). Every task must see the same
# kit, DIR and OUT (a shared file system) and get the same grade options, which the merge checks
# through each row's digest. A task that stops is resubmitted as it was: it grades only what its
# share is missing. Without sbatch (or with SHADOWLAB_SLURM=local) the same commands run here,
# the shards at once, then the merge.
set -euo pipefail
BIN="$(readlink -f "$1")"; DIR="$(readlink -f "$2")"; OUT="$3"; N="$4"; shift 4
mkdir -p "$OUT"; OUT="$(readlink -f "$OUT")"
OPTS=(--batch "$DIR" --out "$OUT" "$@")
if [ "${SHADOWLAB_SLURM:-}" = local ] || ! command -v sbatch > /dev/null; then
  pids=()
  for k in $(seq 1 "$N"); do
    "$BIN" grade "${OPTS[@]}" --shard "$k/$N" > "$OUT/shard_$k.log" 2>&1 &
    pids+=("$!")
  done
  for p in "${pids[@]}"; do wait "$p"; done
  exec "$BIN" grade "${OPTS[@]}" --merge
fi
q() { printf '%q ' "$@"; }
array=$(sbatch --parsable --job-name=shadowlab-grade --array=1-"$N" --output="$OUT/shard_%a.log" \
  --wrap "$(q "$BIN" grade "${OPTS[@]}")--shard \$SLURM_ARRAY_TASK_ID/$N")
merge=$(sbatch --parsable --job-name=shadowlab-grade-merge --dependency=afterok:"$array" \
  --output="$OUT/merge.log" --wrap "$(q "$BIN" grade "${OPTS[@]}")--merge")
echo "submitted array job $array ($N shards) and merge job $merge; gradebook in $OUT"
