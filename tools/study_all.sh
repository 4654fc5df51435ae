#!/usr/bin/env bash
# study_all.sh: the study of docs/accuracy.md, regenerated (`./kit study`). Runs
# `shadowlab study` on every public scene with a shadowing light and on the ladder's
# light-bleeding and contact-hardening scenes, into out/study/<scene>/, then copies each
# scene's table, plots and page (with the images the page shows) into docs/accuracy/<scene>/.
#   tools/study_all.sh SHADOWLAB [--quick] [extra shadowlab study options...]
# --quick: two map sizes and two radii, for a fast look, into out/study/quick/ (docs untouched).
# A scene's folder is resumed: rows already in its study.csv are kept (delete it to redo).
set -euo pipefail
BIN="$1"; shift
ROOT="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
OUT="${SHADOWLAB_STUDY_OUT:-$ROOT/out/study}"
DOCS="$ROOT/docs/accuracy"
# The documented sweep: every technique of the table, 256²..2048² maps, Gaussian radius 1 and 4
# (the SAT box of equal variance: 1.73 and 6.93 texels), both filters, each light as a point
# (hard truth) and as a 0.8 disk (area truth), 3 timed frames, a 192² image: 296 rows a scene,
# three quarters of them lighting with a raw map an earlier row rendered. Widen it with extra options, e.g.
# --radii 1,2,4,8,16. Costs are CPU time with llvmpipe's thread count fixed (study_cost.h).
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"
SWEEP=(--map-sizes 256,512,1024,2048 --radii 1,4 --filters gaussian,sat --light-sizes 0,0.8
       --repeats 3 --image 192 --flicker 4)
# SHADOWLAB_STUDY_SWEEP replaces it (words split on spaces), for a documented smaller run.
if [ -n "${SHADOWLAB_STUDY_SWEEP:-}" ]; then read -r -a SWEEP <<< "$SHADOWLAB_STUDY_SWEEP"; fi
QUICK=0
if [ "${1:-}" = --quick ]; then
  shift; QUICK=1
  OUT="$OUT/quick"; DOCS="$OUT/docs"  # never mixed with, nor replacing, the documented run
  SWEEP=(--map-sizes 256,1024 --radii 2,8 --filters gaussian,sat --light-sizes 0,0.8 --repeats 2
         --image 128)
fi
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
echo "threads:  $(nproc), LP_NUM_THREADS=$LP_NUM_THREADS" >> "$DOCS/machine.txt"
START=$(date +%s)
for scene in "${SCENES[@]}"; do
  name="$(basename "$scene" .json)"
  echo "== $name"
  "$BIN" study --scene "$scene" --out "$OUT/$name" "${SWEEP[@]}" "$@"
  dest="$DOCS/$name"
  rm -rf "$dest"; mkdir -p "$dest"
  cp "$OUT/$name"/{study.csv,index.html,pick.md} "$OUT/$name"/{pareto,kernel_cost,pass_cost,flicker}*.{svg,png} \
    "$dest/" 2>/dev/null || true
  # The images the page shows (one row per technique, the truth), nothing else.
  grep -o 'src="[^"]*\.png"' "$OUT/$name/index.html" | sed 's/^src="//; s/"$//' | sort -u |
    while read -r img; do mkdir -p "$dest/$(dirname "$img")"; cp "$OUT/$name/$img" "$dest/$img"; done
done
# Which configuration to pick, every scene in one table (each scene's pick.md, from its data).
{ echo "| scene | light | question | configuration | RMSE (truth) | frame/copy | map bytes |"
  echo "|---|---|---|---|---|---|---|"
  for scene in "${SCENES[@]}"; do cat "$DOCS/$(basename "$scene" .json)/pick.md"; done; } > "$DOCS/pick.md"
# What α (msm4's moment bias) costs: msm4 at α = 0 .. 3e-3 on two scenes, 512² map, both filters.
ALPHA=()
for a in 0 3e-6 3e-5 3e-4 3e-3; do ALPHA+=("msm4:momentBias=$a"); done
for name in classic light_bleeding; do
  scene="$ROOT/scenes/$name.json"; [ -f "$scene" ] || scene="$ROOT/scenes/ladder/$name.json"
  [ "$QUICK" = 1 ] && break
  echo "== alpha: $name"
  "$BIN" study --scene "$scene" --out "$OUT/alpha_$name" --techniques "$(IFS=,; echo "${ALPHA[*]}")" \
    --map-sizes 512 --radii 1,4 --filters gaussian,sat --repeats 2 --image 192 "$@"
  rm -rf "$DOCS/alpha_$name"; mkdir -p "$DOCS/alpha_$name"
  cp "$OUT/alpha_$name"/{study.csv,pareto.svg,pareto.png} "$DOCS/alpha_$name/"
done
echo "sweep:    ${SWEEP[*]} $*" >> "$DOCS/machine.txt"
echo "took:     $(( $(date +%s) - START )) s (tools/study_all.sh, wall clock)" >> "$DOCS/machine.txt"
echo "docs/accuracy/: ${#SCENES[@]} scenes and the α sweep; see docs/accuracy.md"
