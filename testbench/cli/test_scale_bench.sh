#!/usr/bin/env bash
# bench --scale on two small generated meshes: the driver writes them
# (tools/make_mesh.py), the bench renders each on golden and approx beside
# assimp's import alone and fits the growth exponents. The generator is
# checked on its own: 2R(R-1) triangles, every one facing outward.
# Usage: test_scale_bench.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"

# 1. The generator: counts and winding, worked out independently.
"$PYTHON" tools/make_mesh.py sphere --rings 9 -o "$TMP/s9.obj" >/dev/null && ok || bad "make_mesh.py failed"
"$PYTHON" - "$TMP/s9.obj" <<'PY' && ok || bad "make_mesh.py: wrong count or an inward face"
import sys
v, f = [], []
for line in open(sys.argv[1]):
    p = line.split()
    if p and p[0] == "v": v.append([float(x) for x in p[1:]])
    if p and p[0] == "f": f.append([int(x) - 1 for x in p[1:]])
assert len(f) == 2 * 9 * 8, len(f)          # 2R(R-1)
assert len(v) == 2 + 9 * 8, len(v)          # the poles and R-1 rings of R
for t in f:
    a, b, c = (v[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]; w = [c[k] - a[k] for k in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    centre = [(a[k] + b[k] + c[k]) / 3 for k in range(3)]
    assert sum(n[k] * centre[k] for k in range(3)) > 0, t  # outward: the normal points away from the centre
PY

# 2. The bench through the driver, which makes the meshes first; the
#    animation part at 2 and 6 frames (rtl too: under its cap of 100).
"$RUN" bench --scale --sizes 300 1200 --runs 1 --frames 2 6 --out "$TMP/sb" > "$TMP/log" 2>&1 && ok || { bad "bench --scale failed"; cat "$TMP/log"; }
[[ -f "$TMP/sb/scale/sphere_300.obj" && -f "$TMP/sb/scale/sphere_1200.obj" ]] && ok || bad "the driver made no meshes"
# make_mesh picks R with 2R(R-1) nearest: 312 (R 13) and 1200 (R 25).
jq -e '[.scale.sizes[].triangles] == [312, 1200]' "$TMP/sb/scale.json" >/dev/null && ok || bad "triangle counts: $(jq -c '[.scale.sizes[].triangles]' "$TMP/sb/scale.json")"
jq -e '.scale.sizes | all(.assimp.elapsed_s > 0 and .golden.peak_mb > 0 and .approx.wall_s > 0)' "$TMP/sb/scale.json" >/dev/null && ok || bad "a size lacks a measurement"
jq -e '.scale.exponents | has("golden_time") and has("approx_memory")' "$TMP/sb/scale.json" >/dev/null && ok || bad "no fitted exponents"
jq -e '.scale.timed == "tools/girtd render"' "$TMP/sb/scale.json" >/dev/null && ok || bad "not timed through the driver"
grep -q "| golden time at most 3x assimp's |" "$TMP/sb/scale.md" && ok || bad "scale.md lacks the bars"
jq -e '[.animation[] | [.backend, .short.frames, .long.frames]] == [["golden", 2, 6], ["approx", 2, 6], ["rtl", 2, 6]]' "$TMP/sb/scale.json" >/dev/null && ok || bad "animation rows: $(jq -c '.animation' "$TMP/sb/scale.json")"
jq -e '.animation | all(.short.peak_mb > 0 and .long.peak_mb > 0 and .long_over_short_peak > 0)' "$TMP/sb/scale.json" >/dev/null && ok || bad "an animation run lacks its peak"
grep -q "## Long animations" "$TMP/sb/scale.md" && ok || bad "scale.md lacks the animation table"

# 3. A long render shows its progress on a terminal, each step with its
#    time left: the model's reading (in the import's child), the front end,
#    the back end. (The line starts after a second, or as the environment
#    says: at once here, so that each step is seen however fast it is.)
"$PYTHON" tools/make_mesh.py sphere --triangles 800000 -o "$TMP/big.obj" >/dev/null
GIRTD_PROGRESS_AFTER_S=0 script -qec "'$GIRTD' render '$TMP/big.obj' --out '$TMP/big' --quiet" /dev/null > "$TMP/tty" 2>&1 || true
[[ -s "$TMP/big/report.json" ]] && ok || bad "render on a terminal"
# Not on a file: no line at all.
GIRTD_PROGRESS_AFTER_S=0 "$GIRTD" render "$TMP/big.obj" --out "$TMP/big2" --quiet 2> "$TMP/err"
[[ ! -s "$TMP/err" || -z "$(grep -F '[girtd]' "$TMP/err")" ]] && ok || bad "a progress line on a file: $(head -c 200 "$TMP/err")"
tr '\r' '\n' < "$TMP/tty" > "$TMP/lines"
for step in "reading big.obj: [0-9]+ %" "front end: [0-9]+/800112 polygons \([0-9]+ %\)" "golden: [0-9]+/800112 triangles"; do
  grep -qE "\[girtd\] $step" "$TMP/lines" && ok || bad "no progress line for '$step': $(tail -c 300 "$TMP/lines")"
done
grep -qE "about [0-9]+ s left" "$TMP/lines" && ok || bad "no time left on the progress line"

# 4. --sizes and --frames without --scale are refused, and --scale with --speed.
for args in "--sizes 300" "--frames 2 6" "--scale --speed"; do
  "$GIRTD" bench $args 2> "$TMP/err"; rc=$?
  [[ $rc -ne 0 ]] && ok || bad "bench $args was taken"
done
finish
