#!/usr/bin/env bash
# girtd sweep --slurm through a single-node Slurm cluster on 127.0.0.1
# (tools/slurm_local.sh, started and stopped here): the same rows as the
# local run (but for wall time), spot checks included; without a cluster,
# one clear line and exit 2.
# Usage: test_sweep_slurm.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "$0")/cli_lib.sh" "$1" "$2"
S=traces/sweeps/small.json
SLURM_CONF=$TMP/none/slurm.conf "$RUN" sweep $S --slurm --out "$TMP/x" > /dev/null 2> "$TMP/err"
[[ $? -eq 2 ]] && grep -q "^--slurm: Slurm is not there" "$TMP/err" && ok || bad "no cluster: $(cat "$TMP/err")"

trap 'tools/slurm_local.sh down "$TMP/slurm" >/dev/null 2>&1; rm -rf "$TMP"' EXIT
eval "$(tools/slurm_local.sh up "$TMP/slurm")" && ok || { bad "the cluster did not start"; finish; exit 1; }
"$RUN" sweep $S --slurm --jobs 2 --out "$TMP/s" > "$TMP/s.txt" 2>&1 && ok || bad "slurm sweep: $(tail -5 "$TMP/s.txt")"
grep -q "submitting 2 array task" "$TMP/s.txt" && ok || bad "not submitted: $(head -5 "$TMP/s.txt")"
ls "$TMP/s/slurm/"*.log >/dev/null 2>&1 && ok || bad "no array task logs"
grep -q "the array did not write" "$TMP/s.txt" && bad "rows left to the local run" || ok
"$RUN" sweep $S --jobs 2 --out "$TMP/l" > "$TMP/l.txt" 2>&1 && ok || bad "local sweep"
norm='[.rows[] | del(.wall_s)] | sort_by(.point, .input)'
[[ "$(jq -c "$norm" "$TMP/s/results.json")" == "$(jq -c "$norm" "$TMP/l/results.json")" ]] \
  && ok || bad "Slurm and local rows differ"
finish
