# Shared set-up of the CLI test scripts: sourced with GIRTD_BINARY REPO_ROOT
# as $1 $2. Gives GIRTD and ROOT (absolute), a scratch $TMP removed on exit,
# ok / bad counters and `finish` printing "N passed, N failed".
set -uo pipefail
GIRTD=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
ROOT=$(cd "$2" && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$ROOT"
fails=0
passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }
finish() {
  echo "$passes passed, $fails failed"
  [[ $fails -eq 0 ]]
}
