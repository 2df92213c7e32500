#!/usr/bin/env bash
# models/ is the golden C++ model: it includes only models/ itself, the C++
# library, nlohmann-json, GLM and the headers generated from config/ (girtd/), never the simulator (sim/), SystemC or
# Verilator (Vortex's boundary check). Usage: check_boundaries.sh REPO_ROOT
set -uo pipefail
cd "$1/models" || exit 2
fails=0
while IFS=: read -r file line include; do
  name=$(sed -E 's/^#include [<"]([^>"]+)[>"].*/\1/' <<< "$include")
  if [[ $include == *'"'* ]]; then
    [[ -f "$name" || $name == girtd/* ]] && continue  # a models/ header, or one generated from config/ (girtd/)
  else
    [[ $name =~ ^(systemc|tlm|verilated) ]] && { echo "models/$file:$line: includes $name (SystemC or Verilator)"; fails=$((fails + 1)); continue; }
    [[ $name =~ ^[a-z_]+$ || $name == nlohmann/* || $name == glm/* ]] && continue  # C++ library, json, GLM
  fi
  echo "models/$file:$line: includes $name, outside models/ and the allowed libraries"
  fails=$((fails + 1))
done < <(grep -rnE '^\s*#\s*include' --include='*.hpp' --include='*.cpp' --include='*.h' . | sed 's|^\./||')
echo "$fails include(s) cross the models/ boundary"
[[ $fails -eq 0 ]]
