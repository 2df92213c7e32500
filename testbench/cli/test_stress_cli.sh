#!/usr/bin/env bash
# girtd stress: the fast subset of every family (or, with --full, every case)
# on the thesis' configuration (no FAIL: a limit hit is counted and warned)
# and on config/presets/robust.json (the fixes: huge, shared and zrange exact).
# Usage: test_stress_cli.sh GIRTD_BINARY REPO_ROOT [--full]
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"
subset=--fast; [[ "${3:-}" == --full ]] && subset=""

verdict() { awk -F, -v c="$2" '$2 == c {print $3}' "$1/results.csv"; }

"$RUN" stress $subset --out "$TMP/thesis" > "$TMP/thesis.out" 2> "$TMP/thesis.err" && ok || bad "thesis: exit $?: $(tail -3 "$TMP/thesis.err")"
grep -Eq '^[0-9]+ passed, [0-9]+ flagged, 0 failed$' "$TMP/thesis.out" && ok || bad "thesis closing line: $(cat "$TMP/thesis.out")"
rows=$(($(wc -l < "$TMP/thesis/results.csv") - 1))
[[ $rows -ge 24 ]] && ok || bad "thesis: only $rows cases"
[[ $(awk -F, 'NR > 1 {print $1}' "$TMP/thesis/results.csv" | sort -u | wc -l) == 11 ]] && ok || bad "not every family ran"
# The design as written: the screen-filling triangle and the seams are flagged, never silent.
[[ "$(verdict "$TMP/thesis" huge_cover_1500)" == flagged ]] && ok || bad "huge_cover_1500: $(verdict "$TMP/thesis" huge_cover_1500)"
[[ "$(verdict "$TMP/thesis" shared_fan64_q0)" == flagged ]] && ok || bad "shared_fan64_q0: $(verdict "$TMP/thesis" shared_fan64_q0)"

# The fixes are judged where they apply (every family runs on robust.json under --full).
families=(--family huge --family shared --family zrange --family fine); [[ -z "$subset" ]] && families=()
"$RUN" stress $subset "${families[@]}" --config config/presets/robust.json --out "$TMP/robust" > "$TMP/robust.out" 2> "$TMP/robust.err" \
  && ok || bad "robust: exit $?: $(tail -3 "$TMP/robust.err")"
awk -F, 'NR > 1 && ($1 == "huge" || $1 == "shared" || $1 == "zrange") && $3 != "exact" {print $2 ": " $3 " " $10}' \
  "$TMP/robust/results.csv" > "$TMP/robust.notexact"
[[ ! -s "$TMP/robust.notexact" ]] && ok || bad "robust: $(cat "$TMP/robust.notexact")"
# Fine meshes: their needles wrap and clamp as the thesis wrote the design,
# and with steep attributes limited not one triangle does.
awk -F, 'NR > 1 && $1 == "fine" && $6 == 0 {n++} END {exit n > 0 ? 1 : 0}' "$TMP/thesis/results.csv" \
  && ok || bad "thesis: a fine case with no counted triangle"
awk -F, 'NR > 1 && $1 == "fine" && ($6 != 0 || $3 != "exact") {print $2 ": " $3 ", " $6 " triangles counted"}' \
  "$TMP/robust/results.csv" > "$TMP/robust.fine"
[[ -s "$TMP/robust/results.csv" && ! -s "$TMP/robust.fine" ]] && grep -q '^fine,' "$TMP/robust/results.csv" && ok \
  || bad "robust, fine: $(cat "$TMP/robust.fine")"

# A render that does not finish is a FAIL, not a wait: exit 1.
"$RUN" stress --fast --family limits --timeout 0.001 --out "$TMP/hang" > "$TMP/hang.out" 2> "$TMP/hang.err"
[[ $? == 1 ]] && ok || bad "a hang did not exit 1"
grep -q "FAIL .*a hang" "$TMP/hang.err" && ok || bad "hang verdict: $(cat "$TMP/hang.err")"
# Usage errors exit 2.
"$RUN" stress --family nope > /dev/null 2>&1; [[ $? == 2 ]] && ok || bad "unknown family not refused"

finish
