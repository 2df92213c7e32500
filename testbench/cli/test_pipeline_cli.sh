#!/usr/bin/env bash
# The SystemC pipeline's back ends (approx, rtl) from the command line: the
# same frames as golden, the throughput keys, refusals, dump, progress.
# Usage: test_pipeline_cli.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"

sha() { jq -r .image_sha256 "$1/report.json"; }

# 1. Every frame of a two-frame trace is golden's, on both timed back ends.
for b in golden approx rtl; do
  "$RUN" render traces/equilateral_200.trace --backend $b --frames all --out "$TMP/eq_$b" --quiet && ok || bad "$b render"
done
for b in approx rtl; do
  for f in frame_000.png frame_001.png frame.png; do
    cmp -s "$TMP/eq_golden/$f" "$TMP/eq_$b/$f" && ok || bad "$b $f differs from golden's"
  done
  jq -e '.pixels_generated == (.pixels_written + .pixels_blended + .pixels_z_rejected + .pixels_dropped)' \
    "$TMP/eq_$b/report.json" >/dev/null && ok || bad "$b: pixel accounting"
done

# 2. A model through the timed front end: same counts as the untimed one.
for b in golden approx; do
  "$RUN" render traces/models/star.obj --backend $b --out "$TMP/star_$b" --quiet && ok || bad "star $b"
done
[[ "$(jq -c .frontend "$TMP/star_golden/report.json")" == "$(jq -c .frontend "$TMP/star_approx/report.json")" ]] \
  && ok || bad "front-end counts differ between golden and approx"
[[ "$(sha "$TMP/star_golden")" == "$(sha "$TMP/star_approx")" ]] && ok || bad "star: approx frame differs"
# The front end runs once per render, on either kind of back end.
for b in golden approx; do
  jq -e '.frontend_passes == 1' "$TMP/star_$b/report.json" >/dev/null && ok \
    || bad "star on $b ran the front end $(jq .frontend_passes "$TMP/star_$b/report.json") times"
done

# 3. The throughput keys: present, non-null, consistent.
r="$TMP/star_approx/report.json"
for k in modeled_time_s modeled_mpixels_per_s back_end_mpixels_per_s bottleneck target_met cache.accesses \
         cache.page_misses cache.nac time_split.dda_busy_s time_split.dda_fifo_full_s time_split.dda_starved_s \
         time_split.had_page_wait_s preparer_triangles_per_s preparer_capacity_triangles_per_s \
         target_preparer_triangles_per_s stages.lighting.busy_s stages.dda.starved_s stages.had.fifo_in_max; do
  jq -e ".$k != null" "$r" >/dev/null && ok || bad "report lacks $k"
done
jq -e '.not_modeled == []' "$r" >/dev/null && ok || bad "approx leaves keys unmodeled"
check_registry "$r"
jq -e '.stage_order == ["culling","lighting","view","depth_clip","projection","triangulator","window_clip","depth_sort","preparer","dda","had"]' \
  "$r" >/dev/null && ok || bad "stage order: $(jq -c .stage_order "$r")"
jq -e '(.modeled_mpixels_per_s - .pixels_generated / .modeled_time_s / 1e6 | fabs) < 1e-6' "$r" >/dev/null \
  && ok || bad "modeled rate is not pixels over modeled time"
jq -e '[.stages[] | select(.fifo_in_max != null) | .fifo_in_max] | max <= 16' "$r" >/dev/null \
  && ok || bad "a FIFO held more than its depth"
jq -e '.bottleneck as $b | .stages[$b].busy_s == ([.stages[].busy_s] | max)' "$r" >/dev/null \
  && ok || bad "bottleneck is not the busiest stage"
grep -qE "^(PASS|FAIL): modeled .* Mpixel/s against the 20 Mpixel/s target" "$TMP/star_approx/report.md" \
  && ok || bad "report.md lacks the target verdict"

# 4. Refusals: exit 2, one line, no output.
"$RUN" render traces/thesis/equilateral_200.trace --backend approx --out "$TMP/th" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && $(wc -l < "$TMP/err") -eq 1 && ! -e "$TMP/th" ]] && ok || bad "thesis trace on approx: exit $rc"
# The memory-side options: approx models them all; the frame is unchanged
# and approx's time is rtl's.
printf '{"had": {"write_behind": true, "prefetch": true, "dirty_bits": true}, "vram": {"steal_every_ns": 1000.0}}\n' \
  > "$TMP/mem.json"
for b in approx rtl; do
  "$RUN" render traces/equilateral_200.trace --backend $b --config "$TMP/mem.json" --out "$TMP/mem_$b" --quiet \
    && ok || bad "$b with the memory-side options failed"
  [[ "$(sha "$TMP/mem_$b")" == "$(sha "$TMP/eq_golden")" ]] && ok || bad "the memory-side options changed the frame on $b"
done
[[ "$(jq .modeled_time_s "$TMP/mem_approx/report.json")" == "$(jq .modeled_time_s "$TMP/mem_rtl/report.json")" ]] \
  && ok || bad "approx's time with the memory-side options differs from rtl's"

# 5. --dump from a timed back end equals golden's dump.
"$RUN" render traces/z_overlap.trace --backend golden --out "$TMP/zg" --dump "dda=$TMP/zg.dda" --quiet && ok || bad "dump golden"
"$RUN" render traces/z_overlap.trace --backend approx --out "$TMP/za" --dump "dda=$TMP/za.dda" --quiet && ok || bad "dump approx"
cmp -s <(grep -v '^#' "$TMP/zg.dda") <(grep -v '^#' "$TMP/za.dda") && ok || bad "approx dump differs from golden's"
# A scene's triangles as they left the timed front end equal golden's.
for b in golden approx; do
  "$RUN" render traces/scenes/animation.json --backend $b --out "$TMP/an_$b" --dump "triangle=$TMP/an_$b.trace" \
    --quiet && ok || bad "triangle dump $b"
done
cmp -s <(grep -v '^#' "$TMP/an_golden.trace") <(grep -v '^#' "$TMP/an_approx.trace") && ok \
  || bad "approx's triangle dump differs from golden's"

# 6. A run longer than a second shows progress on a terminal, and not
#    when stderr is a file. (The demo scene alone takes under a second on
#    rtl since the tick warp: three frames of it.)
script -qec "'$GIRTD' render traces/scenes/demo.json --backend rtl --repeat 3 --out '$TMP/win' --quiet" /dev/null \
  > "$TMP/tty" 2>&1 || true
[[ -s "$TMP/win/report.json" ]] && ok || bad "render on a terminal"
grep -qE "\[girtd\] rtl, frame [1-3]/3: [0-9]+/[0-9]+ objects in \([0-9]+ %\), [0-9]+ triangles drawn" "$TMP/tty" && ok || bad "no progress line: $(tail -c 300 "$TMP/tty")"
"$RUN" render traces/scenes/window.json --backend rtl --out "$TMP/win2" --quiet 2> "$TMP/err" && ok || bad "rtl render"
check_registry "$TMP/win2/report.json"
[[ ! -s "$TMP/err" ]] && ok || bad "stderr not empty without a terminal: $(head -c 200 "$TMP/err")"

# approx is rtl's timing to the tick, also where the frame clear is no whole
# number of DDA clocks (230 ns VRAM cycles) or takes no time at all.
printf '{"vram": {"cycle_ns": 230.0}}\n' > "$TMP/vram230.json"
printf '{"vram": {"serial_transfers": 0}}\n' > "$TMP/noclear.json"
for cfg in vram230 noclear; do
  for b in approx rtl; do
    "$RUN" render traces/equilateral_200.trace --backend $b --config "$TMP/$cfg.json" --out "$TMP/$cfg-$b" --quiet \
      && ok || bad "$cfg: $b render"
  done
  [[ "$(jq -c '[.modeled_time_s, .time_split]' "$TMP/$cfg-approx/report.json")" == \
     "$(jq -c '[.modeled_time_s, .time_split]' "$TMP/$cfg-rtl/report.json")" ]] \
    && ok || bad "$cfg: approx's time differs from rtl's"
done

# render --repeat N: a static input as N frames, judged by the sustained rate
# (frames 2..N, the pipeline full). The first frame pays for filling the
# pipeline and its clear is not overlapped, so sustained >= the rate over all
# frames; approx and rtl agree on it; one frame has none; an animation is
# refused (it is not static).
for b in approx rtl; do
  "$RUN" render traces/scenes/window.json --backend $b --repeat 3 --out "$TMP/rep-$b" --quiet     && ok || bad "--repeat 3 on $b"
done
R=$TMP/rep-approx/report.json
jq -e '.frames == 3 and .sustained_mpixels_per_s >= .modeled_mpixels_per_s
       and .target_met == (.sustained_mpixels_per_s >= .target_mpixels_per_s)' "$R" >/dev/null   && ok || bad "sustained: $(jq -c '[.frames, .sustained_mpixels_per_s, .modeled_mpixels_per_s, .target_met]' "$R")"
[[ "$(jq .sustained_mpixels_per_s "$R")" == "$(jq .sustained_mpixels_per_s "$TMP/rep-rtl/report.json")" ]] \
  && ok || bad "approx and rtl sustain different rates"
grep -qE "^(PASS|FAIL): sustained .* Mpixel/s against the 20 Mpixel/s target" "$TMP/rep-approx/report.md" \
  && ok || bad "report.md does not judge the sustained rate"
jq -e '.sustained_mpixels_per_s == null' "$TMP/win2/report.json" >/dev/null && ok || bad "one frame has a sustained rate"
"$RUN" render traces/scenes/animation.json --backend approx --repeat 2 --out "$TMP/rep-anim" --quiet 2> "$TMP/err"
[[ $? -eq 2 ]] && grep -q "^--repeat: traces/scenes/animation.json has [0-9]* frames" "$TMP/err" \
  && ok || bad "--repeat on an animation: $(cat "$TMP/err")"

finish
