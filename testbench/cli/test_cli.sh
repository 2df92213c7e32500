#!/usr/bin/env bash
# End-to-end checks of the girtd command line (docs/interface.md): outputs, report
# keys, exit codes and the one-line error format, dump and replay.
# Usage: test_cli.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"

# 1. A render writes frame.png, report.json and report.md with every contract key.
"$GIRTD" render traces/equilateral_200.trace --backend golden --out "$TMP/eq" --quiet && ok || bad "render exit"
for f in frame.png report.json report.md; do [[ -s "$TMP/eq/$f" ]] && ok || bad "missing $f"; done
# The contract's keys (docs/interface.md), each present; then exactly
# the registry's keys, on both untimed back ends.
for k in backend input triangles_in triangles_drawn pixels_generated pixels_written pixels_blended \
         pixels_z_rejected pixels_dropped dda_cycles dda_efficiency clock_ns modeled_time_s \
         modeled_mpixels_per_s target_mpixels_per_s bottleneck cache.accesses cache.page_misses cache.nac \
         stages.dda.items stages.dda.busy_s stages.dda.stall_s wall_s image_sha256 not_modeled warnings; do
  jq -e --arg k "$k" '($k | split(".")) as $p | getpath($p[:-1]) | has($p[-1])' \
    "$TMP/eq/report.json" >/dev/null && ok || bad "report.json lacks $k"
done
jq -e '.target_mpixels_per_s == 20 and .modeled_time_s == null and (.not_modeled | index("modeled_time_s"))' \
  "$TMP/eq/report.json" >/dev/null && ok || bad "golden: modeled time not null and listed in not_modeled"
check_registry "$TMP/eq/report.json"
"$GIRTD" render traces/equilateral_200.trace --backend reference --out "$TMP/eq_ref" --quiet && ok || bad "reference"
check_registry "$TMP/eq_ref/report.json"
jq -e '.dda_cycles == null and .preparer == null and (.not_modeled | index("dda_cycles"))' "$TMP/eq_ref/report.json" \
  >/dev/null && ok || bad "reference: dda_cycles not null and listed"
grep -q "(holds)" "$TMP/eq/report.md" && ok || bad "pixel accounting identity does not hold"
ls "$TMP/eq" | grep -q partial && bad "partial file left behind" || ok

# 2. Bad input: exit 2, one line FILE:LINE: what, no output directory.
printf 'girtd-trace 1 triangle\ntri 1 2 3\n' > "$TMP/broken.trace"
"$GIRTD" render "$TMP/broken.trace" --out "$TMP/broken_out" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 ]] && ok || bad "malformed trace gave exit $rc"
grep -qE "broken.trace:2: " "$TMP/err" && ok || bad "error line not FILE:LINE: $(cat "$TMP/err")"
[[ $(wc -l < "$TMP/err") -eq 1 ]] && ok || bad "error is not one line"
[[ ! -e "$TMP/broken_out" ]] && ok || bad "output written for bad input"

printf 'girtd-trace 1 triangle\ntri 0 0 0 0 0 0 1  9 0 0 0 0 0 nan  0 9 0 0 0 0 1\n' > "$TMP/nan.trace"
"$GIRTD" render "$TMP/nan.trace" --out "$TMP/nan_out" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 ]] && grep -q "nan.trace:2: " "$TMP/err" && ok || bad "NaN not rejected (exit $rc)"

"$GIRTD" render "$TMP/does_not_exist.trace" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 ]] && grep -q "does_not_exist.trace: no such file" "$TMP/err" && ok || bad "missing file (exit $rc)"

# Endless streams stop at the readers' bounds (traces/FORMAT.md): one line,
# exit 2, nothing written; timeout only catches a hang.
timeout 120 "$GIRTD" render /dev/zero --out "$TMP/zero" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/zero" && $(wc -l < "$TMP/err") -eq 1 ]] && grep -q "^/dev/zero:1: a line longer than 64 MiB" "$TMP/err" \
  && ok || bad "/dev/zero as a trace: exit $rc: $(head -c 300 "$TMP/err")"
timeout 120 "$GIRTD" render traces/equilateral_200.trace --config /dev/zero --out "$TMP/zero" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/zero" && $(wc -l < "$TMP/err") -eq 1 ]] && grep -q "^/dev/zero: larger than 256 MiB" "$TMP/err" \
  && ok || bad "/dev/zero as a configuration: exit $rc: $(head -c 300 "$TMP/err")"

# A name a file gives may hold bytes of no UTF-8 character (the mutation
# campaign's two crashes: report.json could not be written, exit 3): the
# warning writes them \xNN, on stderr and in report.json alike.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl \xff\xfe\nf 1 2 3\n' > "$TMP/bad_utf8.obj"
"$GIRTD" render "$TMP/bad_utf8.obj" --out "$TMP/bad_utf8" --quiet 2> "$TMP/err"; rc=$?
[[ $rc -eq 0 ]] && grep -qF "usemtl '\xff\xfe'" "$TMP/err" \
  && [[ $(jq -r '.warnings[0]' "$TMP/bad_utf8/report.json") == "$(sed -n 's/^warning: //p' "$TMP/err")" ]] \
  && ok || bad "bytes of no UTF-8 character in a warning: exit $rc: $(head -c 300 "$TMP/err")"

"$GIRTD" render traces/equilateral_200.trace --backend nosuch --out "$TMP/nosuch" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/nosuch" && $(wc -l < "$TMP/err") -eq 1 ]] && grep -q "backend" "$TMP/err" && ok \
  || bad "unknown back end gave exit $rc: $(cat "$TMP/err")"
# What a back end cannot do is refused before anything is read (the
# registry's refusals): waveforms need the SystemC pipeline, sampled timing
# is approx's.
"$GIRTD" render traces/equilateral_200.trace --backend golden --wave "$TMP/w.fst" --out "$TMP/refused" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/refused" && "$(cat "$TMP/err")" == "--wave: waveforms record the SystemC pipeline: use --backend rtl (or approx)" ]] \
  && ok || bad "--wave on golden: exit $rc, $(cat "$TMP/err")"
"$GIRTD" render traces/equilateral_200.trace --backend rtl --sample-timing 0.1 --out "$TMP/refused" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/refused" && "$(cat "$TMP/err")" == "--sample-timing: sampled timing is an estimator of the approx back end: use --backend approx" ]] \
  && ok || bad "--sample-timing on rtl: exit $rc, $(cat "$TMP/err")"
# A back end without a DDA has no DDA parameter sets to dump: refused before the input is read.
"$GIRTD" render traces/equilateral_200.trace --backend reference --dump "dda=$TMP/refused.dda" --out "$TMP/refused" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/refused" && ! -e "$TMP/refused.dda" && "$(cat "$TMP/err")" == "--dump: dda: the reference back end has no DDA: dump dda from a back end that has one" ]] \
  && ok || bad "--dump dda on reference: exit $rc, $(cat "$TMP/err")"
# A thesis-level trace is the appendix program's input, at no stage boundary: not a dump level.
"$GIRTD" render traces/demo.trace --dump "thesis=$TMP/refused.thesis" --out "$TMP/refused" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/refused" && ! -e "$TMP/refused.thesis" && "$(cat "$TMP/err")" == "--dump: thesis: not a stage boundary (dump polygon, triangle or dda)" ]] \
  && ok || bad "--dump thesis: exit $rc, $(cat "$TMP/err")"
# Enumerated and ranged options are refused by the parser, one line, exit 2.
for args in "--frames some" "--aa -1" "--level quad" "--wave-window 0:1us"; do
  "$GIRTD" render traces/equilateral_200.trace $args --out "$TMP/badopt" 2> "$TMP/err"; rc=$?
  [[ $rc -eq 2 && ! -e "$TMP/badopt" && $(wc -l < "$TMP/err") -eq 1 ]] && ok || bad "render $args: exit $rc, $(cat "$TMP/err")"
done
for args in "--stall 2" "--random -3"; do
  "$GIRTD" regress $args 2> "$TMP/err" > /dev/null; rc=$?
  [[ $rc -eq 2 ]] && ok || bad "regress $args: exit $rc"
done
"$GIRTD" bench --bless 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 ]] && grep -q "pipeline" "$TMP/err" && ok || bad "bench --bless without --pipeline: exit $rc"

"$GIRTD" render traces/equilateral_200.trace --no-such-option 2> /dev/null; rc=$?
[[ $rc -eq 2 ]] && ok || bad "unknown option gave exit $rc"

printf '{"dda": {"walk_fixx": true}}\n' > "$TMP/bad_config.json"
"$GIRTD" render traces/equilateral_200.trace --config "$TMP/bad_config.json" --out "$TMP/cfg" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 ]] && grep -q "dda.walk_fixx" "$TMP/err" && ok || bad "unknown config key (exit $rc)"

# --config repeats: later files win; a refused value is reported where it was written.
printf '{\n  "fifo": {\n    "dda_had_depth": 40\n  }\n}\n' > "$TMP/depth40.json"
printf '{"fifo": {"dda_had_depth": 8}}\n' > "$TMP/depth8.json"
"$GIRTD" render traces/equilateral_200.trace --config "$TMP/depth40.json" --out "$TMP/cfg40" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/cfg40" ]] \
  && grep -qx "$TMP/depth40.json:3: fifo.dda_had_depth: fifo.dda_had_depth must be at most fifo.max_depth" "$TMP/err" \
  && ok || bad "a depth over fifo.max_depth: exit $rc, $(cat "$TMP/err")"
"$GIRTD" render traces/equilateral_200.trace --config "$TMP/depth40.json" --config "$TMP/depth8.json" \
  --out "$TMP/cfg8" --quiet && [[ "$(jq .config.fifo.dda_had_depth "$TMP/cfg8/report.json")" == 8 ]] \
  && ok || bad "the later --config does not win"

# 3. --dump dda=FILE replays to the same picture.
"$GIRTD" render traces/z_overlap.trace --backend golden --out "$TMP/z1" --dump "dda=$TMP/z.dda" --quiet && ok || bad "dump run"
"$GIRTD" render "$TMP/z.dda" --backend golden --out "$TMP/z2" --quiet && ok || bad "replay run"
h1=$(jq -r .image_sha256 "$TMP/z1/report.json")
h2=$(jq -r .image_sha256 "$TMP/z2/report.json")
[[ -n "$h1" && "$h1" == "$h2" ]] && ok || bad "DDA dump replay differs: $h1 vs $h2"

# 4. --frames all writes one PNG per frame.
"$GIRTD" render traces/equilateral_200.trace --frames all --out "$TMP/all" --quiet && ok || bad "frames all"
[[ -s "$TMP/all/frame_000.png" && -s "$TMP/all/frame_001.png" ]] && ok || bad "per-frame PNGs missing"

# 5. claims prints the table.
"$GIRTD" claims > "$TMP/claims" && ok || bad "claims exit"
grep -q "DDA efficiency" "$TMP/claims" && ok || bad "claims table"
# The front end's load, measured through the timed pipeline: 115 flop per
# triangle is 4.6 Mflop/s at 40,000 triangles/s.
grep -q "^| preparer load | .* | 115 flop per triangle (the thesis' parts): 4.60 Mflop/s .* | confirmed |" "$TMP/claims" \
  && ok || bad "preparer load row: $(grep 'preparer load' "$TMP/claims")"
# The per-stage load on the demo scene, worked out here from an approx
# render's flops: lighting needs more than the thesis' 10 Mflop/s (one light,
# 28 flop per corner and light and more), so the claim is refuted.
"$GIRTD" render traces/scenes/demo.json --backend approx --out "$TMP/demo_approx" --quiet && ok || bad "demo on approx"
lighting=$(jq '.stages.lighting.flops / .frontend.triangles_out * 40000 / 1e6' "$TMP/demo_approx/report.json")
row=$(grep "^| every stage within 10 Mflop/s" "$TMP/claims")
printf -v want "lighting %.1f," "$lighting"
[[ "$row" == *"$want"* && "$row" == *"most: lighting"* ]] && ok || bad "per-stage load row: $row (want $want)"
awk -v m="$lighting" 'BEGIN { exit !(m > 10) }' && [[ "$row" == *"| refuted |" ]] && ok \
  || bad "lighting needs $lighting Mflop/s: the claim must be refuted: $row"


# dda.q_override sets every frame's Q (render --aa is its shorthand). The
# sliver fan is drawn at q 1 in frame 1 and at q 0 in frame 2: with the
# override at 0 both frames are the q 0 picture.
printf '{"dda": {"q_override": 0}}\n' > "$TMP/q0.json"
for how in "--config $TMP/q0.json" "--aa 0" ""; do
  out=$TMP/q${how//[^a-z0-9]/}
  "$GIRTD" render traces/sliver_fan.trace --backend golden --frames all $how --out "$out" --quiet || bad "render $how failed"
  if [[ -n $how ]]; then cmp -s "$out/frame_000.png" "$out/frame_001.png" && ok || bad "$how: frame 1 is not drawn at q 0"
  else cmp -s "$out/frame_000.png" "$out/frame_001.png" && bad "the input's own q is not kept" || ok; fi
done
jq -e '.config.dda.q_override == 0' "$TMP/qaa0/report.json" >/dev/null && ok || bad "--aa not echoed as dda.q_override"
printf '{"dda": {"q_override": 0.3}}\n' > "$TMP/q03.json"
"$GIRTD" render traces/sliver_fan.trace --backend golden --config "$TMP/q03.json" --out "$TMP/q03" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e $TMP/q03 ]] && grep -q "dda.q_override: Q must be 0 or a power of two" "$TMP/err" && ok \
  || bad "Q 0.3 on golden: exit $rc, $(cat "$TMP/err")"
"$GIRTD" render traces/sliver_fan.trace --backend reference --config "$TMP/q03.json" --out "$TMP/q03r" --quiet \
  && ok || bad "the reference back end takes any Q"

finish
