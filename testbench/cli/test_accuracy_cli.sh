#!/usr/bin/env bash
# girtd accuracy end to end (docs/interface.md), on the demo trace (Q = 1) and
# the opaque Q = 0 trace llvmpipe can draw:
# - the timing levels against rtl: approx is rtl's time (within 0.1 %), the
#   DDA-bound time is below it (the DDA alone, no memory side, cannot take
#   longer), a sampled estimate carries its interval and no picture error;
# - the pictures: llvmpipe only where it applies, our reference within 2
#   pixels of it there; every complete level draws rtl's frame;
# - a precision variant: more D fraction bits cover closer to the exact
#   reference; a variant the configuration refuses (D below the Norm unit's
#   8 bits) is an invalid row, not a crash;
# - the files: JSON, CSV with the contract's columns, Markdown, PNG plots;
# - bad usage: one line, exit 2.
# Usage: test_accuracy_cli.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "$0")/cli_lib.sh" "$1" "$2"
A=$TMP/timing
"$RUN" accuracy traces/demo.trace traces/opaque_200px.trace --backends rtl,approx,dda_bound,approx_sampled_0.1 \
  --out "$A" > "$TMP/out.txt" 2>&1 && ok || bad "accuracy failed: $(tail -5 "$TMP/out.txt")"
J=$A/accuracy.json
jq -e '.rows | length == 10' "$J" >/dev/null && ok || bad "rows: $(jq '.rows | length' "$J")"
for key in input level variant wall_s sim_pixels_per_s dda_clocks_per_s modeled_time_s time_error image llvmpipe; do
  jq -e --arg k "$key" 'all(.rows[]; has($k))' "$J" >/dev/null && ok || bad "a row lacks $key"
done
jq -e '[.rows[] | select(.level == "approx") | .time_error | fabs < 0.001] | all and length == 2' "$J" >/dev/null \
  && ok || bad "approx against rtl: $(jq -c '[.rows[] | select(.level == "approx") | .time_error]' "$J")"
jq -e '[.rows[] | select(.level == "dda_bound") | .time_error < 0] | all and length == 2' "$J" >/dev/null \
  && ok || bad "dda_bound not below rtl: $(jq -c '[.rows[] | select(.level == "dda_bound") | .time_error]' "$J")"
jq -e '[.rows[] | select(.level == "approx_sampled_0.1") | (.time_ci_half_s > 0 and .image == null
        and (.time_error | fabs) < 0.2)] | all and length == 2' "$J" >/dev/null \
  && ok || bad "sampled rows: $(jq -c '[.rows[] | select(.level == "approx_sampled_0.1")]' "$J" | head -c 600)"
jq -e '[.rows[] | select(.input == "traces/demo.trace") | .llvmpipe == null] | all' "$J" >/dev/null \
  && ok || bad "llvmpipe on a Q = 1 input"
jq -e '.rows[] | select(.input == "traces/opaque_200px.trace" and .level == "reference") | .llvmpipe.coverage_diff <= 2' \
  "$J" >/dev/null && ok || bad "reference against llvmpipe: $(jq -c '.rows[] | select(.level == "reference") | .llvmpipe' "$J")"
jq -e '(.rtl_agreement | length == 2) and all(.rtl_agreement[]; .agrees)' "$J" >/dev/null && ok || bad "rtl agreement"
jq -e '(.levels | map(.level)) == ["rtl", "approx", "dda_bound", "approx_sampled_0.1"]' "$J" >/dev/null \
  && ok || bad "level table: $(jq -c '.levels' "$J")"
head -1 "$A/accuracy.csv" | grep -q '^input,level,variant,wall_s,sim_pixels_per_s,dda_clocks_per_s,modeled_time_s,time_error,time_ci_half_s,image.max_abs' \
  && ok || bad "csv header: $(head -1 "$A/accuracy.csv")"
grep -q "## Timing estimate" "$A/accuracy.md" && ok || bad "accuracy.md"
is_png() { [[ -f $1 && $(head -c 4 "$1" | tail -c 3) == PNG ]]; }
is_png "$A/time_error_vs_wall.png" && ok || bad "no time plot"
# accuracy.html in headless Chromium: no errors, the chart holds every row with a time error, a series per level.
tools/page_shot.sh dom "$A/accuracy.html" > "$TMP/acc_dom.html"
want="data-rows=\"$(jq '[.rows[] | select(.time_error != null and .wall_s > 0)] | length' "$J")\" data-levels=\"$(jq \
  '[.rows[] | select(.time_error != null and .wall_s > 0) | .level] | unique | length' "$J")\""
grep -q 'data-errors="0"' "$TMP/acc_dom.html" && grep -q "$want" "$TMP/acc_dom.html" && ok \
  || bad "accuracy.html: $(grep -oE '<body[^>]*>|<div id="error_chart"[^>]*>' "$TMP/acc_dom.html"), want $want"

P=$TMP/precision
"$RUN" accuracy traces/opaque_200px.trace --backends golden --vary ep.d.frac_bits=6,12,16 --out "$P" \
  > "$TMP/out2.txt" 2>&1 && ok || bad "precision run failed: $(tail -5 "$TMP/out2.txt")"
J=$P/accuracy.json
jq -e '[.rows[] | select(.variant == "ep.d.frac_bits=6") | .invalid | test("ep.d.frac_bits")] | all and length == 2' \
  "$J" >/dev/null && ok || bad "invalid variant: $(jq -c '[.rows[] | select(.variant == "ep.d.frac_bits=6")]' "$J")"
c12=$(jq '.rows[] | select(.level == "golden" and .variant == "ep.d.frac_bits=12") | .image.coverage_diff' "$J")
c16=$(jq '.rows[] | select(.level == "golden" and .variant == "ep.d.frac_bits=16") | .image.coverage_diff' "$J")
[[ -n $c12 && -n $c16 && $c16 -lt $c12 ]] && ok || bad "coverage with 16 D bits ($c16) not below 12 ($c12)"
jq -e '.variants[] | select(.variant == "ep.d.frac_bits=16") | .ep_error.d.after_1024 < 0.01' "$J" >/dev/null \
  && ok || bad "variant EP error: $(jq -c '.variants' "$J" | head -c 400)"
is_png "$P/picture_error_ep_d_frac_bits.png" && ok || bad "no precision plot"
for key in input level variant wall_s sim_pixels_per_s dda_clocks_per_s modeled_time_s time_error image llvmpipe; do
  jq -e --arg k "$key" 'all(.rows[]; has($k))' "$J" >/dev/null && ok || bad "a precision row lacks $key"
done

"$RUN" accuracy traces/demo.trace --backends golden,warp --out "$TMP/x" > "$TMP/err" 2>&1
[[ $? -eq 2 && $(wc -l < "$TMP/err") -eq 1 ]] && grep -q "^--backends: 'warp'" "$TMP/err" && ok || bad "bad level: $(cat "$TMP/err")"
"$RUN" accuracy traces/demo.trace --vary nokey --out "$TMP/x" > "$TMP/err" 2>&1
[[ $? -eq 2 ]] && grep -q "^--vary: expected KEY=V1,V2" "$TMP/err" && ok || bad "bad --vary: $(cat "$TMP/err")"
[[ ! -e "$TMP/x/accuracy.json" ]] && ok || bad "bad usage wrote output"
finish
