#!/usr/bin/env bash
# Simulator pruning changes nothing but wall time: every sample input
# (traces/workloads.txt) rendered with and without
# --no-prune gives the same frame.png and the same report.json but for
# wall_s and left_out (every count, modeled tick and the image SHA-256).
# Usage: test_prune_cli.sh GIRTD_BINARY REPO_ROOT BACKEND...
source "$(dirname "$0")/cli_lib.sh" "$1" "$2"
shift 2
inputs=$(grep -v "^#" traces/workloads.txt)
for backend in "$@"; do
  for input in $inputs; do
    name=$backend-$(basename "$input")
    "$GIRTD" render "$input" --backend "$backend" --out "$TMP/$name" --quiet 2>/dev/null || { bad "$name: render failed"; continue; }
    "$GIRTD" render "$input" --backend "$backend" --no-prune --out "$TMP/$name-all" --quiet 2>/dev/null \
      || { bad "$name: --no-prune render failed"; continue; }
    cmp -s "$TMP/$name/frame.png" "$TMP/$name-all/frame.png" || bad "$name: frame.png differs"
    if diff <(jq -S 'del(.wall_s, .left_out)' "$TMP/$name/report.json") \
            <(jq -S 'del(.wall_s, .left_out)' "$TMP/$name-all/report.json") > "$TMP/diff"; then ok
    else bad "$name: report differs: $(head -c 600 "$TMP/diff")"; fi
    # Polygon inputs skip the lighting of what is out of view, golden and
    # approx the wrap detector where nothing can wrap; --no-prune skips
    # nothing it can compute.
    units=$(jq -c '[.left_out[].unit]' "$TMP/$name/report.json")
    want='[]'
    [[ $(jq -r .frontend_passes "$TMP/$name/report.json") -gt 0 ]] && want='["lighting"]' || want='["front end"]'
    [[ $backend != rtl ]] && want=$(jq -c '. + ["wrap detector"]' <<< "$want")
    [[ $units == "$want" ]] && ok || bad "$name: left_out $units, expected $want"
    jq -e '.left_out == []' "$TMP/$name-all/report.json" >/dev/null && ok || bad "$name: --no-prune left out something"
    rm -rf "${TMP:?}/$name" "${TMP:?}/$name-all"
  done
done
finish
