#!/usr/bin/env bash
# A hardware limit hit is counted and warned, never silent (report.json
# `numerics`): one opaque triangle over the whole screen whose corners lie
# 1,500 px and more beyond it. The D EPs' 12 integer bits hold +-2048 px, so
# the edge functions wrap while the DDA walks; the reference back end (no
# EPs) fills all 1024 x 1024 pixels.
# Usage: test_numerics_cli.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"

cp traces/stress/huge_overhang.trace "$TMP/huge.trace"
printf '{"ep": {"d": {"int_bits": 14}}}\n' > "$TMP/d14.json"
wraps='[.numerics.D1.wraps, .numerics.D2.wraps, .numerics.D3.wraps] | add'

"$RUN" render "$TMP/huge.trace" --backend reference --out "$TMP/ref" --quiet && ok || bad "reference"
jq -e '.pixels_written == 1048576 and .numerics == null' "$TMP/ref/report.json" >/dev/null && ok \
  || bad "reference: $(jq -c '[.pixels_written, .numerics]' "$TMP/ref/report.json")"

for b in golden approx; do
  "$RUN" render "$TMP/huge.trace" --backend $b --out "$TMP/$b" --quiet 2> "$TMP/$b.err" && ok || bad "$b render"
  r="$TMP/$b/report.json"
  # The picture is wrong, and the run says so: counted, one warning naming D and the option.
  jq -e "($wraps) > 0 and .numerics.triangles_affected == 1 and .numerics.first_triangle_affected == 1
         and .pixels_written < 1048576" "$r" >/dev/null && ok || bad "$b: $(jq -c .numerics "$r")"
  grep -q "^warning: $TMP/huge.trace: wrapped EP values in use (D[0-9] [0-9]*.* in 1 triangle(s); first: triangle 1 drawn (line 11): .*ep.d.int_bits above 12" \
    "$TMP/$b.err" && ok || bad "$b: warning line: $(cat "$TMP/$b.err")"
  jq -e '.warnings | length == 1' "$r" >/dev/null && ok || bad "$b: report warnings"
  # Two more integer bits hold the whole triangle: every pixel, no wrap, no warning.
  "$RUN" render "$TMP/huge.trace" --backend $b --config "$TMP/d14.json" --out "$TMP/${b}14" --quiet 2> "$TMP/${b}14.err" \
    && ok || bad "$b d14 render"
  jq -e "($wraps) == 0 and .pixels_written == 1048576 and .warnings == []" "$TMP/${b}14/report.json" >/dev/null && ok \
    || bad "$b with 14 integer bits: $(jq -c '[.pixels_written, .numerics.D1]' "$TMP/${b}14/report.json")"
  [[ ! -s "$TMP/${b}14.err" ]] && ok || bad "$b d14 printed: $(cat "$TMP/${b}14.err")"
done
[[ "$(jq -c .numerics "$TMP/golden/report.json")" == "$(jq -c .numerics "$TMP/approx/report.json")" ]] && ok \
  || bad "approx counts differ from golden's"

# Many triangles, colour and Z wraps in slivers' fringes: approx counts what golden counts.
for b in golden approx; do
  "$RUN" render traces/scenes/animation.json --backend $b --out "$TMP/an_$b" --quiet 2> "$TMP/an_$b.err" && ok || bad "an $b"
done
jq -e '.numerics.triangles_affected > 1 and .numerics.first_triangle_affected > 1' "$TMP/an_golden/report.json" >/dev/null \
  && ok || bad "animation: $(jq -c .numerics "$TMP/an_golden/report.json")"
[[ "$(jq -c .numerics "$TMP/an_golden/report.json")" == "$(jq -c .numerics "$TMP/an_approx/report.json")" ]] && ok \
  || bad "animation: approx counts differ from golden's"
grep -q "^warning: traces/scenes/animation.json: wrapped EP values in use" "$TMP/an_golden.err" && ok || bad "animation warning"

# A triangle well inside the range: nothing counted but output clips.
"$RUN" render traces/equilateral_200.trace --backend golden --out "$TMP/eq" --quiet 2> "$TMP/eq.err" && ok || bad "eq"
jq -e "($wraps) == 0 and .numerics.triangles_affected == 0 and .numerics.first_triangle_affected == null" \
  "$TMP/eq/report.json" >/dev/null && ok || bad "equilateral: $(jq -c .numerics "$TMP/eq/report.json")"
[[ ! -s "$TMP/eq.err" ]] && ok || bad "equilateral warned: $(cat "$TMP/eq.err")"

# The RTL's wrap detector counts what golden counts (hw/dda/dda_limits.sv).
"$RUN" render "$TMP/huge.trace" --backend rtl --out "$TMP/rtl" --quiet 2> "$TMP/rtl.err" && ok || bad "rtl render"
[[ "$(jq -c .numerics "$TMP/golden/report.json")" == "$(jq -c .numerics "$TMP/rtl/report.json")" ]] && ok \
  || bad "rtl counts differ from golden's: $(jq -c .numerics "$TMP/rtl/report.json")"
grep -q "^warning: $TMP/huge.trace: wrapped EP values in use" "$TMP/rtl.err" && ok || bad "rtl warning: $(cat "$TMP/rtl.err")"

# robust.json: far edges as constants draw every pixel with no D wider, on every back end alike.
for b in golden approx rtl; do
  "$RUN" render "$TMP/huge.trace" --backend $b --config config/presets/robust.json --out "$TMP/${b}_robust" --quiet \
    2> "$TMP/${b}_robust.err" && ok || bad "$b robust render"
  jq -e "($wraps) == 0 and .pixels_written == 1048576 and .warnings == []" "$TMP/${b}_robust/report.json" >/dev/null \
    && ok || bad "$b robust: $(jq -c '[.pixels_written, .numerics.D1]' "$TMP/${b}_robust/report.json")"
done
[[ "$(jq -r .image_sha256 "$TMP/ref/report.json")" == "$(jq -r .image_sha256 "$TMP/rtl_robust/report.json")" ]] \
  && ok || bad "robust rtl frame differs from the reference's"

# Seams: a fan of 64 transparent triangles of one surface (INTERIOR and
# SURFACE fields) blends pixels on its spokes twice (Q = 0: the shared edges;
# Q = 1: the fringes too), counted and warned; the fill rule and the edge
# flags draw each pixel once, in the reference as in the hardware.
{
  echo "girtd-trace 1 triangle"
  echo "q 0"
  for k in 0 1 2 3; do  # four quarter-circle triangles around (512, 512), spokes shared
    case $k in 0) a="812 512"; c="512 812";; 1) a="512 812"; c="212 512";; 2) a="212 512"; c="512 212";; 3) a="512 212"; c="812 512";; esac
    echo "tri 512 512 1000 200 100 50 0.5  $a 1000 200 100 50 0.5  $c 1000 200 100 50 0.5  5 0"
  done
} > "$TMP/fan4.trace"
for b in reference golden approx; do
  "$RUN" render "$TMP/fan4.trace" --backend $b --out "$TMP/fan_$b" --quiet 2> "$TMP/fan_$b.err" && ok || bad "fan $b"
  # Four spokes of 300 pixels besides the centre, each drawn twice, the centre
  # four times: 1203. (The reference's inclusive float test loses the spokes'
  # far ends, which lie exactly on the hypotenuses, to rounding.)
  expected=1203; [[ $b == reference ]] && expected=1199
  jq -e ".pixels_reblended == $expected" "$TMP/fan_$b/report.json" >/dev/null && ok \
    || bad "fan $b: $(jq -c .pixels_reblended "$TMP/fan_$b/report.json") seams, $expected expected"
  grep -q "^warning: $TMP/fan4.trace: $expected pixel blends by a surface" "$TMP/fan_$b.err" && ok || bad "fan $b warning"
  "$RUN" render "$TMP/fan4.trace" --backend $b --config config/presets/robust.json --out "$TMP/fanr_$b" --quiet \
    2> "$TMP/fanr_$b.err" && ok || bad "fan robust $b"
  jq -e '.pixels_reblended == 0 and .pixels_blended == .pixels_generated' "$TMP/fanr_$b/report.json" >/dev/null \
    && ok || bad "fan robust $b: $(jq -c '[.pixels_reblended, .pixels_blended]' "$TMP/fanr_$b/report.json")"
done
# The four triangles cover the diamond |x - 512| + |y - 512| <= 300 once:
# its 2 x 300^2 + 2 x 300 + 1 = 180601 lattice points less the 601 on its two
# right-hand edges, which the top-left rule leaves to a neighbour.
for b in reference golden; do
  jq -e '.pixels_generated == 180000' "$TMP/fanr_$b/report.json" >/dev/null && ok \
    || bad "fan robust $b covers $(jq .pixels_generated "$TMP/fanr_$b/report.json") pixels, 180000 expected"
done
jq -e '.pixels_reblended == null' "$TMP/rtl/report.json" >/dev/null && ok || bad "rtl knows seams?"

finish
