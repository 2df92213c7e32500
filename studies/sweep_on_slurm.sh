#!/usr/bin/env bash
# A sweep's rows as a Slurm job array (tools/girtd sweep SPEC --slurm): one
# array task per slice, each `girtd sweep SPEC --out OUT --jobs 1 --slice
# I/SLICES` (a task is one core); sbatch --wait returns when all ended. The
# driver then runs the sweep itself, which finds the rows written, runs any
# the array left, spot-checks and writes the tables.
#   sweep_on_slurm.sh check                            exit 1 with one line when no cluster answers
#   sweep_on_slurm.sh run GIRTD SLICES SPEC OUT        submit and wait
set -uo pipefail

case "${1:-}" in
  check)
    if ! command -v sbatch >/dev/null || ! sinfo --noheader >/dev/null 2>&1; then
      echo "--slurm: Slurm is not there (no sbatch, or no controller answers): tools/girtd slurm-up starts a" \
           "single-node cluster on this machine (export the SLURM_CONF it prints)" >&2
      exit 1
    fi
    ;;
  run)
    girtd=$2 slices=$3 spec=$4 out=$5
    logs="$out/slurm"
    mkdir -p "$logs"
    logs=$(cd "$logs" && pwd)
    echo "submitting $slices array task(s) to Slurm (logs in $logs)"
    # The spec and folder as given, run from this folder (--chdir): the rows
    # name their inputs as a local run does.
    sbatch --wait --quiet --array=0-$((slices - 1)) --job-name=girtd-sweep --output="$logs/%a.log" \
      --chdir="$PWD" \
      --wrap="exec '$girtd' sweep '$spec' --out '$out' --jobs 1 --slice \$SLURM_ARRAY_TASK_ID/$slices" ||
      echo "warning: sbatch exited $? (logs in $logs)" >&2
    ;;
  *)
    sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
    ;;
esac
