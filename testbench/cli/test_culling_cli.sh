#!/usr/bin/env bash
# Culling in front of lighting (config `culling`, config/presets/culling.json):
# on traces/scenes/out_of_view.json, bounding-sphere culling removes the eight
# models out of view before lighting, leaves the frame as it was and at
# least 1.5x the modeled rate; without a culling stage (the thesis' design)
# the lighting board tests the back faces an input asks to cull, at the same
# flops; a forced back-face cull keeps transparent surfaces' back faces and
# warns; polygon dumps keep their objects.
# Usage: test_culling_cli.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "$0")/cli_lib.sh" "$1" "$2"

scene=traces/scenes/out_of_view.json
for backend in golden approx; do
  "$GIRTD" render "$scene" --backend "$backend" --z-png --out "$TMP/$backend" --quiet || bad "$backend: render failed"
  "$GIRTD" render "$scene" --backend "$backend" --config testbench/configs/object_culling.json --z-png \
    --out "$TMP/$backend-obj" --quiet || bad "$backend: render with object culling failed"
  a=$TMP/$backend/report.json b=$TMP/$backend-obj/report.json
  [[ $(jq -r .image_sha256 "$a") == $(jq -r .image_sha256 "$b") ]] && ok || bad "$backend: object culling changed the frame"
  # 8 of 10 models out of view, 2,304 of 2,880 polygons (8 x 288).
  jq -e '.frontend.objects == 10 and .frontend.objects_culled == 8 and .frontend.object_culled_polygons == 2304
         and .frontend.polygons == 2880 and .frontend.culling_flops_saved > 0' "$b" >/dev/null \
    && ok || bad "$backend: object culling counts: $(jq -c .frontend "$b")"
  # ... and every Zp: the Z buffers are the same too.
  cmp -s "$TMP/$backend/z.png" "$TMP/$backend-obj/z.png" && ok || bad "$backend: object culling changed the Z buffer"
  jq -e '.frontend.objects_culled == 0 and .frontend.culling_flops_saved == 0' "$a" >/dev/null \
    && ok || bad "$backend: culling off in the thesis' design"
done
# The modeled rate: lighting no longer pays for what is out of view. The
# culling stage spends 37 flop per object (sim/frontend/stage_costs.cpp).
jq -n --slurpfile a "$TMP/approx/report.json" --slurpfile b "$TMP/approx-obj/report.json" \
  '$b[0].modeled_mpixels_per_s >= 1.5 * $a[0].modeled_mpixels_per_s
   and $b[0].stages.culling.flops == 370 and $a[0].stages.culling.flops == 0' >/dev/null \
  && ok || bad "approx: modeled rate $(jq .modeled_mpixels_per_s "$TMP/approx/report.json") -> \
$(jq .modeled_mpixels_per_s "$TMP/approx-obj/report.json"), culling flops $(jq .stages.culling.flops "$TMP/approx-obj/report.json")"

# No culling stage in the thesis' design: the back faces traces/scenes/culling.json
# asks to cull are tested on the lighting board, at the culling stage's flops.
# Built (back faces "always"), the culling stage does the same tests and lighting
# no longer does: the same frame, the same culled polygons, the flops moved.
printf '{"culling": {"back_faces": "always"}}\n' > "$TMP/always.json"
"$GIRTD" render traces/scenes/culling.json --backend approx --out "$TMP/bf-off" --quiet || bad "culling.json failed"
"$GIRTD" render traces/scenes/culling.json --backend approx --config "$TMP/always.json" --out "$TMP/bf-on" --quiet \
  || bad "culling.json with back faces always failed"
jq -n --slurpfile a "$TMP/bf-off/report.json" --slurpfile b "$TMP/bf-on/report.json" \
  '$a[0].image_sha256 == $b[0].image_sha256 and $a[0].frontend.culled == $b[0].frontend.culled
   and $a[0].frontend.culled > 0 and $a[0].stages.culling.flops == 0 and $b[0].stages.culling.flops > 0
   and $a[0].stages.lighting.flops - $b[0].stages.lighting.flops == $b[0].stages.culling.flops' >/dev/null \
  && ok || bad "back-face tests without a culling stage: culling $(jq .stages.culling.flops "$TMP/bf-off/report.json") \
-> $(jq .stages.culling.flops "$TMP/bf-on/report.json"), lighting $(jq .stages.lighting.flops "$TMP/bf-off/report.json") \
-> $(jq .stages.lighting.flops "$TMP/bf-on/report.json")"

# A forced back-face cull: the demo's glass sphere is transparent, so its
# back faces stay, counted and warned.
"$GIRTD" render traces/scenes/demo.json --backend golden --config config/presets/culling.json \
  --out "$TMP/demo" --quiet 2> "$TMP/demo.err" || bad "demo with the culling preset failed"
grep -q '^warning: .*back faces of transparent surfaces' "$TMP/demo.err" && ok || bad "no exemption warning: $(cat "$TMP/demo.err")"
jq -e '.frontend.back_faces_exempt > 0 and .frontend.culled > 0
       and any(.warnings[]; test("back faces of transparent surfaces"))' "$TMP/demo/report.json" >/dev/null \
  && ok || bad "demo: exemption not counted: $(jq -c .frontend "$TMP/demo/report.json")"

# Culling back faces changes the frame only within Q + 1 px of a silhouette
# edge (tools/silhouette_check.py, on the unculled run's triangle dump). With
# robust.json: the thesis' seams at shared edges let back faces show through
# the front ones, and culling them changes those pixels too.
robust=config/presets/robust.json
"$GIRTD" render "$scene" --backend golden --config "$robust" --dump "triangle=$TMP/oov.tri" --out "$TMP/r1" --quiet \
  || bad "robust render failed"
"$GIRTD" render "$scene" --backend golden --config "$robust" --config config/presets/culling.json --out "$TMP/r2" \
  --quiet || bad "robust + culling render failed"
if out=$(python3 tools/silhouette_check.py "$TMP/oov.tri" "$TMP/r1/frame.png" "$TMP/r2/frame.png"); then
  [[ $out =~ ^([0-9]+)\ pixels\ differ && ${BASH_REMATCH[1]} -gt 1000 ]] && ok || bad "back faces changed too little: $out"
else bad "culling back faces changed pixels away from the silhouettes: $out"; fi

# A polygon dump keeps the objects, so a replay culls the same.
"$GIRTD" render "$scene" --backend golden --dump "polygons=$TMP/oov.poly" --out "$TMP/dump" --quiet || bad "dump failed"
[[ $(grep -c '^object$' "$TMP/oov.poly") -eq 10 ]] && ok || bad "dump: $(grep -c '^object$' "$TMP/oov.poly") object records, not 10"
"$GIRTD" render "$TMP/oov.poly" --backend golden --config testbench/configs/object_culling.json \
  --out "$TMP/replay" --quiet || bad "replay failed"
jq -e '.frontend.objects_culled == 8' "$TMP/replay/report.json" >/dev/null && ok || bad "replay: objects not kept"
[[ $(jq -r .image_sha256 "$TMP/replay/report.json") == $(jq -r .image_sha256 "$TMP/golden/report.json") ]] \
  && ok || bad "replay draws another frame"

# A bad value is refused where it was written.
printf '{\n  "culling": {"back_faces": "sometimes"}\n}\n' > "$TMP/bad.json"
"$GIRTD" render "$scene" --backend golden --config "$TMP/bad.json" --out "$TMP/bad" 2> "$TMP/bad.err"
[[ $? -eq 2 ]] && grep -q "bad.json:2: culling.back_faces" "$TMP/bad.err" && [[ ! -e $TMP/bad ]] \
  && ok || bad "bad culling.back_faces: $(cat "$TMP/bad.err")"
finish
