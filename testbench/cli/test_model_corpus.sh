#!/usr/bin/env bash
# The real-world model corpus (traces/models/corpus/, manifest corpus.tsv):
# every file renders on golden, approx and rtl with exit 0 and the same frame
# on all three; that frame is its twin's (the same shape written without the
# feature) or the stored, blessed image_sha256; a file with a twin has the
# twin's Z buffer and triangles_in (a face dropped where nobody sees it
# still counts); a `shape:` twin has only those (the file's materials or
# vertex colours are drawn, the twin has none);
# the front end's polygon count (report.json frontend.polygons, golden) is
# the manifest's `polygons`, which make_corpus.py took from the face lists it
# wrote (so a reader that drops or splits faces is caught even where its
# twin is read by the same reader);
# `warning` rows warn on stderr and in report.json, `ok` rows do neither;
# something was drawn (pixels_written > 1000).
# Usage: test_model_corpus.sh GIRTD_BINARY REPO_ROOT
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"

CORPUS=traces/models/corpus
MANIFEST=$CORPUS/corpus.tsv
BACKENDS=(golden approx rtl)

# A top-level key of report.json (written with 2-space indent): its value.
report_value() {  # REPORT KEY
  jq -r --arg k "$2" '.[$k]' "$1"
}

files=() twins=() expects=() shas=() polys=()
while IFS=$'\t' read -r file twin expect what stored polygons; do
  [[ -z "$file" || "$file" == \#* ]] && continue
  files+=("$file") twins+=("$twin") expects+=("$expect") shas+=("$stored") polys+=("$polygons")
  [[ -f "$CORPUS/$file" ]] && ok || bad "$file: listed in corpus.tsv but missing"
  [[ "$expect" == ok || "$expect" == warning ]] && ok || bad "$file: expect '$expect' is neither ok nor warning"
  [[ -n "$what" ]] && ok || bad "$file: no description"
  [[ "$stored" == - || "$stored" =~ ^[0-9a-f]{64}$ ]] && ok || bad "$file: stored sha '$stored' is neither - nor 64 hex digits"
  [[ "$twin" == - || "$stored" == - ]] && ok || bad "$file: both a twin and a stored sha"
  [[ "$polygons" =~ ^[1-9][0-9]*$ ]] && ok || bad "$file: polygons '$polygons' is not a count (run make_corpus.py)"
done < "$MANIFEST"
[[ ${#files[@]} -gt 0 ]] && ok || bad "no rows in $MANIFEST"

# Every model file of the corpus is in the manifest.
declare -A listed
for f in "${files[@]}"; do listed[$f]=1; done
for path in "$CORPUS"/*.obj "$CORPUS"/*.off "$CORPUS"/*.ply "$CORPUS"/*.stl; do
  [[ -e "$path" ]] || continue  # a pattern nothing matched
  name=$(basename "$path")
  # (no grep -q on a pipe: under pipefail its early exit can fail the printf)
  [[ -n "${listed[$name]:-}" ]] && ok || bad "$name: not in corpus.tsv"
done

declare -A golden_sha golden_tris golden_z
for i in "${!files[@]}"; do
  f=${files[$i]}
  [[ -f "$CORPUS/$f" ]] || continue
  first_sha="" first_backend=""
  for b in "${BACKENDS[@]}"; do
    out="$TMP/$f.$b"
    "$GIRTD" render "$CORPUS/$f" --backend "$b" --out "$out" --z-png --quiet 2> "$out.err"; rc=$?
    if [[ $rc -ne 0 || ! -f "$out/report.json" ]]; then
      bad "$f on $b: exit $rc: $(head -c 300 "$out.err")"
      continue
    fi
    ok
    sha=$(report_value "$out/report.json" image_sha256)
    if [[ -z "$first_sha" ]]; then first_sha=$sha first_backend=$b
    else [[ "$sha" == "$first_sha" ]] && ok || bad "$f: $b frame $sha differs from $first_backend's $first_sha"; fi
    if [[ ${expects[$i]} == warning ]]; then
      awk -v f="$CORPUS/$f" 'index($0, "warning: ") == 1 && index($0, f) { found = 1 } END { exit !found }' "$out.err" &&
        ok || bad "$f on $b: no 'warning: ' line naming the file on stderr"
      jq -e '.warnings | length > 0' "$out/report.json" >/dev/null && ok || bad "$f on $b: report.json warnings is empty"
    else
      ! grep -q '^warning: ' "$out.err" && ok || bad "$f on $b: unexpected $(grep -m1 '^warning: ' "$out.err")"
      jq -e '.warnings == []' "$out/report.json" >/dev/null && ok || bad "$f on $b: report.json warnings is not empty"
    fi
    if [[ $b == golden ]]; then
      golden_sha[$f]=$sha
      golden_tris[$f]=$(report_value "$out/report.json" triangles_in)
      golden_z[$f]=$(sha256sum < "$out/z.png")
      pixels=$(report_value "$out/report.json" pixels_written)
      [[ "${pixels:-0}" -gt 1000 ]] && ok || bad "$f: pixels_written ${pixels:-none}: nothing drawn"
      polygons=$(jq -r '.frontend.polygons' "$out/report.json")
      [[ "$polygons" == "${polys[$i]}" ]] && ok ||
        bad "$f: frontend.polygons $polygons, the file holds ${polys[$i]} (corpus.tsv)"
    fi
  done
done

# Twins and stored frames (twins may come later in the manifest).
for i in "${!files[@]}"; do
  f=${files[$i]} twin=${twins[$i]} stored=${shas[$i]}
  [[ -n "${golden_sha[$f]:-}" ]] || continue
  if [[ $twin != - ]]; then
    shape_only=0
    [[ $twin == shape:* ]] && shape_only=1 twin=${twin#shape:}
    if [[ -z "${golden_sha[$twin]:-}" ]]; then bad "$f: twin $twin has no golden frame (not in corpus.tsv, or it failed)"; continue; fi
    if [[ $shape_only == 0 ]]; then
      [[ "${golden_sha[$f]}" == "${golden_sha[$twin]}" ]] && ok ||
        bad "$f: frame ${golden_sha[$f]} differs from its twin $twin's ${golden_sha[$twin]}"
    else
      [[ "${golden_sha[$f]}" != "${golden_sha[$twin]}" ]] && ok ||
        bad "$f: frame is its shape twin $twin's: the file's colours were not drawn"
    fi
    [[ "${golden_z[$f]}" == "${golden_z[$twin]}" ]] && ok || bad "$f: Z buffer differs from its twin $twin's"
    [[ "${golden_tris[$f]}" == "${golden_tris[$twin]}" ]] && ok ||
      bad "$f: triangles_in ${golden_tris[$f]}, its twin $twin's ${golden_tris[$twin]}"
  fi
  if [[ $stored != - ]]; then
    [[ "${golden_sha[$f]}" == "$stored" ]] && ok ||
      bad "$f: frame ${golden_sha[$f]} is not the stored $stored (re-bless: traces/models/README.md)"
  fi
done

finish
