#!/usr/bin/env bash
# End-to-end checks of the front end on the command line: every model format
# renders, the report counts the front end, polygon dump and replay agree, and
# broken models and scenes give exit 2, one line FILE:LINE: what, no output.
# Usage: test_frontend_cli.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"

# 1. OBJ, PLY, STL and OFF models render with a front-end report.
for m in cube.obj sphere.ply sphere.stl torus.off; do
  "$GIRTD" render "traces/models/$m" --out "$TMP/$m" --quiet && ok || bad "render $m"
  jq -e '.frontend.triangles_made > 0' "$TMP/$m/report.json" >/dev/null && ok || bad "$m: no frontend.triangles_made"
  jq -e '.level == "polygon"' "$TMP/$m/report.json" >/dev/null && ok || bad "$m: level is not polygon"
done
grep -q "triangles_made" "$TMP/cube.obj/report.md" && ok || bad "report.md lacks the front-end table"

# 2. A scene: --dump polygons=FILE replays to the same picture.
"$GIRTD" render traces/scenes/animation.json --out "$TMP/a1" --dump "polygons=$TMP/a.poly" --quiet && ok || bad "scene dump run"
"$GIRTD" render "$TMP/a.poly" --out "$TMP/a2" --quiet && ok || bad "polygon replay run"
h1=$(jq -r .image_sha256 "$TMP/a1/report.json")
h2=$(jq -r .image_sha256 "$TMP/a2/report.json")
[[ -n "$h1" && "$h1" == "$h2" ]] && ok || bad "polygon dump replay differs: $h1 vs $h2"
"$GIRTD" render traces/equilateral_200.trace --out "$TMP/eq" --dump "polygons=$TMP/x.poly" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 && ! -e "$TMP/x.poly" ]] && ok || bad "polygon dump of a triangle trace gave exit $rc"

# 3. Bad models and scenes: exit 2, one line FILE[:LINE]: what, no output
# directory. The line is required wherever the file has one to give.
expect_bad() {  # NAME CONTENT PATTERN
  local f="$TMP/$1"
  printf "$2" > "$f"
  "$GIRTD" render "$f" --out "$TMP/out_$1" 2> "$TMP/err"; local rc=$?
  [[ $rc -eq 2 ]] && ok || bad "$1: exit $rc"
  grep -qE "$3" "$TMP/err" && ok || bad "$1: error '$(cat "$TMP/err")' does not match '$3'"
  [[ $(wc -l < "$TMP/err") -eq 1 ]] && ok || bad "$1: error is not one line"
  [[ ! -e "$TMP/out_$1" ]] && ok || bad "$1: output written for bad input"
}
expect_bad empty.obj '' 'empty.obj: empty file'
expect_bad index.obj 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n' 'index.obj:4: vertex index 7 is out of range'
expect_bad index.off 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n' 'index.off:6: vertex index 5 is out of range'
expect_bad index.ply 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n' 'index.ply:13: vertex index 9 is out of range'
expect_bad bigface.off 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n10 0 1 2 0 1 2 0 1 2 0\n' 'bigface.off:6: a face of 10 corners'
# A 200-byte binary PLY whose face claims 10^8 indices: refused before assimp allocates for them.
expect_bad hugelist.ply 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\x00\x00\x00\xe1\xf5\x05\x00\x00\x00\x00\x01\x00\x00\x00\x02\x00\x00\x00' 'hugelist.ply:@[0-9]+: element .face. 0 lists 100000000 values'
expect_bad asciilist.ply 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n100000000 0 1 2\n' 'asciilist.ply:13: element .face. 0 lists 100000000 values'
expect_bad model.3ds 'not read' 'model.3ds: cannot read the model: '
expect_bad absurd.off 'OFF\n99999999999 1 0\n0 0 0\n' 'absurd.off:2: header claims 99999999999 vertices'
expect_bad absurd.ply 'ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n' 'absurd.ply:3: header claims'
expect_bad short.stl 'not a solid, not 84 bytes' 'short.stl:@[0-9]+: binary STL'
expect_bad nan.obj 'v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n' 'nan.obj:2: .*NaN or infinite'
expect_bad inf.obj 'v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n' 'inf.obj:2: .*NaN or infinite'
expect_bad lines.obj 'v 0 0 0\nv 1 0 0\nl 1 2\n' 'lines.obj: .*no polygons'
expect_bad syntax.json '{\n  "girtd_scene": 1,\n  "models": [,]\n}\n' 'syntax.json:3: invalid JSON'
expect_bad unknown.json '{\n  "girtd_scene": 1,\n  "modles": []\n}\n' 'unknown.json:3: unknown key "modles"'
expect_bad nofile.json '{"girtd_scene": 1,\n "models": [{"file": "missing.obj"}]}\n' 'nofile.json:2: model file .*missing.obj does not exist'
expect_bad badcam.json '{"girtd_scene": 1,\n "models": [{"file": "'"$ROOT"'/traces/models/cube.obj"}],\n "camera": {"eye": [0, 0, 5], "target": [0, 0, 5]}}\n' 'badcam.json:3: eye equals target'
expect_bad version.json '{"girtd_scene": 7, "models": []}' 'version.json:1: scene version 7'
# A scene naming a broken model: the scene's line, then the model's own FILE:LINE.
expect_bad badmodel.json '{"girtd_scene": 1,\n "models": [{"file": "index.obj"}]}\n' 'badmodel.json:2: model .*index.obj:4: vertex index 7 is out of range'
# 400 KB of [ : refused before parsing (it crashed the line scanner).
head -c 400000 /dev/zero | tr '\0' '[' > "$TMP/deep_content"
expect_bad deep.json "$(cat "$TMP/deep_content")" 'deep.json:1: JSON nested deeper than 64 levels'
expect_bad badpoly.trace 'girtd-trace 1 polygon\nsurface 0 1 1 1 1 0 0 0 0 0 0 0 0 0\ncamera 0 0 0 1 0 0 0 1 0 0 0 -1 1\nfocal 0.1\npoly 0 3 0 0 0 1 0 0 1 1 nan\n' 'badpoly.trace:5: Z'

# 4. Names with / and ~ are plain names (JSON pointers escape them).
printf '%s' '{"girtd_scene": 1,
 "materials": {"a/b": {"colour": [250, 10, 10]}, "c~1": {"n": 7}},
 "models": [{"name": "m/1", "file": "'"$ROOT"'/traces/models/cube.obj", "material": "a/b"},
            {"name": "m~0", "file": "'"$ROOT"'/traces/models/cube.obj", "material": "c~1", "translate": [3, 0, 0]}],
 "frames": [{}, {"models": {"m/1": {"rotate_deg": [0, 30, 0]}, "m~0": {"scale": 0.5}}}]}' > "$TMP/names.json"
"$GIRTD" render "$TMP/names.json" --out "$TMP/names" --quiet 2> "$TMP/err" && ok || bad "names with / and ~: $(cat "$TMP/err")"
printf '%s' '{"girtd_scene": 1,
 "materials": {"a/b": {"n": 500}},
 "models": [{"file": "'"$ROOT"'/traces/models/cube.obj"}]}' > "$TMP/badn.json"
"$GIRTD" render "$TMP/badn.json" --out "$TMP/badn" 2> "$TMP/err"; rc=$?
[[ $rc -eq 2 ]] && grep -qE 'badn.json:2: "materials/a/b/n" = 500 is outside 1..200' "$TMP/err" && ok || bad "n = 500 under a/b: exit $rc, '$(cat "$TMP/err")'"

finish
