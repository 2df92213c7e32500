#!/usr/bin/env bash
# Measures every recorded result under results/ again, the way it was first
# made, and records it (tools/girtd docs --record; results/recorded.json
# stamps each with this checkout's commit), then regenerates the documents.
#
#   studies/campaign.sh              every result
#   studies/campaign.sh --stale      only those `tools/girtd docs --check` lists as stale
#   studies/campaign.sh STEP...      these steps only (--list prints them)
#
# Each step runs in a fresh out/campaign/STEP (a sweep would otherwise resume
# an earlier run's rows). Commit the code first: a result recorded over
# uncommitted changes reads as stale. On 2 cores the whole campaign takes
# about two and a half hours, the 20 Mpixel/s study an hour of it.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
GIRTD=tools/girtd
OUT=out/campaign
PYTHON=/usr/bin/python3

# Each step and the results/ entries it records, in the order they run: the
# wall-time measurements first (keep the machine otherwise idle for them), the
# study's stages in their order, the pages after the runs they show.
STEPS=(
  "bench:bench.json"
  "speed:speed"
  "scale:scale"
  "accuracy_precision:accuracy/precision_color accuracy/precision_d accuracy/precision_t accuracy/precision_z"
  "accuracy_rtl:accuracy/rtl_color accuracy/rtl_d accuracy/rtl_z"
  "accuracy_shortcuts:accuracy/shortcut_nf_prom accuracy/shortcut_one_minus_nf accuracy/shortcut_q"
  "accuracy_timing:accuracy/timing"
  "pipeline_options:pipeline_options"
  "memory_side:sweeps/memory_side"
  "study:sweeps/study_thesis sweeps/study_coarse sweeps/study_refine sweeps/study_final sweeps/study_path sweeps/study_check"
  "example:examples/sweep_fifo_depth"
  "assimp_corpus:assimp_corpus.md"
  "formal:formal"
  "report_page:report_page"
)

log() { echo "[campaign $(date -u +%H:%M:%S)] $*" >&2; }
fresh() { rm -rf "$OUT/$1" && mkdir -p "$OUT/$1" && echo "$OUT/$1"; }

accuracy() {  # NAME ARGS...: a girtd accuracy run, recorded under results/accuracy/NAME
  local name=$1 dir
  shift
  dir=$(fresh "accuracy/$name")
  "$GIRTD" accuracy "$@" --out "$dir"
  "$GIRTD" docs --record "$dir" >/dev/null
}

sweep() {  # NAME: traces/sweeps/NAME.json, recorded under results/sweeps/NAME
  local dir
  dir=$(fresh "sweep/$1")
  "$GIRTD" sweep "traces/sweeps/$1.json" --out "$dir"
  "$GIRTD" docs --record "$dir" >/dev/null
}

run_step() {
  local dir
  case "$1" in
    accuracy_precision)
      accuracy precision_color --backends golden --vary ep.color.frac_bits=5,6,7,8,9,10,12
      accuracy precision_d --backends golden --vary ep.d.frac_bits=6,8,10,12,13,14,16
      accuracy precision_t --backends golden --vary ep.t.frac_bits=5,6,7,8,9,10,12
      accuracy precision_z --backends golden --vary ep.z.frac_bits=4,6,8,9,10,12 ;;
    accuracy_rtl)
      accuracy rtl_color traces/demo.trace traces/opaque_200px.trace --backends golden,rtl --vary ep.color.frac_bits=7
      accuracy rtl_d traces/demo.trace traces/opaque_200px.trace --backends golden,rtl --vary ep.d.frac_bits=14
      accuracy rtl_z traces/demo.trace traces/opaque_200px.trace --backends golden,rtl --vary ep.z.frac_bits=10 ;;
    accuracy_shortcuts)
      accuracy shortcut_nf_prom --backends approx --vary nf.prom_frac_bits=2,3,4,6,8
      accuracy shortcut_one_minus_nf --backends approx --vary had.one_minus_nf=exact,invert_bits
      accuracy shortcut_q --backends approx --vary dda.q_override=0,0.5,1,2,4,8 ;;
    accuracy_timing) accuracy timing ;;
    bench)
      dir=$(fresh bench)
      "$GIRTD" bench --out "$dir"
      "$GIRTD" bench --leave-out --out "$dir"
      "$GIRTD" docs --record "$dir" >/dev/null ;;
    speed)
      dir=$(fresh speed)
      "$GIRTD" bench --speed --out "$dir"
      "$GIRTD" docs --record "$dir" >/dev/null ;;
    scale)
      dir=$(fresh scale)
      "$GIRTD" bench --scale --runs 9 --out "$dir"
      "$GIRTD" docs --record "$dir" >/dev/null ;;
    pipeline_options)
      dir=$(fresh pipeline_options)
      "$GIRTD" bench --pipeline --options --out "$dir"
      rm -rf results/pipeline_options && mkdir -p results/pipeline_options
      cp "$dir/pipeline.json" "$dir/pipeline.md" results/pipeline_options/
      "$PYTHON" studies/recorded.py stamp results/pipeline_options "girtd bench --pipeline --options --out $dir" ;;
    memory_side) sweep memory_side ;;
    study)
      for stage in study_thesis study_coarse study_refine study_final study_path study_check; do sweep "$stage"; done ;;
    example)
      rm -rf results/examples/sweep_fifo_depth
      "$GIRTD" python examples/sweep_fifo_depth.py --out results/examples/sweep_fifo_depth
      "$PYTHON" studies/recorded.py stamp results/examples/sweep_fifo_depth \
        "girtd python examples/sweep_fifo_depth.py --out results/examples/sweep_fifo_depth" ;;
    assimp_corpus)
      ctest --test-dir build -R "assimp's test models" --output-on-failure
      "$GIRTD" docs --record build/testbench/assimp_corpus.md >/dev/null ;;
    formal)
      dir=$(fresh formal)
      "$GIRTD" formal --out "$dir"
      "$GIRTD" docs --record "$dir" >/dev/null ;;
    report_page)
      # The pages of the demo (rtl), the memory-side sweep and the timing accuracy run.
      "$GIRTD" demo >/dev/null  # out/demo, the page the docs show
      [[ -f "$OUT/sweep/memory_side/sweep.html" ]] || sweep memory_side
      [[ -f "$OUT/accuracy/timing/accuracy.html" ]] || accuracy timing
      mkdir -p results/report_page
      tools/page_shot.sh png out/demo/report.html results/report_page/demo.png 1400,2600
      tools/page_shot.sh png "$OUT/sweep/memory_side/sweep.html" results/report_page/sweep_memory_side.png 1400,1500
      tools/page_shot.sh png "$OUT/accuracy/timing/accuracy.html" results/report_page/accuracy_timing.png 1400,1400
      "$PYTHON" studies/recorded.py stamp results/report_page \
        "tools/page_shot.sh png PAGE.html results/report_page/NAME.png (studies/campaign.sh report_page)" ;;
    *) echo "studies/campaign.sh: no step '$1' (--list)" >&2; exit 2 ;;
  esac
}

chosen=()
case "${1:-}" in
  --list) for s in "${STEPS[@]}"; do echo "${s%%:*}: ${s#*:}"; done; exit 0 ;;
  --stale)
    stale=$("$PYTHON" studies/recorded.py check 2>/dev/null | sed -n 's/^results\/\([^:]*\):.*/\1/p' || true)
    for s in "${STEPS[@]}"; do
      for r in ${s#*:}; do
        if grep -qxF "$r" <<<"$stale"; then chosen+=("${s%%:*}"); break; fi
      done
    done ;;
  "") for s in "${STEPS[@]}"; do chosen+=("${s%%:*}"); done ;;
  *) chosen=("$@") ;;
esac

if [[ -n "$(git status --porcelain -- sim models hw config traces studies cmake CMakeLists.txt)" ]]; then
  log "warning: uncommitted changes in what the results measure: they will read as stale"
fi
start=$(date +%s)
for i in "${!chosen[@]}"; do
  step=${chosen[$i]}
  log "step $((i + 1))/${#chosen[@]}: $step ($(( ($(date +%s) - start) / 60 )) min so far)"
  t0=$(date +%s)
  run_step "$step"
  log "$step took $(( $(date +%s) - t0 )) s"
done
"$GIRTD" docs >/dev/null
log "done in $(( ($(date +%s) - start) / 60 )) min: ${#chosen[@]} step(s); tools/girtd docs --check says what is still stale"
