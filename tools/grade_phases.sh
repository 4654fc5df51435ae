#!/usr/bin/env bash
# grade_phases.sh: where one grade's CPU goes, phase by phase (docs/performance.md, "Grading
# time"). Grades SUBMISSION once with SHADOWLAB_GRADER_TIMING=1 and --keep-work, adds up the
# "phase" lines of the grade process and of every worker's log (grader/intake/phase_clock.h),
# reference renders apart, and prints a table; the last row is the whole run as the kernel
# counted it (/usr/bin/time: user + sys of the grade and all its children).
#   tools/grade_phases.sh SHADOWLAB SUBMISSION OUT [grade options...]
set -euo pipefail
BIN="$(readlink -f "$1")"; SUB="$2"; OUT="$3"; shift 3
rm -rf "$OUT"; mkdir -p "$OUT"
SHADOWLAB_GRADER_TIMING=1 /usr/bin/time -f "whole %U %S %e" -o "$OUT.time" \
  "$BIN" grade --submission "$SUB" --out "$OUT" --keep-work "$@" > "$OUT.stdout" 2> "$OUT.stderr"
python3 - "$OUT" "$OUT.stderr" "$OUT.time" <<'PY'
import glob, os, re, sys
out, stderr, timing = sys.argv[1:]
line = re.compile(r"^phase (\S+) (.*): ([0-9.]+) s wall, ([0-9.]+) s user, ([0-9.]+) s sys$")
rows = {}  # (who, phase) -> [processes, user, sys]
def add(who, text):
    for l in text.splitlines():
        m = line.match(l)
        if not m: continue
        key = (who, m.group(2))
        r = rows.setdefault(key, [0, 0.0, 0.0])
        r[0] += 1; r[1] += float(m.group(4)); r[2] += float(m.group(5))
add("grade process", open(stderr).read())
work = glob.glob(os.path.join(out, ".work-*"))[0]
for log in glob.glob(os.path.join(work, "**", "log.txt"), recursive=True):
    rel = os.path.relpath(log, work).split(os.sep)
    who = "reference workers" if rel[0] == "ref" else f"{rel[1]} workers" if len(rel) > 2 else f"{rel[0]} worker"
    add(who, open(log, errors="replace").read())
u, s, e = open(timing).read().split()[1:4]
print("| process | phase | processes | user s | sys s |")
print("|---|---|---:|---:|---:|")
tot = [0.0, 0.0]
per = {}
for (who, phase), (n, us, sy) in sorted(rows.items()):
    print(f"| {who} | {phase} | {n} | {us:.2f} | {sy:.2f} |")
    tot[0] += us; tot[1] += sy
    p = per.setdefault(who, [0, 0.0, 0.0]); p[0] = max(p[0], n); p[1] += us; p[2] += sy
for who, (n, us, sy) in sorted(per.items()):
    print(f"| {who} | all its phases | {n} | {us:.2f} | {sy:.2f} |")
print(f"| all | phases counted | | {tot[0]:.2f} | {tot[1]:.2f} |")
print(f"| all | whole run (/usr/bin/time; {e} s wall) | | {float(u):.2f} | {float(s):.2f} |")
PY
