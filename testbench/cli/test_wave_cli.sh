#!/usr/bin/env bash
# render --wave: one FST of the RTL and the SystemC pipeline. The file
# parses (fst2vcd), holds the named signals, keeps to its window and scopes,
# its .gtkw names only signals that exist, and the waveform agrees with the
# run's own log of pushed pixels at the clock the DDA pushed them.
# Usage: test_wave_cli.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"
Q="python3 $ROOT/testbench/cli/vcd_query.py"

# 1. A window of 60 us while the DDA draws (the demo trace's first triangles).
"$GIRTD" render traces/demo.trace --backend rtl --out "$TMP/d" --wave "$TMP/d/wave.fst" --wave-window 200us:260us \
  --quiet && ok || bad "render --wave"
for f in wave.fst wave.gtkw wave.pixels.csv frame.png report.json; do [[ -s "$TMP/d/$f" ]] && ok || bad "missing $f"; done
fst2vcd -f "$TMP/d/wave.fst" -o "$TMP/d.vcd" >/dev/null 2>&1 && ok || bad "fst2vcd cannot read the waveform"
grep -q '^\$timescale' "$TMP/d.vcd" && grep -A1 '^\$timescale' "$TMP/d.vcd" | grep -q "1ns" && ok || bad "timescale is not 1 ns"
$Q "$TMP/d.vcd" names > "$TMP/names"
for s in pipeline.frame pipeline.preparer.busy pipeline.preparer.fifo_in pipeline.back_end.starved \
         pipeline.window_clip.items_out TOP.girtd_backend.clk_i TOP.girtd_backend.u_dda.state_q \
         TOP.girtd_backend.u_had.state_q TOP.girtd_backend.pixel_x_o; do
  grep -q "^$s\(\[\|$\)" "$TMP/names" && ok || bad "waveform lacks $s"
done
grep -q "u_vram.mem" "$TMP/names" && bad "the VRAM array was recorded" || ok
read -r first last < <($Q "$TMP/d.vcd" times)
[[ $first -ge 200000 && $last -le 260000 ]] && ok || bad "timestamps $first..$last outside 200000..260000 ns"
[[ $last -ge 259990 ]] && ok || bad "window not recorded to its end ($last)"

# The pixel log against the waveform: X, Y and the push just before the edge.
n=$(($(wc -l < "$TMP/d/wave.pixels.csv") - 1))
[[ $n -gt 100 ]] && ok || bad "only $n pixels logged in the window"
for row in 2 $((n / 2 + 1)) $((n + 1)); do
  IFS=, read -r t x y < <(sed -n "${row}p" "$TMP/d/wave.pixels.csv")
  [[ $t -ge 200000 && $t -le 260000 ]] && ok || bad "logged pixel outside the window: $t"
  [[ $($Q "$TMP/d.vcd" value TOP.girtd_backend.pixel_push_o $((t - 1))) == 1 ]] && ok || bad "no push on the waveform at $t"
  [[ $($Q "$TMP/d.vcd" value TOP.girtd_backend.pixel_x_o $((t - 1))) == "$x" ]] && ok || bad "X at $t is not $x"
  [[ $($Q "$TMP/d.vcd" value TOP.girtd_backend.pixel_y_o $((t - 1))) == "$y" ]] && ok || bad "Y at $t is not $y"
done
# The frame is the same with and without the waveform.
"$GIRTD" render traces/demo.trace --backend golden --out "$TMP/g" --quiet
[[ "$(jq -r .image_sha256 "$TMP/g/report.json")" == "$(jq -r .image_sha256 "$TMP/d/report.json")" ]] && ok || bad "--wave changed the frame"

# 2. The save file names only recorded signals.
missing=0
while read -r sig; do grep -qxF "$sig" "$TMP/names" || { missing=1; echo "  gtkw names $sig"; }; done \
  < <(grep -E '^(pipeline|TOP)\.' "$TMP/d/wave.gtkw")
[[ $missing -eq 0 ]] && ok || bad ".gtkw names signals the waveform lacks"
grep -q '^-SystemC: preparer' "$TMP/d/wave.gtkw" && grep -q '^-RTL: DDA' "$TMP/d/wave.gtkw" && ok || bad "gtkw groups"

# 3. Scopes and a window in DDA cycles; VCD output.
"$GIRTD" render traces/equilateral_200.trace --backend rtl --out "$TMP/s" --wave "$TMP/s/w.vcd" \
  --wave-window 1000cycles:1200cycles --wave-scope TOP.girtd_backend.u_dda --wave-scope pipeline.back_end --quiet \
  && ok || bad "scoped render"
$Q "$TMP/s/w.vcd" names > "$TMP/snames"
grep -q "^TOP.girtd_backend.u_dda.state_q" "$TMP/snames" && grep -q "^pipeline.back_end.busy" "$TMP/snames" && ok \
  || bad "scoped signals missing"
grep -q "u_had\|pipeline.preparer" "$TMP/snames" && bad "signals outside the scopes recorded" || ok
read -r first last < <($Q "$TMP/s/w.vcd" times)
[[ $first -ge 35000 && $last -le 42000 ]] && ok || bad "cycles window: $first..$last outside 35000..42000 ns"

# 4. Recording changes nothing: the same modeled time and counts with and
#    without a waveform, also when the window ends while the DDA waits for
#    the front end (cube.obj's DDA is starved at 110 us).
printf '{"had": {"write_behind": true, "prefetch": true, "dirty_bits": true}}\n' > "$TMP/mem.json"
for run in "traces/directed/nf_rows.dda" "traces/models/cube.obj" "traces/models/cube.obj --config $TMP/mem.json"; do
  input=${run%% *}
  # shellcheck disable=SC2086
  "$GIRTD" render $run --backend rtl --out "$TMP/n0" --quiet
  # A guard against a hang, generous enough for a sanitizer build on a busy machine.
  # shellcheck disable=SC2086
  timeout 900 "$GIRTD" render $run --backend rtl --out "$TMP/n1" --wave "$TMP/n1.fst" --wave-window 0:110us --quiet \
    && ok || bad "$input: --wave run failed or hung"
  for k in modeled_time_s pixels_generated dda_cycles time_split image_sha256; do
    [[ "$(jq -c .$k "$TMP/n0/report.json")" == "$(jq -c .$k "$TMP/n1/report.json")" ]] && ok \
      || bad "$input: --wave changed $k: $(jq -c .$k "$TMP/n0/report.json") vs $(jq -c .$k "$TMP/n1/report.json")"
  done
done

# The approx back end records the SystemC side alone, and changes nothing either.
"$GIRTD" render traces/models/star.obj --backend approx --out "$TMP/a0" --quiet
"$GIRTD" render traces/models/star.obj --backend approx --out "$TMP/a1" --wave "$TMP/a1/w.fst" --wave-window 0:2ms \
  --quiet && ok || bad "approx --wave"
fst2vcd -f "$TMP/a1/w.fst" -o "$TMP/a1.vcd" >/dev/null 2>&1 && ok || bad "approx waveform unreadable"
$Q "$TMP/a1.vcd" names > "$TMP/anames"
grep -q "^pipeline.lighting.busy" "$TMP/anames" && ! grep -q "^TOP" "$TMP/anames" && ok || bad "approx waveform signals"
read -r first last < <($Q "$TMP/a1.vcd" times)
[[ $first -eq 0 && $last -eq 2000000 ]] && ok || bad "approx window $first..$last"
[[ "$(jq -c '[.modeled_time_s, .time_split]' "$TMP/a0/report.json")" == "$(jq -c '[.modeled_time_s, .time_split]' "$TMP/a1/report.json")" ]] \
  && ok || bad "approx --wave changed the timing"

[[ ! -e "$TMP/a1/w.pixels.csv" ]] && ok || bad "approx wrote a pixel log"
"$GIRTD" render traces/models/star.obj --backend approx --out "$TMP/a2" --wave "$TMP/a2.fst" \
  --wave-scope TOP.girtd_backend.u_dda 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/a2" ]] && grep -q "SystemC side alone" "$TMP/err" && ok || bad "approx with an RTL scope: exit $rc"

# 5. Refusals: exit 2, one line, nothing written.
"$GIRTD" render traces/equilateral_200.trace --backend rtl --out "$TMP/b1" --wave "$TMP/b1.fst" \
  --wave-scope TOP.no_such_block 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && $(wc -l < "$TMP/err") -eq 1 && ! -e "$TMP/b1.fst" && ! -e "$TMP/b1" ]] && ok \
  || bad "unknown scope: exit $rc, $(cat "$TMP/err")"
grep -q "names no part of the RTL (scopes include: .*TOP.girtd_backend.u_dda" "$TMP/err" && ok || bad "scope error: $(cat "$TMP/err")"
"$GIRTD" render traces/models/star.obj --backend rtl --out "$TMP/b1p" --wave "$TMP/b1p.fst" \
  --wave-scope pipeline.lightning 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/b1p" ]] && grep -q "pipeline.lighting" "$TMP/err" && ok || bad "stage scope typo: exit $rc"
ls "$TMP" | grep -q "partial" && bad "partial files left behind" || ok
"$GIRTD" render traces/equilateral_200.trace --backend golden --wave "$TMP/b2.fst" --out "$TMP/b2" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/b2" ]] && grep -q "backend rtl" "$TMP/err" && ok || bad "golden --wave: exit $rc"
for w in "5:2" "abc:10" "10parsecs:20"; do
  "$GIRTD" render traces/equilateral_200.trace --backend rtl --wave "$TMP/b3.fst" --wave-window "$w" --out "$TMP/b3" \
    2> "$TMP/err"; rc=$?
  [[ $rc -eq 2 && ! -e "$TMP/b3" ]] && grep -q "^--wave-window" "$TMP/err" && ok || bad "window '$w': exit $rc"
done
"$GIRTD" render traces/equilateral_200.trace --backend rtl --wave "$TMP/b4.png" --out "$TMP/b4" 2> /dev/null; rc=$?
[[ $rc -eq 2 ]] && ok || bad "wave file .png accepted"
"$GIRTD" render traces/equilateral_200.trace --backend rtl --wave "$TMP/b5.fst" --wave-window 1s: --out "$TMP/b5" \
  2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/b5.fst" && ! -e "$TMP/b5" ]] && grep -q "recorded nothing" "$TMP/err" && ok \
  || bad "window after the run: exit $rc"
# The same with --frames all: each frame's PNG was written as the frame
# ended, and goes with the failed run (nothing half-written, no folder).
"$GIRTD" render traces/equilateral_200.trace --backend rtl --frames all --wave "$TMP/b5a.fst" --wave-window 1s: \
  --out "$TMP/b5a" 2> /dev/null; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/b5a" ]] && ok || bad "--frames all after a failed run: exit $rc, left: $(ls -A "$TMP/b5a" 2>&1)"
touch "$TMP/afile"
"$GIRTD" render traces/equilateral_200.trace --backend rtl --wave "$TMP/afile/w.fst" --out "$TMP/b6" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/b6" ]] && ok || bad "waveform under a file: exit $rc"
"$GIRTD" render traces/equilateral_200.trace --backend rtl --wave "$TMP/b7.fst" --out "$TMP/afile/o" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/b7.fst" ]] && ok || bad "output under a file: exit $rc, waveform left: $(ls "$TMP" | grep b7)"

finish
