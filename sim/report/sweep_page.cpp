#include "report/sweep_page.hpp"

namespace girtd {
namespace {

constexpr const char* kSweepScript = R"JS(
const el = (tag, text) => { const e = document.createElement(tag); if (text !== undefined) e.textContent = text; return e; };
const pts = data.points.filter(p => p.valid).sort((a, b) => a.cost - b.cost || b.min_mpixels_per_s - a.min_mpixels_per_s);
const settings = p => data.axes.map(a => a + ' = ' + JSON.stringify(p[a])).join('\n');
const box = document.getElementById('front_chart');
const table = document.getElementById('front_table');
const head = el('tr');
['point', ...data.axes, 'cost', 'Mpixel/s, slowest input', 'meets target'].forEach(h => head.appendChild(el('th', h)));
table.appendChild(head);
pts.filter(p => p.on_front).forEach(p => {
  const tr = el('tr');
  [p.point, ...data.axes.map(a => JSON.stringify(p[a])), p.cost, p.min_mpixels_per_s.toFixed(2), p.meets_target ? 'yes' : '']
      .forEach(c => tr.appendChild(el('td', String(c))));
  table.appendChild(tr);
});
if (typeof uPlot === 'undefined') box.appendChild(el('p', 'The chart library is not in this page (tools/girtd installs it).'));
else {
  const hover = document.getElementById('hover');
  const x = pts.map(p => p.cost), rate = pts.map(p => p.min_mpixels_per_s);
  const front = pts.map(p => p.on_front ? p.min_mpixels_per_s : null), target = pts.map(() => data.target);
  new uPlot({width: 900, height: 420, title: 'rate on the slowest input against cost', scales: {x: {time: false}},
             axes: [{label: 'cost (chips, models/cost)'}, {label: 'Mpixel/s'}],
             series: [{label: 'cost'},
                      {label: 'points', stroke: '#4575b4', paths: () => null, points: {show: true, size: 6}},
                      {label: 'Pareto front', stroke: '#d73027', width: 2, spanGaps: true, points: {show: true, size: 7}},
                      {label: data.target + ' Mpixel/s', stroke: '#1a9850', dash: [6, 4], points: {show: false}}],
             hooks: {setCursor: [u => { const i = u.cursor.idx; if (i !== null && i !== undefined && pts[i])
               hover.textContent = pts[i].point + ': ' + pts[i].min_mpixels_per_s.toFixed(2) + ' Mpixel/s, cost ' +
                                   pts[i].cost + '\n' + settings(pts[i]); }]}},
            [x, rate, front, target], box);
  box.dataset.points = pts.length;  // what the chart holds (the test reads it back)
  box.dataset.front = pts.filter(p => p.on_front).length;
}
)JS";

}  // namespace

std::string sweep_html(const std::string& spec, const std::string& headline, const nlohmann::json& points,
                       const std::vector<std::string>& axes, double target_mpixels_per_s,
                       const std::optional<ChartLibrary>& charts) {
  const nlohmann::json data = {{"points", points}, {"axes", axes}, {"target", target_mpixels_per_s}};
  return page_head("girtd sweep " + spec, charts) + "<h1>girtd sweep " + html_text(spec) + "</h1>\n<pre>" +
         html_text(headline) + "</pre>\n<div id=\"front_chart\"></div>\n<p>Hover a point to read it:</p>" +
         "<pre id=\"hover\"></pre>\n<h2>The Pareto front</h2><table id=\"front_table\"></table>\n" +
         page_tail(data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), kSweepScript);
}

}  // namespace girtd
