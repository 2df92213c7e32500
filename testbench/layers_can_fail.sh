#!/usr/bin/env bash
# The layer check can fail. On a copy of the tree's sources it must first
# pass; then, with one of each kind of upward use planted, it must name
# every planted line and exit 1:
#   models/common (the bottom layer) including the DDA (a layer above it),
#   and sim/io including the CLI (the top of sim/);
#   models/ including SystemC (<systemc>) and Verilator ("verilated.h");
#   hw/dda instantiating the HAD (a layer above it);
#   a new folder of source placed in no layer.
# Usage: layers_can_fail.sh REPO_ROOT
set -euo pipefail
repo="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$repo" && tar cf - --exclude='*.png' models sim hw python examples studies testbench tools traces docs) |
  (cd "$tmp" && tar xf -)
python3 "$repo/tools/check_layers.py" "$tmp" >/dev/null || { echo "FAIL: the unmodified copy does not pass"; exit 1; }

echo '#include "dda/dda_engine.hpp"' >> "$tmp/models/common/types.hpp"
echo '#include "cli/commands.hpp"' >> "$tmp/sim/io/trace.hpp"
echo '#include <systemc>' >> "$tmp/models/dda/dda_engine.cpp"
echo '#include "verilated.h"' >> "$tmp/models/had/had.hpp"
printf 'module planted;\n  had u_had (.clk_i());\nendmodule\n' > "$tmp/hw/dda/planted.sv"
mkdir "$tmp/sim/newstage" && echo 'int x;' > "$tmp/sim/newstage/x.cpp"
set +e
out=$(python3 "$repo/tools/check_layers.py" "$tmp")
rc=$?
set -e
echo "$out"
fails=0
expect() {
  grep -qE "$1" <<< "$out" || { echo "FAIL: not named: $2"; fails=$((fails + 1)); }
}
expect "^models/common/types.hpp:$(wc -l < "$tmp/models/common/types.hpp"): includes \"dda/dda_engine.hpp\", in models/dda, a layer above models/common$" \
  "the upward include in models/"
expect "^sim/io/trace.hpp:$(wc -l < "$tmp/sim/io/trace.hpp"): includes \"cli/commands.hpp\", in sim/cli, a layer above sim/io$" \
  "the upward include in sim/"
expect '^models/dda/dda_engine.cpp:[0-9]+: includes <systemc>' "the SystemC include"
expect '^models/had/had.hpp:[0-9]+: includes "verilated.h"' "the Verilator include"
expect '^hw/dda/planted.sv:2: instantiates had, in hw/had, a layer above hw/dda$' "the upward instantiation"
expect '^sim/newstage: holds source but is in no layer' "the unplaced folder"
[[ $rc -eq 1 ]] || { echo "FAIL: the check exited $rc, not 1"; fails=$((fails + 1)); }
[[ $fails -eq 0 ]] && echo "the check rejected every planted use"
[[ $fails -eq 0 ]]
