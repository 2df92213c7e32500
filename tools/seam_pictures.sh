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
  python3 - "$OUT/$name/frame.png" "models/dda/img/glass_$name.png" 680 430 320 340 <<'PY'
import struct, sys, zlib
src, dst, x0, y0, w, h = sys.argv[1], sys.argv[2], *map(int, sys.argv[3:])
data = open(src, "rb").read()
pos, idat, width, height = 8, b"", 0, 0
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR":
        width, height, depth, colour = struct.unpack(">IIBB", body[:10])
        assert depth == 8 and colour == 2, "8-bit RGB expected"
    elif kind == b"IDAT":
        idat += body
    pos += 12 + n
raw, stride, rows, prev = zlib.decompress(idat), 3 * width, [], bytearray(3 * width)
for y in range(height):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - 3] if i >= 3 else 0
        b, c = prev[i], prev[i - 3] if i >= 3 else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line)
    prev = line
out = b"".join(b"\0" + bytes(rows[y][3 * x0:3 * (x0 + w)]) for y in range(y0, y0 + h))
chunk = lambda k, b: struct.pack(">I", len(b)) + k + b + struct.pack(">I", zlib.crc32(k + b))
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) + \
      chunk(b"IDAT", zlib.compress(out, 9)) + chunk(b"IEND", b"")
open(dst, "wb").write(png)
PY
done
