#!/usr/bin/env bash
# The demo's glass sphere drawn as the thesis wrote the design and with
# config/presets/robust.json (fill rule and edge flags): the crops shown in
# models/dda/README.md, and the seam counts (report.json pixels_reblended).
# Usage: tools/seam_pictures.sh [BUILD_DIR]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
cd "$ROOT"
for name in thesis robust; do
  cfg=(); [[ $name == robust ]] && cfg=(--config config/presets/robust.json)
  "$BUILD/bin/girtd" render traces/scenes/demo.json --backend golden "${cfg[@]}" --out "$OUT/$name" --quiet 2>/dev/null
  echo "$name: $(jq .pixels_reblended "$OUT/$name/report.json") seam pixels"
  "$ROOT/tools/png_crop.py" "$OUT/$name/frame.png" "models/dda/img/glass_$name.png" 680 430 320 340 1
done
