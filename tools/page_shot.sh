#!/usr/bin/env bash
# Opens a page in headless Chromium (offline: background networking off) and
# prints its DOM after its scripts ran, or saves a screenshot.
# Usage: tools/page_shot.sh dom PAGE.html
#        tools/page_shot.sh png PAGE.html OUT.png [WIDTH,HEIGHT]
# As root Chromium needs --no-sandbox; a fresh profile each time.
set -euo pipefail
what=$1 page=$(realpath "$2")
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
chrome=(chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking
        --disable-component-update --disable-sync --user-data-dir="$profile" --virtual-time-budget=10000)
case "$what" in
  dom) timeout 120 "${chrome[@]}" --dump-dom "file://$page" 2>/dev/null ;;
  png) timeout 120 "${chrome[@]}" --window-size="${4:-1400,2400}" --screenshot="$(realpath -m "$3")" "file://$page" \
         >/dev/null 2>&1 ;;
  *) echo "usage: $0 dom|png PAGE.html [OUT.png [WIDTH,HEIGHT]]" >&2; exit 2 ;;
esac
