#include "report/report_page.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/image_compare.hpp"
#include "io/png_io.hpp"
#include "report/page_parts.hpp"

namespace girtd {
namespace {

// The page's own script: builds the tables from the data and the charts
// with uPlot, and records on <body> what a test reads back (errors seen,
// and per chart the sums of its series).
constexpr const char* kPageScript = R"JS(
const r = data.report;
const el = (tag, text, cls) => { const e = document.createElement(tag); if (text !== undefined) e.textContent = text; if (cls) e.className = cls; return e; };
function table(rows, head) {
  const t = el('table');
  if (head) { const tr = el('tr'); head.forEach(h => tr.appendChild(el('th', h))); t.appendChild(tr); }
  rows.forEach(row => { const tr = el('tr'); row.forEach(c => tr.appendChild(el('td', c === null || c === undefined ? '—' : String(c)))); t.appendChild(tr); });
  return t;
}
const num = (x, d) => (x === null || x === undefined) ? '—' : Number(x).toFixed(d);
function build() {
  const judged = r.sustained_mpixels_per_s ?? r.modeled_mpixels_per_s;
  const verdict = document.getElementById('verdict');
  if (judged === null || judged === undefined) verdict.textContent = 'untimed back end: no throughput verdict';
  else verdict.textContent = (r.target_met ? 'PASS' : 'FAIL') + ': ' + num(judged, 2) + ' Mpixel/s' +
      (r.sustained_mpixels_per_s !== null && r.sustained_mpixels_per_s !== undefined ? ' sustained' : '') +
      ' against the ' + r.target_mpixels_per_s + ' Mpixel/s target; bottleneck: ' + (r.bottleneck ?? '—');
  verdict.className = r.target_met ? 'pass' : 'fail';
  document.getElementById('run').appendChild(table([
    ['input', r.input], ['back end', r.backend], ['frames', r.frames], ['modeled time (s)', num(r.modeled_time_s, 6)],
    ['wall time (s)', num(r.wall_s, 3)], ['image SHA-256', r.image_sha256]]));
  const ts = r.time_split || {};
  document.getElementById('time').appendChild(table(Object.keys(ts).map(k => [k, num(ts[k], 6)]), ['where the time went', 's']));
  document.getElementById('pixels').appendChild(table([
    ['generated', r.pixels_generated], ['written', r.pixels_written], ['blended', r.pixels_blended],
    ['Z-rejected', r.pixels_z_rejected], ['dropped', r.pixels_dropped]], ['pixels', 'count']));
  const w = document.getElementById('warnings');
  if (!r.warnings.length) w.appendChild(el('p', 'none'));
  r.warnings.forEach(x => w.appendChild(el('p', x, 'warning')));
  const n = r.numerics || {};
  document.getElementById('numerics').appendChild(table(Object.keys(n).filter(k => typeof n[k] === 'object' && n[k] !== null)
      .map(k => [k, n[k].wraps, n[k].saturations, n[k].clamps]), ['EP', 'wraps', 'saturations', 'clamps']));
  document.getElementById('left_out').appendChild(table((r.left_out || []).map(x => [x.unit, x.reason]), ['unit', 'reason']));
  document.getElementById('config').textContent = JSON.stringify(r.config, null, 1);

  const pm = data.page_misses;
  if (pm) {  // each page's cell, coloured on a log scale from blue (1 miss) to orange-white (the most)
    const canvas = document.getElementById('miss_map'), ctx = canvas.getContext('2d');
    const img = ctx.createImageData(pm.width, pm.height);
    const cols = pm.width / pm.page_width_px, most = pm.counts.reduce((m, c) => Math.max(m, c), 1);
    let total = 0;
    pm.counts.forEach((c, page) => {
      total += c;
      const v = c ? Math.round(255 * Math.log1p(c) / Math.log1p(most)) : 0;
      const x0 = (page % cols) * pm.page_width_px, y0 = Math.floor(page / cols) * pm.page_height_px;
      for (let y = y0; y < y0 + pm.page_height_px; ++y)
        for (let x = x0; x < x0 + pm.page_width_px; ++x) {
          const i = 4 * (y * pm.width + x);
          if (c) { img.data[i] = v; img.data[i + 1] = Math.round(v * 0.6); img.data[i + 2] = 255 - v; }
          else { img.data[i] = 24; img.data[i + 1] = 24; img.data[i + 2] = 32; }
          img.data[i + 3] = 255;
        }
    });
    ctx.putImageData(img, 0, 0);
    canvas.dataset.missesSum = total;
    document.getElementById('miss_scale').textContent = 'Log scale: dark none, blue 1, orange-white ' + most +
        ' misses (the most of any page); ' + total + ' in all, ' + pm.page_width_px + ' x ' + pm.page_height_px + ' pixel pages.';
  }
  const charts = document.getElementById('timelines');
  if (typeof uPlot !== 'undefined' && data.compare) {  // the error histogram, log counts
    const h = data.compare.histogram, box = document.getElementById('error_histogram');
    box.dataset.pixels = h.reduce((a, b) => a + b, 0);
    box.dataset.differing = h.slice(1).reduce((a, b) => a + b, 0);
    const last = Math.max(1, h.reduce((m, c, i) => c ? i : m, 0));
    new uPlot({width: 500, height: 220, title: 'pixels by largest channel difference',
               scales: {x: {time: false}, y: {distr: 3}}, axes: [{label: 'difference (LSB)'}, {label: 'pixels'}],
               series: [{}, {label: 'pixels', stroke: '#b2182b', fill: 'rgba(178,24,43,0.3)',
                             paths: uPlot.paths.bars({size: [0.9]})}]},
              [h.slice(0, last + 1).map((_, i) => i), h.slice(0, last + 1).map(c => c || null)], box);
  }
  if (typeof uPlot === 'undefined') { charts.appendChild(el('p', 'The chart library is not in this page (tools/girtd installs it).')); return; }
  const sync = uPlot.sync('time');
  for (const st of data.timeline) {
    const box = el('div', undefined, 'chart');
    box.dataset.stage = st.name;
    box.appendChild(el('h3', st.name));
    charts.appendChild(box);
    const sum = a => a.reduce((s, v) => s + v, 0);
    if (st.bins.length) {
      const x = st.bins.map((_, i) => i * st.bin_s * 1e3);
      // A bin: starved, busy, blocked seconds (StageState's order).
      const frac = k => st.bins.map(b => b[k] / st.bin_s);
      box.dataset.starvedS = sum(st.bins.map(b => b[0]));
      box.dataset.busyS = sum(st.bins.map(b => b[1]));
      box.dataset.blockedS = sum(st.bins.map(b => b[2]));
      new uPlot({width: 900, height: 160, title: st.name + ': share of each ' + num(st.bin_s * 1e6, 1) + ' us',
                 cursor: {sync: {key: sync.key}}, scales: {x: {time: false}},
                 axes: [{label: 'modeled ms'}, {label: 'share'}],
                 series: [{}, {label: 'busy', stroke: '#1b7837', width: 1}, {label: 'starved', stroke: '#b2182b', width: 1},
                          {label: 'blocked', stroke: '#2166ac', width: 1}]},
                [x, frac(1), frac(0), frac(2)], box);
    } else {
      box.appendChild(el('p', 'not recorded on this back end or run'));
    }
    if (st.fifo_in.length) {
      const x = st.fifo_in.map((_, i) => i * st.fifo_in_bin_s * 1e3);
      box.dataset.fifoMax = Math.max(...st.fifo_in);
      new uPlot({width: 900, height: 120, title: 'FIFO in front of ' + st.name + ': most items in each ' +
                 num(st.fifo_in_bin_s * 1e6, 1) + ' us', cursor: {sync: {key: sync.key}}, scales: {x: {time: false}},
                 axes: [{label: 'modeled ms'}, {label: 'items'}],
                 series: [{}, {label: 'occupancy', stroke: '#762a83', width: 1, paths: uPlot.paths.stepped({align: 1})}]},
                [x, st.fifo_in], box);
    }
  }
}
build();
)JS";



// The DDA waste map's pixels: dark grey where nothing was drawn, else a
// blue -> yellow -> red ramp over 0 -> 50 -> 100 % of the clocks wasted.
// The map's levels (0..254, and kNone) index a palette of those colours.
std::string waste_map_png(const ScreenMaps& m) {
  std::array<uint8_t, 3 * 256> palette{};
  for (int w = 0; w < 256; ++w) {
    uint8_t* px = &palette[size_t(3 * w)];
    if (w == ScreenMaps::kNone) {
      px[0] = px[1] = px[2] = 40;
      continue;
    }
    const double f = w / 254.0;
    const double lo = std::min(1.0, 2 * f), hi = std::max(0.0, 2 * f - 1);
    px[0] = uint8_t(255 * lo);
    px[1] = uint8_t(255 * (lo - hi));
    px[2] = uint8_t(255 * (1 - lo));
  }
  return png_indexed_bytes(m.width, m.height, m.dda_waste, palette);
}

// The heat maps' part of the page: the page-miss map is drawn from the data
// by the page's script, the waste map is a picture.
std::string heat_maps_html(const RunStats& s) {
  if (!s.maps) return "<p>Heat maps: on the timed back ends (approx, rtl).</p>";
  std::ostringstream o;
  o << "<div><h2>Page misses per cache page</h2><canvas id=\"miss_map\" width=\"" << s.maps->width
    << "\" height=\"" << s.maps->height << "\" class=\"frame\"></canvas><p id=\"miss_scale\"></p></div>\n"
    << "<div><h2>DDA clocks wasted, by triangle</h2><img class=\"frame\" id=\"waste_map\" alt=\"DDA waste map\" "
    << "src=\"data:image/png;base64," << base64(waste_map_png(*s.maps)) << "\"><p>The share of its DDA clocks "
    << "each triangle spent in states that emitted no pixel, over the pixels it drew (the last triangle drawn "
    << "there): blue 0 %, yellow 50 %, red 100 %; grey: none drawn.</p></div>\n";
  return o.str();
}

// The comparison: a histogram of each pixel's largest channel difference
// (0..255) and its heat map (dark: equal; blue -> red: 1 -> the largest).
std::string compare_html(const RgbImage& frame, const FrameComparison& c, nlohmann::json& data) {
  std::vector<uint64_t> histogram(256, 0);
  RgbImage map;
  map.width = frame.width;
  map.height = frame.height;
  map.rgb.assign(frame.rgb.size(), 0);
  std::vector<uint8_t> diff(frame.rgb.size() / 3);
  int most = 0;
  for (size_t i = 0; i < diff.size(); ++i) {
    int d = 0;
    for (size_t k = 0; k < 3; ++k) d = std::max(d, std::abs(int(frame.rgb[3 * i + k]) - int(c.frame.rgb[3 * i + k])));
    diff[i] = uint8_t(d);
    ++histogram[size_t(d)];
    most = std::max(most, d);
  }
  for (size_t i = 0; i < diff.size(); ++i) {
    uint8_t* px = &map.rgb[3 * i];
    if (!diff[i]) {
      px[0] = px[1] = px[2] = 24;
      continue;
    }
    const double f = most > 1 ? double(diff[i] - 1) / double(most - 1) : 1.0;
    px[0] = uint8_t(60 + 195 * f);
    px[1] = uint8_t(60 * (1 - f));
    px[2] = uint8_t(255 * (1 - f));
  }
  const ImageError e = compare_images(frame, c.frame);
  data["compare"] = {{"against", c.against}, {"histogram", histogram}, {"differing", e.differing},
                     {"max_abs", e.max_abs}, {"mean_abs", e.mean_abs}};
  std::ostringstream o;
  o << "<div><h2>Against " << html_text(c.against) << ": the largest channel difference per pixel</h2>"
    << "<img class=\"frame\" id=\"error_map\" alt=\"error heat map\" src=\"data:image/png;base64,"
    << base64(png_rgb_bytes(map, true)) << "\"><p>"
    << (most ? "Dark: equal; blue 1 to red " + std::to_string(most) + " (the largest); " : std::string("Equal: "))
    << e.differing << " pixels differ.</p><div id=\"error_histogram\"></div></div>\n";
  return o.str();
}

}  // namespace

nlohmann::json report_page_data(const nlohmann::json& report, const RunStats& s) {
  nlohmann::json timeline = nlohmann::json::array();
  for (const StageStats& st : s.stages)
    timeline.push_back({{"name", st.name}, {"bin_s", st.series_bin_s}, {"bins", st.series},
                        {"fifo_in_bin_s", st.fifo_in_bin_s}, {"fifo_in", st.fifo_in_series}});
  nlohmann::json data = {{"report", report}, {"timeline", timeline}};
  if (s.maps)
    data["page_misses"] = {{"width", s.maps->width}, {"height", s.maps->height},
                           {"page_width_px", s.maps->page_width_px}, {"page_height_px", s.maps->page_height_px},
                           {"counts", s.maps->page_misses}};
  return data;
}

std::string report_html(nlohmann::json page_data, const RgbImage& frame, const std::string& frame_png,
                        const RunStats& s, const std::optional<FrameComparison>& compare,
                        const std::optional<ChartLibrary>& charts) {
  const std::string compared = compare ? compare_html(frame, *compare, page_data) : "";
  const nlohmann::json& r = page_data.at("report");
  std::ostringstream o;
  o << page_head("girtd render: " + r.value("input", std::string()) + " on " + r.value("backend", std::string()),
                 charts)
    << "<h1>girtd render</h1>\n<p id=\"verdict\"></p>\n"
    << "<div class=\"row\"><div><h2>Frame</h2><img class=\"frame\" alt=\"the frame\" src=\"data:image/png;base64,"
    << base64(frame_png) << "\"></div>\n" << heat_maps_html(s) << compared << "<div><h2>Run</h2><div id=\"run\"></div><div id=\"time\"></div>"
    << "<div id=\"pixels\"></div></div></div>\n"
    << "<h2>Timelines: each stage over modeled time, and the FIFO in front of it</h2>\n"
    << "<p>Drag to zoom (all charts follow), double-click to reset.</p><div id=\"timelines\"></div>\n"
    << "<h2>Warnings</h2><div id=\"warnings\"></div>\n<h2>Numerics</h2><div id=\"numerics\"></div>\n"
    << "<h2>Left out</h2><div id=\"left_out\"></div>\n<h2>Configuration</h2><pre id=\"config\"></pre>\n"
    << page_tail(page_data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), kPageScript);
  return o.str();
}

}  // namespace girtd
