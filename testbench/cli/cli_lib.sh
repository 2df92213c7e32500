# Shared set-up of the CLI test scripts: sourced with GIRTD_BINARY REPO_ROOT
# as $1 $2. Gives GIRTD and ROOT (absolute), RUN (the driver tools/girtd on
# that binary: it makes the RTL variants and synthesis sizes a command needs
# first and draws the plots after, as a user's run does), PYTHON, a scratch $TMP
# removed on exit, ok / bad counters and `finish` printing "N passed, N failed".
set -uo pipefail
GIRTD=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
ROOT=$(cd "$2" && pwd)
export GIRTD_BINARY="$GIRTD"
RUN="$ROOT/tools/girtd"
PYTHON=/usr/bin/python3  # Debian's, where matplotlib and numpy are (not a pyenv shim)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$ROOT"
fails=0
passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }
finish() {
  echo "$passes passed, $fails failed"
  [[ $fails -eq 0 ]]
}

# check_registry REPORT: report.json holds exactly the keys the registry
# (girtd_report_keys, beside girtd) declares, and what it lists in
# not_modeled is null.
check_registry() {
  local report=$1 keys k
  keys=$("$(dirname "$GIRTD")/girtd_report_keys" | sed -n 's/^| `\([^`]*\)` .*/\1/p')
  [[ -n "$keys" ]] || { bad "girtd_report_keys printed no key"; return; }
  for k in $keys; do  # declared -> present (inside a non-null group, in every stage)
    jq -e --arg k "$k" '($k | split(".")) as $p
      | if $p[0] == "stages" then [.stages[] | has($p[2])] | all
        elif ($p | length) == 1 then has($p[0])
        else (getpath($p[:-1]) == null) or (getpath($p[:-1]) | has($p[-1])) end' "$report" >/dev/null \
      || bad "$report: declared key $k missing"
  done
  local present  # present -> declared (not inside config, dda_states or numerics, keyed by name; a stage's name is *)
  present=$(jq -r '[paths(true) | select(.[0] != "config" and .[0] != "dda_states" and .[0] != "numerics")
                    | select(all(.[]; type == "string")) | if .[0] == "stages" then (if length == 3 then ["stages", "*", .[2]] else empty end) else . end
                    | join(".")] | unique[]' "$report")
  for k in $present; do
    # a declared key, or a group of declared keys (cache, stages)
    grep -qx -- "$k" <<< "$keys" || grep -q -- "^$k\." <<< "$keys" || bad "$report: key $k not in the registry"
  done
  jq -e '. as $r | [.not_modeled[] | split(".") as $p
         | if $p[0] == "stages" then $r.stages[][$p[2]] else $r | getpath($p) end] | all(. == null)' "$report" >/dev/null \
    || bad "$report: a not_modeled key has a value"
}
