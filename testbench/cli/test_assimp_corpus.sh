#!/usr/bin/env bash
# assimp's own test models (Debian assimp-testmodels, /usr/share/assimp/models):
# every file in it either renders on golden (exit 0) or is refused (exit 2,
# one line on stderr naming the file, no output folder); none crashes, hangs
# past the import's limit or exits otherwise. A file refused as no trace is
# not a model format (a texture, a glTF buffer, a note): counted apart. Named files that must render with their content visible render
# the same frame on rtl. Prints the counts per folder (rendered, refused, the
# refusals' commonest reasons) and writes them to OUT (a Markdown table).
# Usage: test_assimp_corpus.sh GIRTD_BINARY REPO_ROOT OUT
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1" "$2"
out=$3
CORPUS=/usr/share/assimp/models
[[ -d "$CORPUS" ]] || { echo "SKIP: $CORPUS is not there (Debian assimp-testmodels; tools/girtd test installs it)"; exit 77; }

# The files of the issue's list: visible content, and rtl draws golden's frame.
MUST_RENDER=(Collada/duck.dae Collada/teapots.DAE 3DS/fels.3ds FBX/box.fbx
             glTF2/BoxTextured-glTF-Binary/BoxTextured.glb glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
             AC/Wuson.ac LWO/LWO2/uvtest.lwo X/test.x ASE/ThreeCubesGreen.ASE)

declare -A rendered refused others reasons
n=0
while IFS= read -r -d '' f; do
  rel=${f#"$CORPUS"/}
  folder=${rel%%/*}
  n=$((n + 1))
  dir="$TMP/r$n"
  timeout 150 "$GIRTD" render "$f" --backend golden --out "$dir" --quiet 2> "$TMP/err"
  rc=$?
  if [[ $rc -eq 0 ]]; then
    rendered[$folder]=$(( ${rendered[$folder]:-0} + 1 )); ok
  elif [[ $rc -eq 2 ]]; then
    if [[ $(wc -l < "$TMP/err") -eq 1 ]] && grep -qF "$f" "$TMP/err" && [[ ! -e "$dir" ]]; then
      ok
      # The reason without the file's name and place: what the refusals have in common.
      line=$(cat "$TMP/err")
      line=${line#"$f"}
      why=$(sed -E 's/^(:@?[0-9]+)?: //; s/[0-9]+/N/g' <<< "$line")
      (( ${#why} > 90 )) && why="$(cut -c1-90 <<< "$why" | sed -E 's/ [^ ]*$//') ..."
      if [[ "$why" == "not a GIRTD trace"* || "$why" == "empty trace"* ]]; then
        others[$folder]=$(( ${others[$folder]:-0} + 1 ))  # a texture, a buffer, a note: not a model format
      else
        refused[$folder]=$(( ${refused[$folder]:-0} + 1 ))
        reasons[$folder]+="$why"$'\n'
      fi
    else
      bad "$rel: refused without one line naming it, or with output: $(head -c 300 "$TMP/err")"
    fi
  else
    bad "$rel: exit $rc: $(head -c 300 "$TMP/err")"
  fi
  rm -rf "$dir"
done < <(find "$CORPUS" -type f -print0 | sort -z)

for rel in "${MUST_RENDER[@]}"; do
  for b in golden rtl; do
    timeout 300 "$GIRTD" render "$CORPUS/$rel" --backend $b --out "$TMP/must_$b" --quiet 2> "$TMP/err" \
      && ok || bad "$rel: $b: $(head -c 300 "$TMP/err")"
  done
  px=$(jq .pixels_written "$TMP/must_golden/report.json" 2>/dev/null || echo 0)
  [[ ${px:-0} -gt 1000 ]] && ok || bad "$rel: only $px pixels drawn"
  [[ "$(jq -r .image_sha256 "$TMP/must_golden/report.json" 2>/dev/null)" == \
     "$(jq -r .image_sha256 "$TMP/must_rtl/report.json" 2>/dev/null)" ]] && ok || bad "$rel: rtl's frame differs from golden's"
  rm -rf "$TMP/must_golden" "$TMP/must_rtl"
done

{
  echo "| folder | model files | rendered | refused | the refusals' commonest reasons | other files |"
  echo "|---|---|---|---|---|---|"
  tr=0 tx=0 to=0
  while IFS= read -r folder; do
    r=${rendered[$folder]:-0} x=${refused[$folder]:-0} o=${others[$folder]:-0}
    tr=$((tr + r)) tx=$((tx + x)) to=$((to + o))
    why=$(printf '%s' "${reasons[$folder]:-}" | sort | uniq -c | sort -rn | head -2 |
          sed -E 's/^ *([0-9]+) (.*)/`\2` (\1)/; s/\|/\\|/g' | paste -sd ';' - | sed 's/;/; /g')
    echo "| $folder | $((r + x)) | $r | $x | $why | $o |"
  done < <(printf '%s\n' "${!rendered[@]}" "${!refused[@]}" "${!others[@]}" | sort -u)
  echo "| all | $((tr + tx)) | $tr | $tx | | $to |"
} > "$out"
cat "$out"
echo "$n files"
finish
