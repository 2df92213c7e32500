#include "report/accuracy_page.hpp"

namespace girtd {
namespace {

// Exact levels (rtl, approx: error 0) sit on the floor of the log axis.
constexpr const char* kAccuracyScript = R"JS(
const el = (tag, text) => { const e = document.createElement(tag); if (text !== undefined) e.textContent = text; return e; };
const floor = 1e-4;  // % : where an exact estimate is drawn on the log axis
const rows = data.rows.filter(r => r.time_error !== null && r.time_error !== undefined && r.wall_s > 0)
                      .sort((a, b) => a.wall_s - b.wall_s);
const levels = [...new Set(rows.map(r => r.level))];
const table = document.getElementById('levels');
const head = el('tr');
['level', 'rows', 'mean wall s', 'mean |error| %', 'max |error| %', 'under 1 %', 'on the Pareto front'].forEach(h => head.appendChild(el('th', h)));
table.appendChild(head);
data.levels.forEach(l => {
  const tr = el('tr');
  [l.level, l.rows, l.wall_s_mean?.toFixed(3), l.time_error_mean_abs === null ? '—' : (100 * l.time_error_mean_abs).toFixed(3),
   l.time_error_max_abs === null ? '—' : (100 * l.time_error_max_abs).toFixed(3), l.under_1pct, l.on_front ? 'yes' : '']
      .forEach(c => tr.appendChild(el('td', c === undefined || c === null ? '—' : String(c))));
  table.appendChild(tr);
});
const box = document.getElementById('error_chart');
if (typeof uPlot === 'undefined') box.appendChild(el('p', 'The chart library is not in this page (tools/girtd installs it).'));
else {
  const colours = ['#1b7837', '#2166ac', '#b2182b', '#762a83', '#e08214', '#35978f', '#8c510a'];
  const hover = document.getElementById('hover');
  const x = rows.map(r => r.wall_s);
  const series = levels.map(l => rows.map(r => r.level === l ? Math.max(floor, 100 * Math.abs(r.time_error)) : null));
  new uPlot({width: 900, height: 420, title: "modeled-time error against rtl, and what it cost",
             scales: {x: {time: false, distr: 3}, y: {distr: 3}},
             axes: [{label: 'wall s per run'}, {label: '|error| % (exact: ' + floor + ')'}],
             series: [{label: 'wall s'}, ...levels.map((l, i) => ({label: l, stroke: colours[i % colours.length],
                                                                     paths: () => null, points: {show: true, size: 7}}))],
             hooks: {setCursor: [u => { const i = u.cursor.idx; if (i !== null && i !== undefined && rows[i]) {
               const r = rows[i]; hover.textContent = r.level + ' on ' + r.input + ' (' + r.variant + '): ' +
                   (100 * r.time_error).toFixed(4) + ' % in ' + r.wall_s.toFixed(3) + ' s'; } }]}},
            [x, ...series], box);
  box.dataset.rows = rows.length;  // what the chart holds (the test reads it back)
  box.dataset.levels = levels.length;
}
)JS";

}  // namespace

std::string accuracy_html(const std::string& command, const nlohmann::json& rows, const nlohmann::json& levels,
                          const std::optional<ChartLibrary>& charts) {
  const nlohmann::json data = {{"rows", rows}, {"levels", levels}};
  return page_head("girtd accuracy", charts) + "<h1>girtd accuracy</h1>\n<pre>" + html_text(command) +
         "</pre>\n<div id=\"error_chart\"></div>\n<p>Hover a point to read it:</p><pre id=\"hover\"></pre>\n"
         "<h2>Per level, over the inputs</h2><table id=\"levels\"></table>\n" +
         page_tail(data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), kAccuracyScript);
}

}  // namespace girtd
