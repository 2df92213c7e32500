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

"$GIRTD" render "$TMP/huge.trace" --backend reference --out "$TMP/ref" --quiet && ok || bad "reference"
jq -e '.pixels_written == 1048576 and .numerics == null' "$TMP/ref/report.json" >/dev/null && ok \
  || bad "reference: $(jq -c '[.pixels_written, .numerics]' "$TMP/ref/report.json")"

for b in golden approx; do
  "$GIRTD" render "$TMP/huge.trace" --backend $b --out "$TMP/$b" --quiet 2> "$TMP/$b.err" && ok || bad "$b render"
  r="$TMP/$b/report.json"
  # The picture is wrong, and the run says so: counted, one warning naming D and the option.
  jq -e "($wraps) > 0 and .numerics.triangles_affected == 1 and .numerics.first_triangle_affected == 1
         and .pixels_written < 1048576" "$r" >/dev/null && ok || bad "$b: $(jq -c .numerics "$r")"
  grep -q "^warning: $TMP/huge.trace: wrapped EP values in use (D[0-9] [0-9]*.* in 1 triangle(s); first: triangle 1 drawn (line 11): .*ep.d.int_bits above 12" \
    "$TMP/$b.err" && ok || bad "$b: warning line: $(cat "$TMP/$b.err")"
  jq -e '.warnings | length == 1' "$r" >/dev/null && ok || bad "$b: report warnings"
  # Two more integer bits hold the whole triangle: every pixel, no wrap, no warning.
  "$GIRTD" render "$TMP/huge.trace" --backend $b --config "$TMP/d14.json" --out "$TMP/${b}14" --quiet 2> "$TMP/${b}14.err" \
    && ok || bad "$b d14 render"
  jq -e "($wraps) == 0 and .pixels_written == 1048576 and .warnings == []" "$TMP/${b}14/report.json" >/dev/null && ok \
    || bad "$b with 14 integer bits: $(jq -c '[.pixels_written, .numerics.D1]' "$TMP/${b}14/report.json")"
  [[ ! -s "$TMP/${b}14.err" ]] && ok || bad "$b d14 printed: $(cat "$TMP/${b}14.err")"
done
[[ "$(jq -c .numerics "$TMP/golden/report.json")" == "$(jq -c .numerics "$TMP/approx/report.json")" ]] && ok \
  || bad "approx counts differ from golden's"

# Many triangles, colour and Z wraps in slivers' fringes: approx counts what golden counts.
for b in golden approx; do
  "$GIRTD" render traces/scenes/animation.json --backend $b --out "$TMP/an_$b" --quiet 2> "$TMP/an_$b.err" && ok || bad "an $b"
done
jq -e '.numerics.triangles_affected > 1 and .numerics.first_triangle_affected > 1' "$TMP/an_golden/report.json" >/dev/null \
  && ok || bad "animation: $(jq -c .numerics "$TMP/an_golden/report.json")"
[[ "$(jq -c .numerics "$TMP/an_golden/report.json")" == "$(jq -c .numerics "$TMP/an_approx/report.json")" ]] && ok \
  || bad "animation: approx counts differ from golden's"
grep -q "^warning: traces/scenes/animation.json: wrapped EP values in use" "$TMP/an_golden.err" && ok || bad "animation warning"

# A triangle well inside the range: nothing counted but output clips.
"$GIRTD" render traces/equilateral_200.trace --backend golden --out "$TMP/eq" --quiet 2> "$TMP/eq.err" && ok || bad "eq"
jq -e "($wraps) == 0 and .numerics.triangles_affected == 0 and .numerics.first_triangle_affected == null" \
  "$TMP/eq/report.json" >/dev/null && ok || bad "equilateral: $(jq -c .numerics "$TMP/eq/report.json")"
[[ ! -s "$TMP/eq.err" ]] && ok || bad "equilateral warned: $(cat "$TMP/eq.err")"

finish
