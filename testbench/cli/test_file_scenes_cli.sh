#!/usr/bin/env bash
# Scenes in model files (traces/models/file_scenes/, sim/io/README.md
# "Materials, cameras and lights"): a glTF's materials, cameras and light, a
# PLY's vertex colours, an OBJ's texture and a broken material library give
# the pixels worked out by hand below; the three back ends draw the same
# frame; --camera picks a camera by name and refuses an unknown one in one
# line; a scene's own keys override the file's; a polygon dump keeps the
# corner colours.
# Usage: test_file_scenes_cli.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "$0")/cli_lib.sh" "$1" "$2"
dir=$ROOT/traces/models/file_scenes

# pixel PNG X Y: "R G B" of one pixel (x right, y down from the top-left).
pixel() {
  "$PYTHON" -c 'import sys, matplotlib.image as m
a = m.imread(sys.argv[1]); x, y = int(sys.argv[2]), int(sys.argv[3])
print(*(int(round(v * 255)) for v in a[y, x, :3]))' "$@"
}
# expect NAME PNG X Y CONDITION: CONDITION on r, g, b (a Python expression).
expect() {
  local name=$1 png=$2 x=$3 y=$4 cond=$5 rgb
  rgb=$(pixel "$png" "$x" "$y") || { bad "$name: cannot read $png"; return; }
  python3 -c "r, g, b = map(int, '$rgb'.split()); import sys; sys.exit(0 if ($cond) else 1)" \
    && ok || bad "$name: pixel ($x, $y) is ($rgb), expected $cond"
}
sha() { jq -r .image_sha256 "$1/report.json"; }

# --- two_materials.gltf through its first camera, "front": eye (0, 0, 5),
# vertical field of view 0.8 rad, so D/S = 1 / tan(0.4) = 2.365 and a point
# (X, Y, 0) lands at x = 512 + 512 * 2.365 * X / 5 = 512 + 242.2 X. The red
# quad (X -2..-0.2) covers x 28..464, the blue one (0.2..2) 560..996, both
# y 270..754. Lighting: the point light at (0, 0, 10) becomes a light from
# +z, its intensity normalised to 0.75 beside an ambient 0.25; a quad's own
# channel saturates (0.25 + 0.75 cos 0 = 1); the others hold only the
# specular term, CRE(~0 deg) 0.30 x (R.E)^n x 0.75 x 255 = 57 x (R.E)^n,
# Gouraud-interpolated from the corners. Red: roughness 1, n = 2/1 - 2 = 0,
# clamped to 1; R.E from 0.91 (the far corners) to 1: 52..57 inside. Blue:
# roughness 0.5, n = 2/0.5^4 - 2 = 30; R.E is 0.981 at the inner corners
# (31) and 0.913 at the outer ones (3.7); the quad's centre lies on the
# diagonal between an inner and an outer corner: (31 + 3.7) / 2 = 17.
gltf=$dir/two_materials.gltf
for backend in golden approx rtl; do
  "$GIRTD" render "$gltf" --backend "$backend" --out "$TMP/tm-$backend" --quiet 2> "$TMP/tm-$backend.err" \
    || bad "$backend: two_materials.gltf failed: $(cat "$TMP/tm-$backend.err")"
done
png=$TMP/tm-golden/frame.png
expect "front, red quad" "$png" 246 512 'r >= 250 and 45 <= g <= 60 and abs(g - b) <= 2'
expect "front, blue quad" "$png" 778 512 'b >= 250 and 14 <= r <= 21 and abs(r - g) <= 1'
expect "front, gap between the quads" "$png" 512 512 'r == g == b == 0'
expect "front, above the quads" "$png" 246 200 'r == g == b == 0'
[[ $(sha "$TMP/tm-golden") == $(sha "$TMP/tm-approx") && $(sha "$TMP/tm-golden") == $(sha "$TMP/tm-rtl") ]] \
  && ok || bad "golden, approx and rtl draw two_materials.gltf differently"
grep -q 'PBR metal/roughness approximated' "$TMP/tm-golden.err" && ok || bad "no PBR warning: $(cat "$TMP/tm-golden.err")"

# The materials' exponents, as the polygon dump records them.
"$GIRTD" render "$gltf" --dump "polygons=$TMP/tm.poly" --out "$TMP/tm-dump" --quiet 2>/dev/null || bad "dump failed"
[[ $(awk '$1 == "surface" { print $2, $6 }' "$TMP/tm.poly" | tr '\n' ' ') == "0 1 1 30 " ]] && ok \
  || bad "surface exponents: $(grep '^surface' "$TMP/tm.poly")"

# The second camera, "far", at (0, 0, 10) (its aspect ratio 2 changes
# nothing: the vertical angle spans the square screen): 121.1 px per unit, the red
# quad's centre (X -1.1) at x 379, the blue one's at 645, their inner
# edges at 488 and 536.
"$GIRTD" render "$gltf" --camera far --out "$TMP/far" --quiet 2>/dev/null || bad "--camera far failed"
expect "far, red quad" "$TMP/far/frame.png" 379 512 'r >= 250 and g < 70'
expect "far, blue quad" "$TMP/far/frame.png" 645 512 'b >= 250 and r < 70'
expect "far, gap" "$TMP/far/frame.png" 512 512 'r == g == b == 0'
expect "far, left of the red quad" "$TMP/far/frame.png" 246 512 'r == g == b == 0'

# An unknown camera: one line naming the file's cameras, exit 2, no output.
"$GIRTD" render "$gltf" --camera nope --out "$TMP/nope" > /dev/null 2> "$TMP/nope.err"
rc=$?
[[ $rc -eq 2 && $(wc -l < "$TMP/nope.err") -eq 1 && ! -e $TMP/nope ]] && grep -q '"front", "far"' "$TMP/nope.err" \
  && ok || bad "--camera nope: exit $rc, $(cat "$TMP/nope.err")"
# A name the file gives holding a newline is written \x0a: still one line.
jq '.nodes[2].name = "fr\nont"' "$gltf" > "$TMP/newline.gltf"
"$GIRTD" render "$TMP/newline.gltf" --camera nope --out "$TMP/nope" > /dev/null 2> "$TMP/nope.err"
rc=$?
[[ $rc -eq 2 && $(wc -l < "$TMP/nope.err") -eq 1 ]] && grep -q 'fr\\x0aont' "$TMP/nope.err" \
  && ok || bad "a camera name with a newline: exit $rc, $(cat "$TMP/nope.err")"
"$GIRTD" render traces/scenes/polygons.poly --camera front --out "$TMP/trace" 2> "$TMP/trace.err"
[[ $? -eq 2 && $(wc -l < "$TMP/trace.err") -eq 1 ]] && ok || bad "--camera on a trace: $(cat "$TMP/trace.err")"

# The same file placed by a scene: without "camera" and "lights" the file's
# own are used (the same frame as rendering the file); "camera": "auto"
# frames it anew.
cat > "$TMP/placed.json" <<EOF
{"girtd_scene": 1, "models": [{"file": "$gltf"}]}
EOF
"$GIRTD" render "$TMP/placed.json" --out "$TMP/placed" --quiet 2>/dev/null || bad "scene placing the glTF failed"
[[ $(sha "$TMP/placed") == $(sha "$TMP/tm-golden") ]] && ok || bad "a scene without camera and lights differs from the file's own"
cat > "$TMP/auto.json" <<EOF
{"girtd_scene": 1, "camera": "auto", "models": [{"file": "$gltf"}]}
EOF
"$GIRTD" render "$TMP/auto.json" --out "$TMP/auto" --quiet 2>/dev/null || bad "scene with camera auto failed"
[[ $(sha "$TMP/auto") != $(sha "$TMP/tm-golden") ]] && ok || bad "\"camera\": \"auto\" kept the file's camera"

# Vertex colours and a texture, seen head on with ambient light only (Id 1,
# no directional light, hence no specular): a pixel's colour is the
# barycentric mix of its corners' colours. Camera at (0, 0, 5), 40 deg:
# 281.3 px per unit. The PLY square's corners (-1, -1) red, (1, -1) green,
# (1, 1) blue, (-1, 1) white: at (+-0.9, +-0.9) the nearest corner weighs
# 0.95 if the square is cut along the diagonal through it (the opposite
# corner 0.05), else 0.9 (the diagonal's two corners 0.05 each): at least
# 229 in its own channels, at most 13 in the others.
flat_scene() {  # flat_scene FILE -> scene JSON on stdout
  printf '{"girtd_scene": 1, "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "fov_deg": 40},
  "lights": {"ambient": 1}, "models": [{"file": "%s"}]}\n' "$1"
}
flat_scene "$dir/vertex_colours.ply" > "$TMP/vc.json"
"$GIRTD" render "$TMP/vc.json" --out "$TMP/vc" --quiet --dump "polygons=$TMP/vc.poly" || bad "vertex colours failed"
png=$TMP/vc/frame.png
expect "vertex colours, red corner" "$png" 259 765 'r >= 228 and g <= 14 and b <= 14'
expect "vertex colours, green corner" "$png" 765 765 'g >= 228 and r <= 14 and b <= 14'
expect "vertex colours, blue corner" "$png" 765 259 'b >= 228 and r <= 14 and g <= 14'
expect "vertex colours, white corner" "$png" 259 259 'min(r, g, b) >= 228'
# The polygon dump keeps the corners' colours: replayed, the same frame.
grep -q '^vpoly ' "$TMP/vc.poly" && ok || bad "the dump has no vpoly record"
"$GIRTD" render "$TMP/vc.poly" --out "$TMP/vc-replay" --quiet || bad "replaying the dump failed"
[[ $(sha "$TMP/vc-replay") == $(sha "$TMP/vc") ]] && ok || bad "the replayed dump draws another frame"
# A scene's "material" overrides the file's colours: one colour everywhere.
sed 's/"file": "[^"]*"/&, "material": "grey"/; s/"models"/"materials": {"grey": {"colour": [100, 100, 100]}}, &/' \
  "$TMP/vc.json" > "$TMP/vc-grey.json"
"$GIRTD" render "$TMP/vc-grey.json" --out "$TMP/vc-grey" --quiet || bad "vertex colours with a scene material failed"
expect "scene material over vertex colours" "$TMP/vc-grey/frame.png" 259 765 'r == g == b == 100'

# A scene's material over a file's materials: they split no surface, so the
# house with its library draws as the house without one.
for f in house_mtl house; do
  printf '{"girtd_scene": 1, "materials": {"grey": {"colour": [150, 150, 150]}},
  "models": [{"file": "%s", "material": "grey"}]}\n' "$ROOT/traces/models/corpus/$f.obj" > "$TMP/$f.json"
  "$GIRTD" render "$TMP/$f.json" --out "$TMP/$f" --quiet 2>/dev/null || bad "$f with a scene material failed"
done
[[ $(sha "$TMP/house_mtl") == $(sha "$TMP/house") ]] && ok || bad "a scene material did not replace the file's materials"

# The OBJ's texture: the left square maps the red texel, the right one the
# blue texel; Kd 1 1 1, so the faces are (255, 0, 0) and (0, 0, 255).
# Their centres (X -+1.1) at x 203 and 821.
flat_scene "$dir/textured.obj" > "$TMP/tx.json"
"$GIRTD" render "$TMP/tx.json" --out "$TMP/tx" --quiet 2> "$TMP/tx.err" || bad "textured OBJ failed"
expect "texture, left square" "$TMP/tx/frame.png" 203 512 'r == 255 and g == b == 0'
expect "texture, right square" "$TMP/tx/frame.png" 821 512 'b == 255 and r == g == 0'
grep -q 'textures are drawn as their mean colour over each face' "$TMP/tx.err" && ok || bad "no texture warning"

# A material library assimp cannot read: a warning, the default material:
# the frame of the same square without a library.
"$GIRTD" render "$dir/broken_library.obj" --out "$TMP/broken" --quiet 2> "$TMP/broken.err" \
  || bad "broken_library.obj failed: $(cat "$TMP/broken.err")"
grep -v 'mtllib\|usemtl' "$dir/broken_library.obj" > "$TMP/plain.obj"
"$GIRTD" render "$TMP/plain.obj" --out "$TMP/plain" --quiet || bad "the plain square failed"
[[ $(sha "$TMP/broken") == $(sha "$TMP/plain") ]] && ok || bad "broken_library.obj is not drawn with the default material"
grep -q 'broken_library.obj: the files it names (its material library) could not be read' "$TMP/broken.err" \
  && ok || bad "no broken-library warning: $(cat "$TMP/broken.err")"
jq -e 'any(.warnings[]; test("could not be read"))' "$TMP/broken/report.json" > /dev/null \
  && ok || bad "the broken-library warning is not in report.json"
expect "broken library, the default grey" "$TMP/broken/frame.png" 512 512 'r == g == b > 0'

# An FBX camera: FieldOfView 49.134 deg in global_settings.fbx of assimp's
# test models, so D/S = 1 / tan(24.567 deg) = 2.1874.
fbx=/usr/share/assimp/models/FBX/global_settings.fbx
if [[ -f $fbx ]]; then
  "$GIRTD" render "$fbx" --dump "polygons=$TMP/fbx.poly" --out "$TMP/fbx" --quiet 2>/dev/null || bad "$fbx failed"
  awk '$1 == "camera" { d = $NF - 2.1874; exit !(d < 0.001 && d > -0.001) }' "$TMP/fbx.poly" && ok \
    || bad "FBX camera: $(grep '^camera' "$TMP/fbx.poly")"
fi
finish
