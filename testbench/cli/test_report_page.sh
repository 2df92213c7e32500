#!/usr/bin/env bash
# report.html in a real browser (headless Chromium, tools/page_shot.sh): the
# demo scene on approx, 2 frames.
# - the page refers to nothing on the network, and renders without errors;
# - each chart holds the run's data, read back from the page: every SystemC
#   stage's busy, starved and blocked seconds summed over its timeline equal
#   report.json's (the DDA's and the HAD's busy and blocked: their timelines
#   come from the back end's counters, starved there is the rest), the FIFO
#   charts' peaks equal fifo_in_max, the page-miss
#   heat map's cells add up to cache.page_misses, the waste map is there;
# - a screenshot is kept in OUT_DIR.
# Usage: test_report_page.sh GIRTD_BINARY REPO_ROOT OUT_DIR
source "$(dirname "$0")/cli_lib.sh" "$1" "$2"
OUT=$3
mkdir -p "$OUT"
command -v chromium >/dev/null || { bad "chromium is not installed (tools/girtd test installs it)"; finish; exit; }
"$GIRTD" render traces/scenes/demo.json --backend approx --repeat 2 --out "$TMP/d" --quiet 2>/dev/null \
  && ok || bad "render failed"
P=$TMP/d/report.html
grep -qE '(src|href)="(https?:)?//' "$P" && bad "the page refers to the network" || ok
tools/page_shot.sh dom "$P" > "$TMP/dom.html" && ok || bad "chromium failed"
python3 - "$TMP/dom.html" "$TMP/d/report.json" <<'PY' && ok || bad "the page's data differ from report.json (above)"
import html.parser, json, sys
class Attrs(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(); self.body = {}; self.charts = {}; self.miss = None; self.waste = False
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "body": self.body = a
        if a.get("class") == "chart": self.charts[a["data-stage"]] = a
        if a.get("id") == "miss_map": self.miss = a
        if a.get("id") == "waste_map" and a.get("src", "").startswith("data:image/png;base64,"): self.waste = True
p = Attrs(); p.feed(open(sys.argv[1]).read())
r = json.load(open(sys.argv[2]))
errors = []
if p.body.get("data-ready") != "1": errors.append("the page's script did not finish")
if p.body.get("data-errors") != "0": errors.append("errors in the page: " + p.body.get("data-error-text", ""))
timed = [s for s in r["stage_order"] if s not in ("dda", "had")]
for name in r["stage_order"]:
    c, st = p.charts.get(name), r["stages"][name]
    if c is None: errors.append("no chart for " + name); continue
    keys = (("busy_s", "data-busy-s"), ("blocked_s", "data-blocked-s"))
    if name in timed: keys += (("starved_s", "data-starved-s"),)
    for key, attr in keys:
        got = float(c.get(attr, "nan"))
        if not abs(got - st[key]) <= 1e-9 + 1e-6 * abs(st[key]): errors.append("%s %s: page %r, report %r" % (name, key, got, st[key]))
for name in r["stage_order"]:
    c = p.charts.get(name)
    if c is not None and "data-fifo-max" in c and int(float(c["data-fifo-max"])) != r["stages"][name]["fifo_in_max"] \
            and name != "had":
        errors.append("%s FIFO peak: page %s, report %s" % (name, c["data-fifo-max"], r["stages"][name]["fifo_in_max"]))
if p.miss is None or int(p.miss.get("data-misses-sum", -1)) != r["cache"]["page_misses"]:
    errors.append("page-miss map: %r against %r" % (p.miss and p.miss.get("data-misses-sum"), r["cache"]["page_misses"]))
if not p.waste: errors.append("no waste map")
if len(timed) < 5: errors.append("only %d timed stages" % len(timed))
print("\n".join(errors))
sys.exit(1 if errors else 0)
PY
# --compare reference: the error histogram counts every pixel, and the
# differing ones equal a comparison of the two PNGs made here (PIL).
"$GIRTD" render traces/demo.trace --backend approx --compare reference --out "$TMP/c" --quiet 2>/dev/null \
  && "$GIRTD" render traces/demo.trace --backend reference --out "$TMP/r" --quiet 2>/dev/null && ok || bad "renders failed"
want=$(/usr/bin/python3 -c "
import sys, numpy
from PIL import Image
a, b = (numpy.asarray(Image.open(f).convert('RGB'), dtype=int) for f in sys.argv[1:3])
print('data-pixels=\"%d\" data-differing=\"%d\"' % (a.shape[0] * a.shape[1], int((abs(a - b).max(axis=2) > 0).sum())))
" "$TMP/c/frame.png" "$TMP/r/frame.png")
tools/page_shot.sh dom "$TMP/c/report.html" > "$TMP/cdom.html"
grep -q 'data-errors="0"' "$TMP/cdom.html" && grep -q "$want" "$TMP/cdom.html" && ok \
  || bad "--compare: $(grep -oE '<body[^>]*>|<div id="error_histogram"[^>]*>' "$TMP/cdom.html"), want $want"
tools/page_shot.sh png "$P" "$OUT/report_page.png" && [[ $(head -c 4 "$OUT/report_page.png" | tail -c 3) == PNG ]] \
  && ok || bad "no screenshot"
finish
