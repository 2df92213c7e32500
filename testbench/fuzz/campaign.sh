#!/usr/bin/env bash
# A fuzz campaign: each target for 10^6 executions or 10 minutes, whichever
# comes first (override: RUNS=..., SECONDS_PER_TARGET=...), one at a time.
#   testbench/fuzz/campaign.sh [BUILD_DIR] [TARGET...]
# Needs the fuzz sub-build (build/fuzz: tools/girtd fuzz builds it). Prints a
# row per target (executions, coverage, features, corpus, outcome) and
# leaves the grown corpus in BUILD/fuzz/work/TARGET and any crash, leak or
# timeout input in BUILD/fuzz/artifacts/TARGET/; a fixed one goes into
# testbench/fuzz/regressions/TARGET/ so CTest replays it from then on.
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="${1:-$ROOT/build}"
shift || true
TARGETS=("$@")
((${#TARGETS[@]})) || TARGETS=(trace scene config sweep_spec obj off ply stl gltf dae)
RUNS="${RUNS:-1000000}"
# assimp's own leaks on refused input are suppressed here, not in the replays
# (assimp_leaks.supp says why); "suppressed" in the output counts them.
export LSAN_OPTIONS="suppressions=$ROOT/testbench/fuzz/assimp_leaks.supp"
SECONDS_PER_TARGET="${SECONDS_PER_TARGET:-600}"

# Model imports run at ~70 executions/s on 10-30 KB inputs (assimp builds
# every importer per import): shorter inputs buy more executions.
max_len() { case "$1" in trace | scene | config | sweep_spec | gltf | dae) echo 65536 ;; *) echo 8192 ;; esac; }

seeds() {
  case "$1" in
    trace) echo "$ROOT/traces" ;;
    scene) echo "$ROOT/traces/scenes" ;;
    config) echo "$ROOT/config" ;;
    sweep_spec) echo "$ROOT/traces/sweeps" ;;
    gltf) echo "$ROOT/traces/models/file_scenes"; [[ -d /usr/share/assimp/models/glTF2 ]] && echo /usr/share/assimp/models/glTF2 ;;
    dae) [[ -d /usr/share/assimp/models/Collada ]] && echo /usr/share/assimp/models/Collada || echo "$ROOT/traces/models/file_scenes" ;;
    *) echo "$ROOT/traces/models" ;;
  esac
}

printf '| target | executions | seconds | coverage (edges) | features | corpus | outcome |\n|---|---|---|---|---|---|---|\n'
for t in "${TARGETS[@]}"; do
  bin="$BUILD/fuzz/bin/fuzz_$t"
  [[ -x "$bin" ]] || { echo "no $bin: build it first (cmake --build build --target girtd_fuzz)" >&2; exit 2; }
  work="$BUILD/fuzz/work/$t" art="$BUILD/fuzz/artifacts/$t"
  mkdir -p "$work" "$art"
  dirs=("$work" $(seeds "$t"))
  for kind in corpus regressions; do [[ -d "$ROOT/testbench/fuzz/$kind/$t" ]] && dirs+=("$ROOT/testbench/fuzz/$kind/$t"); done
  log="$BUILD/fuzz/work/$t.log"
  start=$(date +%s)
  "$bin" -runs="$RUNS" -max_total_time="$SECONDS_PER_TARGET" -max_len="$(max_len "$t")" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$art/" "${dirs[@]}" >"$log" 2>&1
  rc=$?
  secs=$(( $(date +%s) - start ))
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
  last=$(grep -E '^#[0-9]+' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' <<<"$last" | grep -o '[0-9]*')
  ft=$(grep -o 'ft: [0-9]*' <<<"$last" | grep -o '[0-9]*')
  corp=$(grep -o 'corp: [0-9]*/[0-9a-zA-Z]*' <<<"$last" | cut -d' ' -f2)
  outcome="clean"
  ((rc != 0)) && outcome="FOUND: $(grep -m1 -oE 'ERROR: [A-Za-z]+: [a-z-]+|deadly signal|timeout|out-of-memory|runtime error' "$log" || echo "exit $rc") (see $log)"
  printf '| %s | %s | %s | %s | %s | %s | %s |\n' "$t" "${execs:-?}" "$secs" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$outcome"
done
