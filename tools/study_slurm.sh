#!/usr/bin/env bash
# study_slurm.sh: one scene's study as a Slurm array job, N shards, then the merge.
#   tools/study_slurm.sh SHADOWLAB SCENE OUT N [shadowlab study options...]
# Submits an array of N tasks (task i runs `shadowlab study --shard i+1/N --out OUT/shard_<i+1>`)
# and a merge job after all of them (`--merge OUT/shard_* --out OUT`: nothing is left to run,
# the table is written in the sweep's order, the plots and page are drawn). Every task must see
# the same kit, scene and truth cache (a shared file system). Without sbatch (or with
# SHADOWLAB_SLURM=local) the same commands run here, the shards at once, then the merge.
set -euo pipefail
BIN="$(readlink -f "$1")"; SCENE="$(readlink -f "$2")"; OUT="$3"; N="$4"; shift 4
mkdir -p "$OUT"; OUT="$(readlink -f "$OUT")"
OPTS=(--scene "$SCENE" --no-progress "$@")
if [ "${SHADOWLAB_SLURM:-}" = local ] || ! command -v sbatch > /dev/null; then
  pids=()
  for k in $(seq 1 "$N"); do
    "$BIN" study "${OPTS[@]}" --shard "$k/$N" --out "$OUT/shard_$k" > "$OUT/shard_$k.log" 2>&1 &
    pids+=("$!")
  done
  for p in "${pids[@]}"; do wait "$p"; done
  shards=(); for k in $(seq 1 "$N"); do shards+=("$OUT/shard_$k"); done
  "$BIN" study "${OPTS[@]}" --merge "${shards[@]}" --out "$OUT"
  exit 0
fi
q() { printf '%q ' "$@"; }
array=$(sbatch --parsable --job-name=shadowlab-study --array=1-"$N" --output="$OUT/shard_%a.log" \
  --wrap "$(q "$BIN" study "${OPTS[@]}") --shard \$SLURM_ARRAY_TASK_ID/$N --out $(printf %q "$OUT")/shard_\$SLURM_ARRAY_TASK_ID")
shards=""; for k in $(seq 1 "$N"); do shards+="$(q "$OUT/shard_$k")"; done
merge=$(sbatch --parsable --job-name=shadowlab-study-merge --dependency=afterok:"$array" \
  --output="$OUT/merge.log" --wrap "$(q "$BIN" study "${OPTS[@]}") --merge $shards--out $(q "$OUT")")
echo "submitted array job $array ($N shards) and merge job $merge; results in $OUT"
