# The driver's variant step, sourced by tools/girtd: makes what a girtd
# command needs before it runs, as `girtd --plan COMMAND ARGS...` lists it
# (one tab-separated line each; studies/girtd_main.cpp). The simulator itself
# runs no build, synthesis, Python or Slurm: those happen here.
#   variant KEY DIR WHY MAIN SANITIZED BUILD_ID
#                                 an RTL variant: configure DIR against the main build MAIN (DIR/config.json
#                                 is its configuration), build its girtd, stamp it (DIR/built_for.txt: MAIN,
#                                 SANITIZED, and BUILD_ID, the main executable's identity) so the simulator
#                                 runs in it, and only while the main build is the one it was built against
#   dda-cells DIR                 size the DDA by synthesis (DIR/synth.ys -> DIR/stat.txt)
#   opaque-trace COUNT PATH       the speed bench's workload (tools/make_opaque_trace.py)
#   mesh TRIANGLES PATH           a scale bench's UV sphere of about TRIANGLES triangles, once (tools/make_mesh.py)
#   slurm-array SLICES SPEC OUT   run the sweep's rows as a job array first (studies/sweep_on_slurm.sh)
#   plots DIR                     draw the command's plots after it ran (studies/COMMAND_plots.py)

# Debian's python3, where matplotlib and numpy are (not a pyenv shim).
PYTHON=/usr/bin/python3

# The last lines of a log, indented.
log_tail() { tail -n 12 "$1" | sed 's/^/  /' >&2; }

# build_variant KEY DIR WHY MAIN SANITIZED BUILD_ID
build_variant() {
  local key=$1 dir=$2 why=$3 main=$4 sanitized=$5 build_id=$6 lock
  local configured="$main $sanitized" built="$main $sanitized $build_id"
  local defines=(-DCMAKE_BUILD_TYPE=Release "-DGIRTD_RTL_VARIANT_OF=$main" "-DGIRTD_RTL_CONFIG=$dir/config.json")
  [[ "$sanitized" == 1 ]] && defines+=(-DGIRTD_SANITIZE=ON)
  mkdir -p "$dir"
  # Two drivers (two sweeps) may want the same variant at once: one builds it.
  exec {lock}>"$dir.lock"
  if ! flock -n "$lock"; then
    echo "girtd: waiting for another girtd that is building the RTL variant $key" >&2
    flock "$lock"
  fi
  if [[ "$(cat "$dir/configured_for.txt" 2>/dev/null)" != "$configured" || ! -f "$dir/build.ninja" ]]; then
    echo "girtd: building an RTL variant for $why in $dir (once: later runs with these values reuse it;" \
         "a few minutes, log in build.log)" >&2
    rm -f "$dir/build.ninja" "$dir/CMakeCache.txt" "$dir/built_for.txt"
    if ! cmake -S "$ROOT" -B "$dir" -G Ninja "${defines[@]}" >"$dir/build.log" 2>&1 </dev/null; then
      echo "girtd: configuring the RTL variant $key failed ($dir/build.log):" >&2
      log_tail "$dir/build.log"
      exit 3
    fi
    echo "$configured" >"$dir/configured_for.txt"
  elif [[ "$(cat "$dir/built_for.txt" 2>/dev/null)" == "$built" ]] &&
       ninja -C "$dir" -n girtd 2>/dev/null </dev/null | grep -q "no work to do"; then
    exec {lock}>&-
    return 0
  else
    echo "girtd: updating the RTL variant $key ($why): its sources or the main build changed" >&2
  fi
  rm -f "$dir/built_for.txt"
  if ! cmake --build "$dir" --target girtd >>"$dir/build.log" 2>&1 </dev/null; then
    rm -f "$dir/configured_for.txt"  # configure afresh next time
    echo "girtd: building the RTL variant $key failed ($dir/build.log):" >&2
    log_tail "$dir/build.log"
    exit 3
  fi
  echo "$built" >"$dir/built_for.txt"
  exec {lock}>&-
}

# synthesise_dda DIR: the sweep reads the count from DIR/stat.txt.
NO_SYNTHESIS_WARNED=""
synthesise_dda() {
  if ! command -v yosys >/dev/null; then
    [[ -n "$NO_SYNTHESIS_WARNED" ]] || echo "warning: yosys is not installed: cost_yosys_dda_cells stays null" \
      "(tools/girtd hw-cost installs it)" >&2
    NO_SYNTHESIS_WARNED=1
    return 0
  fi
  echo "girtd: sizing the DDA by synthesis for one width set ($1)" >&2
  yosys -q -s "$1/synth.ys" >"$1/synth.log" 2>&1 </dev/null || echo "warning: synthesis failed: $1/synth.log" >&2
}

# has_arg NAME ARGS...: true when ARGS hold NAME (or NAME=...).
has_arg() {
  local name=$1 a
  shift
  for a in "$@"; do [[ "$a" == "$name" || "$a" == "$name"=* ]] && return 0; done
  return 1
}

# plans_dir BIN: where empty plans are remembered, beside BIN's build (none
# for an executable outside a build tree).
plans_dir() {
  local build
  build=$(dirname "$(dirname "$1")")
  [[ -f "$build/CMakeCache.txt" ]] && echo "$build/plans"
  return 0
}

# plan_key BIN ARGS...: what a plan depends on: the executable, the folder,
# the arguments and the configuration files' contents. Nothing when a
# configuration is not a regular file (a pipe is read once: by the plan).
plan_key() {
  local bin=$1 next="" a configs=()
  shift
  for a in "$@"; do
    if [[ "$next" == 1 ]]; then configs+=("$a"); fi
    next=""
    if [[ "$a" == --config ]]; then next=1; fi
    if [[ "$a" == --config=* ]]; then configs+=("${a#--config=}"); fi
  done
  for a in "${configs[@]}"; do [[ -f "$a" ]] || return 0; done
  { stat -L -c '%n %Y %s' "$bin"; printf '%s\n' "$PWD" "$@"; cat "${configs[@]}" </dev/null; } | sha256sum | cut -c1-32
}

# prepare BIN COMMAND ARGS...: makes everything the plan lists but the array
# and the plots, which it leaves in SLURM_ARRAY and PLOTS_DIR for run_prepared.
SLURM_ARRAY=()
PLOTS_DIR=""
prepare() {
  local bin=$1 cmd=$2
  shift
  # Help needs nothing; without a configuration file only these commands can
  # need anything: a plain render asks nothing (tools/girtd render stays fast).
  if has_arg -h "$@" || has_arg --help "$@"; then return 0; fi
  [[ "$cmd" == accuracy || "$cmd" == sweep || "$cmd" == bench ]] || has_arg --config "$@" || return 0
  # A plan that asked for nothing is remembered (a girtd start costs 0.1 s):
  # the same arguments, files and executable ask for nothing again.
  local plans key empty=""
  plans=$(plans_dir "$bin")
  key=$(plan_key "$bin" "$@")
  [[ -n "$plans" && -n "$key" ]] && empty="$plans/$key"
  [[ -n "$empty" && -f "$empty" ]] && return 0
  local plan kind a b c d e f
  plan=$("$bin" --plan "$@") || exit $?  # bad input: the simulator's one line, its exit code
  if [[ -z "$plan" ]]; then
    [[ -z "$empty" ]] || { mkdir -p "$plans" && : >"$empty"; }
    return 0
  fi
  while IFS=$'\t' read -r -u 3 kind a b c d e f; do
    case "$kind" in
      variant)
        [[ -n "$f" ]] || { echo "girtd: internal error: a variant line without its fields: $a" >&2; exit 3; }
        build_variant "$a" "$b" "$c" "$d" "$e" "$f" ;;
      dda-cells) synthesise_dda "$a" ;;
      opaque-trace)
        mkdir -p "$(dirname "$b")" && "$PYTHON" "$ROOT/tools/make_opaque_trace.py" "$a" --out "$b" </dev/null ;;
      mesh)
        [[ -f "$b" ]] || { mkdir -p "$(dirname "$b")" && "$PYTHON" "$ROOT/tools/make_mesh.py" sphere --triangles "$a" \
          -o "$b.part" </dev/null >/dev/null && mv "$b.part" "$b"; } ;;
      slurm-array) SLURM_ARRAY=("$a" "$b" "$c") ;;
      plots) PLOTS_DIR=$a ;;
      "") ;;
      *) echo "girtd: internal error: the plan has a line the driver does not know: $kind" >&2; exit 3 ;;
    esac
  done 3<<<"$plan"
}

# without_flag FLAG ARGS...: ARGS without FLAG, into ARGS_LEFT.
without_flag() {
  local flag=$1 a
  shift
  ARGS_LEFT=()
  for a in "$@"; do [[ "$a" == "$flag" ]] || ARGS_LEFT+=("$a"); done
}

# run_prepared BIN COMMAND ARGS...: prepare, run, plot. Replaces this shell
# by girtd when nothing follows it.
run_prepared() {
  local bin=$1 cmd=$2
  if [[ "$cmd" == sweep ]] && has_arg --slurm "${@:3}"; then
    "$ROOT/studies/sweep_on_slurm.sh" check || exit 2
  fi
  prepare "$@"
  shift
  if ((${#SLURM_ARRAY[@]})); then
    "$ROOT/studies/sweep_on_slurm.sh" run "$bin" "${SLURM_ARRAY[@]}"
  fi
  without_flag --slurm "$@"
  [[ -n "$PLOTS_DIR" ]] || exec "$bin" "${ARGS_LEFT[@]}"
  # girtd runs as a child (the plots follow): a stop reaches it, and a run
  # that was stopped (exit 130) draws nothing.
  local pid rc=0
  "$bin" "${ARGS_LEFT[@]}" &
  pid=$!
  trap 'kill -TERM "$pid" 2>/dev/null' INT TERM
  while :; do
    rc=0
    wait "$pid" || rc=$?
    kill -0 "$pid" 2>/dev/null || break  # wait was cut short by a signal: wait again
  done
  trap - INT TERM
  ((rc == 0 || rc == 1)) || exit "$rc"
  [[ -f "$PLOTS_DIR/$cmd.json" || -f "$PLOTS_DIR/results.json" ]] || exit "$rc"
  if "$PYTHON" "$ROOT/studies/${cmd}_plots.py" "$PLOTS_DIR"; then
    echo "wrote the plots in $PLOTS_DIR"
  else
    echo "girtd $cmd: the plots failed (python3-matplotlib; tools/girtd installs it)" >&2
    rc=1
  fi
  exit "$rc"
}
