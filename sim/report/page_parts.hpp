// What the self-contained pages (report.html, sweep.html) share: the chart
// library (uPlot from npm, installed into the build by tools/girtd and
// inlined; nothing is fetched when a page opens), escaping, the style, and
// the script prologue and epilogue that record on <body> what the browser
// tests read back (errors seen, ready).
#pragma once

#include <optional>
#include <string>

namespace girtd {

struct ChartLibrary {
  std::string script, style;
};
// nullopt when tools/girtd has not installed it: the page then has no charts.
std::optional<ChartLibrary> load_chart_library();
extern const char* const kNoChartLibrary;  // the warning a run gives then

std::string html_text(const std::string& s);    // <, > and & escaped
std::string script_safe(std::string text);      // inside <script>: no "</"
std::string base64(const std::string& bytes);

// <!DOCTYPE html> ... <body>: the title, the style, the chart library.
std::string page_head(const std::string& title, const std::optional<ChartLibrary>& charts);
// `data` (JSON text) as a script element, then `script` run with the error-recording
// prologue and epilogue (body data-errors, data-error-text, data-ready), and
// </body></html>.
std::string page_tail(const std::string& data_json, const char* script);

}  // namespace girtd
