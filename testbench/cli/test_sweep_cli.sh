#!/usr/bin/env bash
# girtd sweep end to end (docs/interface.md) on traces/sweeps/small.json: 32 points
# (5 axes, one of them setting two keys together) x 2 inputs, 2 frames each.
# - invalid points (a FIFO depth over the built 32) are rows with the
#   reason, not runs; approx runs prefetch (stepped memory side);
# - a point's name is the hash of its merged configuration: the same on
#   every input, different between points;
# - rows carry the sustained rate and the cost; 2 points are spot-checked on
#   rtl and agree;
# - a killed sweep resumes: the rerun gives the clean run's rows (but for
#   wall time);
# - a bad spec is one line `SPEC:LINE: what`, exit 2.
# Usage: test_sweep_cli.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "$0")/cli_lib.sh" "$1" "$2"
S=traces/sweeps/small.json
"$RUN" sweep $S --jobs 2 --out "$TMP/a" > "$TMP/out.txt" 2> "$TMP/err.txt" && ok || bad "sweep failed: $(tail -5 "$TMP/out.txt" "$TMP/err.txt")"
J=$TMP/a/results.json
jq -e '.rows | length == 64' "$J" >/dev/null && ok || bad "rows: $(jq '.rows | length' "$J")"
jq -e '[.rows[] | select(."fifo.dda_had_depth" == 64)] | all(.valid == false and (.invalid | test("fifo.dda_had_depth")))' \
  "$J" >/dev/null && ok || bad "depth 64 not invalid: $(jq -c '[.rows[] | select(."fifo.dda_had_depth" == 64)][0]' "$J")"
jq -e '[.rows[] | select(."had.prefetch" == true and ."fifo.dda_had_depth" != 64)] | length == 16 and all(.valid)' \
  "$J" >/dev/null && ok || bad "prefetch rows: $(jq -c '[.rows[] | select(."had.prefetch" == true)][0]' "$J")"
jq -e '[.rows[] | select(.valid)] | length == 32 and all(.sustained_mpixels_per_s > 0 and .cost > 0
       and (.image_sha256 | length == 64))' "$J" >/dev/null && ok || bad "valid rows: $(jq -c '[.rows[] | select(.valid)][0]' "$J")"
jq -e '[.rows[].point | test("^[0-9a-f]{16}$")] | all' "$J" >/dev/null && ok || bad "point names"
jq -e '(.points | length == 32) and ([.points[].point] | unique | length == 32)' "$J" >/dev/null \
  && ok || bad "points not distinct: $(jq '[.points[].point] | unique | length' "$J")"
jq -e '[.rows | group_by(.point)[] | length == 2] | all' "$J" >/dev/null && ok || bad "a point's rows have different names"
jq -e '[.rows[] | select(.rtl_agrees != null)] | length == 4 and all(.rtl_agrees == true)' "$J" >/dev/null \
  && ok || bad "spot checks: $(jq -c '[.rows[] | select(.rtl_agrees != null) | [.point, .rtl_agrees]]' "$J")"
# yosys sizes the DDA once per width set: no axis here changes a width.
jq -e '[.rows[] | select(.valid) | .cost_yosys_dda_cells] | (.[0] > 1000) and (unique | length == 1)' "$J" >/dev/null \
  && ok || bad "yosys cells: $(jq -c '[.rows[] | select(.valid) | .cost_yosys_dda_cells] | unique' "$J")"
# Pages of 16 pixels, 16 x 1 or 4 x 4, read 16 cells at once: the same VRAM.
jq -e '[.rows[] | select(.valid)] | group_by(.page | tostring) | map(.[0].cost_vram_chips) | unique | length == 1' "$J" \
  >/dev/null && ok || bad "page shapes of 16 pixels cost different VRAM"
head -1 "$TMP/a/results.csv" | grep -q '^dda.clock_ns,fifo.dda_had_depth,had.access_ns,had.prefetch,page,point,input,valid' \
  && ok || bad "csv header: $(head -1 "$TMP/a/results.csv")"
grep -q "## Pareto front" "$TMP/a/sweep.md" && ok || bad "sweep.md"
[[ $(head -c 4 "$TMP/a/rate_vs_cost.png" | tail -c 3) == PNG ]] && ok || bad "no plot"
# sweep.html in headless Chromium: no errors, the chart holds every valid point and the front.
tools/page_shot.sh dom "$TMP/a/sweep.html" > "$TMP/sweep_dom.html"
grep -q 'data-errors="0"' "$TMP/sweep_dom.html" && grep -q 'data-ready="1"' "$TMP/sweep_dom.html" && ok \
  || bad "sweep.html: $(grep -o '<body[^>]*>' "$TMP/sweep_dom.html")"
want="data-points=\"$(jq '[.points[] | select(.valid)] | length' "$J")\" data-front=\"$(jq '[.points[] | select(.on_front)] | length' "$J")\""
grep -q "$want" "$TMP/sweep_dom.html" && ok || bad "sweep.html chart: $(grep -o '<div id="front_chart"[^>]*>' "$TMP/sweep_dom.html"), want $want"

# Killed after a few rows, then rerun: the same rows as the clean run.
setsid "$RUN" sweep $S --jobs 2 --out "$TMP/b" > "$TMP/b.txt" 2>&1 &
pid=$!
# Waits for rows, not for a time: a loaded CI machine wrote 13 rows in 10 s.
for _ in $(seq 1200); do [[ $(ls "$TMP/b/rows" 2>/dev/null | grep -c '\.json$') -ge 10 ]] && break; sleep 0.25; done
kill -- -"$pid" 2>/dev/null; wait "$pid" 2>/dev/null
n=$(ls "$TMP/b/rows" | grep -c '\.json$')
[[ $n -ge 10 && $n -lt 64 ]] && ok || bad "the kill came at $n rows"
"$RUN" sweep $S --jobs 2 --out "$TMP/b" > "$TMP/b2.txt" 2>&1 && ok || bad "resumed sweep failed"
grep -q "already in" "$TMP/b2.txt" && ok || bad "no resume line"
norm='[.rows[] | del(.wall_s)] | sort_by(.point, .input)'
if [[ "$(jq -c "$norm" "$TMP/b/results.json")" == "$(jq -c "$norm" "$J")" ]]; then ok
else bad "resumed rows differ from the clean run's: $(diff <(jq -S "$norm" "$TMP/b/results.json") <(jq -S "$norm" "$J") | head -12)"; fi

printf '{\n  "inputs": ["%s/traces/demo.trace"],\n  "axes": {"dda.clock_ns": [35]},\n  "colour": 1\n}\n' "$ROOT" > "$TMP/bad.json"
"$RUN" sweep "$TMP/bad.json" --out "$TMP/c" > /dev/null 2> "$TMP/err"
rc=$?
[[ $rc -eq 2 && $(wc -l < "$TMP/err") -eq 1 ]] && grep -q "^$TMP/bad.json:4: colour: unknown key" "$TMP/err" \
  && ok || bad "bad spec: rc $rc, $(cat "$TMP/err")"
[[ ! -e "$TMP/c" ]] && ok || bad "a bad spec wrote output"
# Spec mistakes the parser catches at their line: an unknown key, a value of
# the wrong kind, a key two axes set.
for axes in '"dda.clok_ns": [35]' '"dda.clock_ns": ["fast"]' '"dda.clock_ns": [35], "both": [{"dda.clock_ns": 30}]'; do
  printf '{\n  "inputs": ["%s/traces/demo.trace"],\n  "axes": {%s}\n}\n' "$ROOT" "$axes" > "$TMP/bad2.json"
  "$RUN" sweep "$TMP/bad2.json" --out "$TMP/d" > /dev/null 2> "$TMP/err"
  [[ $? -eq 2 ]] && grep -q "^$TMP/bad2.json:3: axes\." "$TMP/err" && ok || bad "spec axes {$axes}: $(cat "$TMP/err")"
done
[[ ! -e "$TMP/d" ]] && ok || bad "a bad spec wrote output"
finish
