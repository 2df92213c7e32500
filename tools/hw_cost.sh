#!/usr/bin/env bash
# Hardware cost of the RTL DDA: yosys generic cell counts and logic depth
# (ltp) per unit and for the whole DDA, and iCE40 HX8K LUTs and Fmax from
# nextpnr. Prints a markdown table (hw/dda/README.md quotes it).
# Usage: tools/hw_cost.sh [BUILD_DIR]    (needs yosys, nextpnr-ice40)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
G="$BUILD/generated/hw"
H="$ROOT/hw/dda"
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
SRC="$G/girtd_pkg.sv $H/dda_ep.sv $H/dda_counter.sv $H/dda_saturate.sv $H/dda_norm.sv $H/dda_nf.sv $H/dda_limits.sv $H/dda.sv"
SRC="$SRC $ROOT/hw/cost/cost_shell_ep.sv $ROOT/hw/cost/cost_shell_dda.sv"
pkg() { sed -n "s/.*localparam int $1 = \(.*\);/\1/p" "$G/girtd_pkg.sv" | head -1; }
width() { echo $(( $(echo "$1" | tr -d ' ') )); }
CW=$(width "$(pkg COLOR_W)"); ZW=$(width "$(pkg Z_W)"); DW=$(width "$(pkg D_W)")

generic() {  # top [chparam] -> "cells depth"
  local top=$1 chp=${2:-}
  yosys -p "read_verilog -sv -I$G $SRC; ${chp:+chparam $chp $top;} synth -top $top -flatten; ltp -noff; stat" \
    > "$W/g.log" 2>&1
  local cells depth
  cells=$(grep -E "^\s+Number of cells:" "$W/g.log" | tail -1 | awk '{print $4}')
  depth=$(grep -oE "Longest topological path in .* \(length=[0-9]+\)" "$W/g.log" | tail -1 | grep -oE "[0-9]+\)$" | tr -d ')')
  echo "$cells $depth"
}

ice40() {  # shell_top [chparam] -> "luts fmax"
  local top=$1 chp=${2:-}
  yosys -p "read_verilog -sv -I$G $SRC; ${chp:+chparam $chp $top;} synth_ice40 -top $top -json $W/i.json" \
    > "$W/i.log" 2>&1
  nextpnr-ice40 --hx8k --package ct256 --json "$W/i.json" --freq 28.6 --timing-allow-fail --seed 1 \
    > "$W/p.log" 2>&1 || { echo "- failed"; return; }
  local luts fmax
  luts=$(grep -oE "ICESTORM_LC:\s+[0-9]+/" "$W/p.log" | tail -1 | grep -oE "[0-9]+")
  fmax=$(grep -oE "Max frequency for clock .*: [0-9.]+ MHz" "$W/p.log" | tail -1 | grep -oE "[0-9.]+ MHz" | cut -d' ' -f1)
  echo "$luts $fmax"
}

echo "| unit | yosys cells | logic depth (ltp) | iCE40 LCs | iCE40 Fmax (MHz) | closes at 35 ns (28.6 MHz)? |"
echo "|---|---|---|---|---|---|"
row() {  # name generic_top generic_chparam shell_top shell_chparam
  read -r cells depth < <(generic "$2" "$3")
  if [[ -n "$4" ]]; then read -r luts fmax < <(ice40 "$4" "$5"); else luts="-"; fmax="-"; fi
  local ok="-"
  [[ "$fmax" != "-" && -n "$fmax" ]] && ok=$(awk -v f="$fmax" 'BEGIN{print (f >= 28.6) ? "yes" : "no"}')
  echo "| $1 | $cells | $depth | $luts | $fmax | $ok |"
}
row "colour/T EP ($CW bits)" dda_ep "-set W $CW" cost_shell_ep "-set W $CW"
row "Z EP ($ZW bits)" dda_ep "-set W $ZW" cost_shell_ep "-set W $ZW"
row "D EP ($DW bits)" dda_ep "-set W $DW" cost_shell_ep "-set W $DW"
row "X/Y counter (16 bits)" dda_counter "" "" ""
row "Norm_Q (one edge)" dda_norm "" "" ""
row "nf (U decoder + PROMs)" dda_nf "" "" ""
row "whole DDA (10 EPs + sequencer + nf)" dda "-set WRAP_DETECT 0" cost_shell_dda ""
row "whole DDA with the wrap detector (simulation aid)" dda "" "" ""
