#!/usr/bin/env python3
"""class_batch.py: a class of N submissions for `shadowlab grade --batch`, made from the kit.

    tools/class_batch.py OUT N [--hostile]

Submission i (s001_..., in name order) is, in turn: a copy of reference/, the untouched student
kit, then each entry of tests/submissions/catalogue.json (reference/ with the entry's files on
top: correct alternatives, mutants, fragile variants), and with --hostile also a render that
never ends (a loop in moments.glsl), a folder holding a 50 MB file, a shader whose macros expand
to 2^26 terms (the compiler runs out of time or memory) and a msm.glsl that is a link to /etc/passwd; then round
again. (A fork bomb has no place to go: a submission is shader sources, nothing of it runs on the
CPU but the driver's compiler.) So a
batch's scores can be checked against each entry's known verdict, and its cost measured on a
realistic mix (docs/performance.md)."""
import json, os, shutil, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STAGE_FILES = ["moments.glsl", "gaussian_blur.comp", "sat.comp", "sat_lookup.glsl", "msm.glsl"]


def kinds(hostile):
    yield "reference", {}
    yield "student_kit", None
    cat = json.load(open(os.path.join(ROOT, "tests", "submissions", "catalogue.json")))
    for e in cat["entries"]:
        files = e.get("files", [e["file"]])
        yield e["name"], {os.path.basename(f): os.path.join(ROOT, "tests", "submissions", f) for f in files}
    if hostile:
        yield "hostile_hang", "hang"
        yield "hostile_50mb", "big"
        yield "hostile_macro_bomb", "bomb"
        yield "hostile_link", "link"


def make(folder, spec):
    os.makedirs(folder)
    if spec is None:  # the student kit's stubs
        for f in STAGE_FILES:
            shutil.copy(os.path.join(ROOT, "student", f), folder)
        return
    for f in STAGE_FILES:
        shutil.copy(os.path.join(ROOT, "reference", f), folder)
    if spec == "hang":
        path = os.path.join(folder, "moments.glsl")
        text = open(path).read()
        head = "vec4 computeMoments(float z)\n{\n"
        assert head in text, "reference/moments.glsl changed"
        text = text.replace(head, head + "    for (int i = 0; i < 100000; ++i)\n"
                            "        for (int j = 0; j < 100000; ++j) z = fract(z * 1.0001 + 0.1);\n")
        open(path, "w").write(text)
    elif spec == "bomb":
        path = os.path.join(folder, "msm.glsl")
        bomb = "#define X0 zf\n" + "".join(f"#define X{k} (X{k - 1} + X{k - 1})\n" for k in range(1, 27))
        head = "float momentShadowIntensity(vec4 b, float zf)\n{\n"
        text = open(path).read()
        assert head in text, "reference/msm.glsl changed"
        open(path, "w").write(bomb + text.replace(head, head + "    zf = X26;\n"))
    elif spec == "link":
        os.remove(os.path.join(folder, "msm.glsl"))
        os.symlink("/etc/passwd", os.path.join(folder, "msm.glsl"))
    elif spec == "big":
        with open(os.path.join(folder, "screenshot.bin"), "wb") as f:
            f.write(os.urandom(50 << 20))
    else:
        for name, src in spec.items():
            shutil.copy(src, os.path.join(folder, name))


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(args) != 2:
        sys.exit(__doc__)
    out, n = args[0], int(args[1])
    if os.path.exists(out):
        sys.exit(f"class_batch: {out} exists; give a new folder")
    all_kinds = list(kinds("--hostile" in sys.argv))
    for i in range(n):
        name, spec = all_kinds[i % len(all_kinds)]
        make(os.path.join(out, f"s{i + 1:03d}_{name}"), spec)
    print(f"{n} submissions in {out} ({len(all_kinds)} kinds)")


if __name__ == "__main__":
    main()
