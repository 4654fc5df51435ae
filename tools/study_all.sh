#!/usr/bin/env bash
# study_all.sh: the study of docs/accuracy.md, regenerated (`./kit study`). Runs
# `shadowlab study` on every public scene with a shadowing light and on the ladder's
# light-bleeding and contact-hardening scenes, into out/study/<scene>/, then copies each
# scene's table, plots and page (with the images the page shows) into docs/accuracy/<scene>/.
#   tools/study_all.sh SHADOWLAB [--quick] [--exact] [extra shadowlab study options...]
# --quick: two map sizes and two radii, for a fast look, into out/study/quick/ (docs untouched).
# --exact: every study under callgrind (tools/cost_exact.sh): costs in instructions, which no
# other process moves; 20-40x slower (hours for the documented sweep).
# A scene's folder is resumed: rows already in its study.csv are kept (delete it to redo).
# Scenes run side by side, one study per core (SHADOWLAB_STUDY_JOBS, default nproc), each with
# one llvmpipe thread: a study is mostly serial (truths, errors, images between the frames), so
# two with one thread each finish in about 0.7x the time of one after the other with two.
set -euo pipefail
BIN="$1"; shift
ROOT="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
OUT="${SHADOWLAB_STUDY_OUT:-$ROOT/out/study}"
DOCS="$ROOT/docs/accuracy"
JOBS="${SHADOWLAB_STUDY_JOBS:-$(nproc)}"
# The documented sweep: every technique of the table, 256²..1024² maps, Gaussian radius 1 and 4
# (the SAT box of equal variance: 1.73 and 6.93 texels), both filters, each light as a point
# (hard truth) and as a 0.8 disk (area truth), 3 timed frames, a 192² image, the flicker of a
# turning light over 4 frames. 2048² maps are left out: one scene's 2048² rows alone take
# longer than the other sizes together (add them with SHADOWLAB_STUDY_SWEEP). Costs are CPU time
# with llvmpipe's thread count fixed (study_cost.h).
export LP_NUM_THREADS="${LP_NUM_THREADS:-1}"
SWEEP=(--map-sizes 256,512,1024 --radii 1,4 --filters gaussian,sat --light-sizes 0,0.8
       --repeats 3 --image 192 --flicker 4)
# SHADOWLAB_STUDY_SWEEP replaces it (words split on spaces), for a documented smaller run.
if [ -n "${SHADOWLAB_STUDY_SWEEP:-}" ]; then read -r -a SWEEP <<< "$SHADOWLAB_STUDY_SWEEP"; fi
QUICK=0 RUN=("$BIN")
while [ $# -gt 0 ]; do
  case "$1" in
    --quick)
      shift; QUICK=1
      OUT="$OUT/quick"; DOCS="$OUT/docs"  # never mixed with, nor replacing, the documented run
      SWEEP=(--map-sizes 256,1024 --radii 2,8 --filters gaussian,sat --light-sizes 0,0.8 --repeats 2
             --image 128) ;;
    --exact) shift; RUN=("$ROOT/tools/cost_exact.sh" "$BIN") ;;
    *) break ;;
  esac
done
SCENES=()
for s in "$ROOT"/scenes/classic.json "$ROOT"/scenes/contact.json \
         "$ROOT"/scenes/ladder/light_bleeding.json "$ROOT"/scenes/ladder/contact_hardening.json \
         "$ROOT"/scenes/*.json; do
  case " ${SCENES[*]:-} " in *" $s "*) continue ;; esac  # listed first already
  [ -f "$s" ] || continue
  grep -q '"lights"' "$s" || continue
  [ "$(basename "$s")" = unlit_no_shadow.json ] && continue  # no light casts shadows
  SCENES+=("$s")
done
mkdir -p "$DOCS"
"$BIN" info | grep -v "^kit root" > "$DOCS/machine.txt"
grep -m1 'model name' /proc/cpuinfo | sed 's/^model name\s*: /cpu:      /' >> "$DOCS/machine.txt"
echo "threads:  $(nproc), LP_NUM_THREADS=$LP_NUM_THREADS, $JOBS studies at once" >> "$DOCS/machine.txt"
START=$(date +%s)
# Runs "$@" in the background once fewer than JOBS run; its output goes to $OUT/<name>.log.
RUNNING=0 FAILED=0
finish_one() { if ! wait -n; then FAILED=$((FAILED + 1)); fi; RUNNING=$((RUNNING - 1)); }
spawn() {
  local name="$1"; shift
  while [ "$RUNNING" -ge "$JOBS" ]; do finish_one; done
  mkdir -p "$OUT"
  ( t0=$(date +%s)
    if "$@" > "$OUT/$name.log" 2>&1; then echo "== $name: done in $(( $(date +%s) - t0 )) s"
    else echo "== $name: FAILED, see $OUT/$name.log" >&2; tail -5 "$OUT/$name.log" >&2; exit 1; fi ) &
  RUNNING=$((RUNNING + 1))
}
# (spawn runs these in an `if`, where set -e does not stop a function: each checks itself.)
# One scene: its study, then its table, plots, page and the images the page shows into the docs.
study_scene() {
  local scene="$1" name dest; name="$(basename "$scene" .json)"
  "${RUN[@]}" study --scene "$scene" --out "$OUT/$name" --no-progress "${SWEEP[@]}" "${EXTRA[@]}" || return
  dest="$DOCS/$name"
  rm -rf "$dest"; mkdir -p "$dest"
  # The plots as SVG (what the page and docs/accuracy.md show; the PNGs stay in out/study/).
  cp "$OUT/$name"/{study.csv,index.html,pick.md} "$OUT/$name"/{pareto,kernel_cost,pass_cost,flicker}*.svg \
    "$dest/" 2>/dev/null || true
  grep -o 'src="[^"]*\.png"' "$OUT/$name/index.html" | sed 's/^src="//; s/"$//' | sort -u |
    while read -r img; do mkdir -p "$dest/$(dirname "$img")"; cp "$OUT/$name/$img" "$dest/$img"; done
}
# What α (msm4's moment bias) costs: msm4 at α = 0 .. 3e-3, 512² map, both filters.
ALPHA=()
for a in 0 3e-6 3e-5 3e-4 3e-3; do ALPHA+=("msm4:momentBias=$a"); done
study_alpha() {
  local name="$1" scene="$ROOT/scenes/$1.json"
  [ -f "$scene" ] || scene="$ROOT/scenes/ladder/$1.json"
  "${RUN[@]}" study --scene "$scene" --out "$OUT/alpha_$name" --no-progress \
    --techniques "$(IFS=,; echo "${ALPHA[*]}")" --map-sizes 512 --radii 1,4 --filters gaussian,sat \
    --repeats 2 --image 192 "${EXTRA[@]}" || return
  rm -rf "$DOCS/alpha_$name"; mkdir -p "$DOCS/alpha_$name"
  cp "$OUT/alpha_$name"/{study.csv,pareto.svg} "$DOCS/alpha_$name/"
}
EXTRA=("$@")
for scene in "${SCENES[@]}"; do spawn "$(basename "$scene" .json)" study_scene "$scene"; done
if [ "$QUICK" = 0 ]; then
  for name in classic light_bleeding; do spawn "alpha_$name" study_alpha "$name"; done
fi
while [ "$RUNNING" -gt 0 ]; do finish_one; done
[ "$FAILED" = 0 ] || { echo "study_all.sh: $FAILED stud(ies) failed (logs in $OUT/)" >&2; exit 1; }
# Which configuration to pick, every scene in one table (each scene's pick.md, from its data).
{ echo "| scene | light | question | configuration | RMSE (truth) | frame/copy | map bytes |"
  echo "|---|---|---|---|---|---|---|"
  for scene in "${SCENES[@]}"; do cat "$DOCS/$(basename "$scene" .json)/pick.md"; done; } > "$DOCS/pick.md"
echo "sweep:    ${SWEEP[*]} ${EXTRA[*]}" >> "$DOCS/machine.txt"
echo "took:     $(( $(date +%s) - START )) s (tools/study_all.sh, wall clock)" >> "$DOCS/machine.txt"
if [ "$QUICK" = 1 ]; then echo "$DOCS: ${#SCENES[@]} scenes (quick look)"
else echo "docs/accuracy/: ${#SCENES[@]} scenes and the α sweep; see docs/accuracy.md"; fi
