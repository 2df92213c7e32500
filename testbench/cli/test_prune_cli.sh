#!/usr/bin/env bash
# Simulator pruning changes nothing but wall time: every sample input
# (traces/workloads.txt) rendered with and without
# --no-prune gives the same frame.png and the same report.json but for
# wall_s and left_out (every count, modeled tick and the image SHA-256).
# On golden and approx this cross-checks the DDA's span path against the
# clocked specification (models/dda/dda_span.hpp) on every sample input.
# Usage: test_prune_cli.sh GIRTD_BINARY REPO_ROOT BACKEND...
source "$(dirname "$0")/cli_lib.sh" "$1" "$2"
shift 2
inputs=$(grep -v "^#" traces/workloads.txt)
for backend in "$@"; do
  for input in $inputs; do
    name=$backend-$(basename "$input")
    "$GIRTD" render "$input" --backend "$backend" --frames all --z-png --out "$TMP/$name" --quiet 2>/dev/null \
      || { bad "$name: render failed"; continue; }
    "$GIRTD" render "$input" --backend "$backend" --frames all --z-png --no-prune --out "$TMP/$name-all" --quiet \
      2>/dev/null || { bad "$name: --no-prune render failed"; continue; }
    for png in "$TMP/$name"/*.png; do  # every frame and the Z buffer
      cmp -s "$png" "$TMP/$name-all/$(basename "$png")" || bad "$name: $(basename "$png") differs"
    done
    if diff <(jq -S 'del(.wall_s, .left_out)' "$TMP/$name/report.json") \
            <(jq -S 'del(.wall_s, .left_out)' "$TMP/$name-all/report.json") > "$TMP/diff"; then ok
    else bad "$name: report differs: $(head -c 600 "$TMP/diff")"; fi
    # What may be left out: lighting (polygon inputs), the wrap detector
    # and the DDA's clock-by-clock runs (golden and approx); --no-prune
    # leaves out nothing.
    allowed='["lighting", "wrap detector", "DDA clocks"]'
    [[ $backend == rtl ]] && allowed='["lighting"]'
    jq -e --argjson ok "$allowed" '[.left_out[].unit] - $ok == []' "$TMP/$name/report.json" >/dev/null \
      && ok || bad "$name: left_out $(jq -c '[.left_out[].unit]' "$TMP/$name/report.json")"
    jq -e '.left_out == []' "$TMP/$name-all/report.json" >/dev/null && ok || bad "$name: --no-prune left out something"
    # Pruning happens: the scene with most of it out of view leaves lighting
    # out (its 2,304 polygons out of view), and golden and approx leave out
    # the detector of triangles that cannot wrap, and compute their runs as
    # spans.
    if [[ $input == traces/scenes/out_of_view.json ]]; then
      jq -e '.left_out[] | select(.unit == "lighting") | .reason | test("^2304 polygons")' "$TMP/$name/report.json" \
        >/dev/null && ok || bad "$name: lighting not left out: $(jq -c .left_out "$TMP/$name/report.json")"
      [[ $backend == rtl ]] || jq -e 'any(.left_out[]; .unit == "wrap detector")' "$TMP/$name/report.json" >/dev/null \
        && ok || bad "$name: wrap detector not left out"
      [[ $backend == rtl ]] || jq -e 'any(.left_out[]; .unit == "DDA clocks")' "$TMP/$name/report.json" >/dev/null \
        && ok || bad "$name: no DDA clocks computed as spans"
    fi
    rm -rf "${TMP:?}/$name" "${TMP:?}/$name-all"
  done
done
finish
