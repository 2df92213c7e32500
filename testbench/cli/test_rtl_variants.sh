#!/usr/bin/env bash
# RTL variants on demand (sim/rtl/rtl_variants.hpp): a configuration whose
# widths, layouts or depths the built RTL lacks runs in an RTL variant the
# driver (tools/girtd, here on the given binary) builds for it first. For each CONFIG, INPUT renders on golden, approx and rtl:
# - one frame: golden's (the bit-exact model, which needs no build);
# - approx and rtl: the same counts (pixels, DDA clocks and states, cache
#   accesses and page misses, FIFO maximum) and the same modeled time (to
#   the base tick);
# - under a slow HAD (slow_had.json, merged after CONFIG) the DDA -> HAD FIFO
#   fills to exactly its configured depth on approx and rtl;
# - approx's and rtl's report.html heat maps are the same;
# - a second rtl run reuses the variant (no "building" line);
# - the simulator run without the driver refuses a variant it lacks.
# Prints one row per CONFIG.
# Usage: test_rtl_variants.sh GIRTD_BINARY REPO_ROOT INPUT CONFIG...
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"
input=$3
shift 3
slow="testbench/variants/slow_had.json"
fill_input="traces/sliver_fan.trace"
counts='[.triangles_drawn, .pixels_generated, .pixels_written, .pixels_blended, .pixels_z_rejected,
         .pixels_dropped, .dda_cycles, .dda_states, .cache, .stages.had.fifo_in_max]'

# The page-miss counts and the waste map's picture of a report.html, hashed.
heat_maps() {
  python3 -c '
import hashlib, re, sys
page = open(sys.argv[1]).read()
data = re.search(r"<script id=\"girtd-data\" type=\"application/json\">(.*?)</script>", page, re.S).group(1)
misses = re.search(r"\"page_misses\":\{[^}]*\"counts\":\[([0-9,]*)\]", data).group(1)
waste = re.search(r"id=\"waste_map\"[^>]*src=\"([^\"]*)\"", page).group(1)
print(hashlib.sha256((misses + waste).encode()).hexdigest())' "$1"
}
# The simulator alone builds nothing: without the driver's variant step, one
# line naming it, exit 4, nothing written.
# (The first configuration the built RTL lacks: some need no variant.)
for cfg in "$@"; do
  GIRTD_VARIANTS_DIR="$TMP/no_variants" "$GIRTD" --plan render "$input" --backend rtl --config "$cfg" | grep -q "^variant" \
    || continue
  GIRTD_VARIANTS_DIR="$TMP/no_variants" "$GIRTD" render "$input" --backend rtl --config "$cfg" --out "$TMP/refused" \
    2> "$TMP/refused.err"
  rc=$?
  [[ $rc -eq 4 && $(wc -l < "$TMP/refused.err") -eq 1 && ! -e "$TMP/refused" ]] \
    && grep -q "^girtd: this configuration needs the RTL elaborated for .*, not built for this build of girtd: tools/girtd builds it" "$TMP/refused.err" \
    && ok || bad "the simulator alone: rc $rc, $(cat "$TMP/refused.err")"
  break
done
printf '%-14s %-17s %-8s %-9s %-12s %-9s %-14s %-14s\n' config rtl_build built image page_misses fifo_max approx_time_s rtl_time_s
for cfg in "$@"; do
  name=$(basename "$cfg" .json)
  mkdir -p "$TMP/$name"
  for b in golden approx rtl; do
    "$RUN" render "$input" --backend $b --config "$cfg" --out "$TMP/$name/$b" --quiet 2> "$TMP/$name/$b.err" \
      && ok || bad "$name: $b render: $(cat "$TMP/$name/$b.err")"
  done
  build_line=$(grep -o "building an RTL variant.*in [^ ]*" "$TMP/$name/rtl.err" | head -1)
  r="$TMP/$name/rtl/report.json" a="$TMP/$name/approx/report.json" g="$TMP/$name/golden/report.json"
  [[ -s "$r" && -s "$a" && -s "$g" ]] || { bad "$name: a report is missing"; continue; }
  sha=$(jq -r .image_sha256 "$g")
  [[ "$(jq -r .image_sha256 "$r")" == "$sha" ]] && ok || bad "$name: rtl's frame differs from golden's"
  [[ "$(jq -r .image_sha256 "$a")" == "$sha" ]] && ok || bad "$name: approx's frame differs from golden's"
  [[ "$(jq -c "$counts" "$r")" == "$(jq -c "$counts" "$a")" ]] && ok \
    || bad "$name: counts differ: rtl $(jq -c "$counts" "$r") approx $(jq -c "$counts" "$a")"
  [[ "$(jq .modeled_time_s "$a")" == "$(jq .modeled_time_s "$r")" ]] \
    && ok || bad "$name: approx's modeled time $(jq .modeled_time_s "$a") s, rtl's $(jq .modeled_time_s "$r") s"
  # report.html's heat maps: approx's (the timing model's misses, the golden DDA's pixels) and rtl's
  # (the pixels the RTL pushes; with dda.output_latency_clocks >= 2 some are pushed after the next load).
  [[ "$(heat_maps "$TMP/$name/approx/report.html")" == "$(heat_maps "$TMP/$name/rtl/report.html")" ]] \
    && ok || bad "$name: approx's and rtl's heat maps differ"

  # Reused: the second run builds nothing.
  "$RUN" render "$input" --backend rtl --config "$cfg" --out "$TMP/$name/rtl2" --quiet 2> "$TMP/$name/rtl2.err" \
    && ! grep -q "^girtd: .*RTL variant" "$TMP/$name/rtl2.err" && ok || bad "$name: the variant was not reused: $(cat "$TMP/$name/rtl2.err")"

  # The FIFO fills to its depth (and reports it: a 64-deep FIFO needs a 7-bit count).
  depth=$(jq .config.fifo.dda_had_depth "$r")
  for b in approx rtl; do
    "$RUN" render "$fill_input" --backend $b --config "$cfg" --config "$slow" --out "$TMP/$name/fill_$b" --quiet \
      && ok || bad "$name: $b fill run"
    got=$(jq .stages.had.fifo_in_max "$TMP/$name/fill_$b/report.json" 2> /dev/null)
    [[ "$got" == "$depth" ]] && ok || bad "$name: $b: the FIFO's maximum under a slow HAD is $got, its depth $depth"
  done

  printf '%-14s %-17s %-8s %-9s %-12s %-9s %-14s %-14s\n' "$name" "$(jq -r .rtl_build "$r")" \
    "$([[ -n "$build_line" ]] && echo now || echo before)" "${sha:0:8}" "$(jq .cache.page_misses "$r")" \
    "$(jq .stages.had.fifo_in_max "$r")" "$(jq .modeled_time_s "$a")" "$(jq .modeled_time_s "$r")"
done
finish
