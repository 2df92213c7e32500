#include "report/page_parts.hpp"

#include <openssl/evp.h>

#include <fstream>
#include <sstream>

namespace girtd {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::ostringstream o;
  o << in.rdbuf();
  return o.str();
}

constexpr const char* kPageStyle = R"CSS(
body { font-family: sans-serif; margin: 1em 2em; color: #222; }
h1 { font-size: 1.4em; } h2 { font-size: 1.15em; margin-top: 1.5em; } h3 { font-size: 1em; margin: 0.5em 0 0; }
table { border-collapse: collapse; margin: 0.5em 0; } td, th { border: 1px solid #ccc; padding: 2px 8px; text-align: left; }
.pass { color: #1b7837; font-weight: bold; } .fail { color: #b2182b; font-weight: bold; }
.warning { color: #8c510a; } .frame { width: 512px; image-rendering: pixelated; border: 1px solid #888; }
.row { display: flex; gap: 2em; flex-wrap: wrap; } pre { background: #f6f6f6; padding: 0.5em; max-height: 20em; overflow: auto; }
)CSS";

// Every page's script runs between these: errors are recorded on <body>.
constexpr const char* kPrologue = R"JS(
const errors = [];
window.addEventListener('error', e => errors.push(String(e.message)));
const consoleError = console.error;
console.error = (...a) => { errors.push(a.map(String).join(' ')); consoleError(...a); };
const data = JSON.parse(document.getElementById('girtd-data').textContent);
try {
)JS";
constexpr const char* kEpilogue = R"JS(
} catch (e) { errors.push(String(e)); }
document.body.dataset.errors = errors.length;
document.body.dataset.errorText = errors.join(' | ');
document.body.dataset.ready = '1';
)JS";

}  // namespace

const char* const kNoChartLibrary =
    "the page has no charts: the chart library is not installed (tools/girtd installs it)";

std::optional<ChartLibrary> load_chart_library() {
  const std::string dist = std::string(GIRTD_WEB_DIR) + "/node_modules/uplot/dist/";
  ChartLibrary lib{read_file(dist + "uPlot.iife.min.js"), read_file(dist + "uPlot.min.css")};
  if (lib.script.empty() || lib.style.empty()) return std::nullopt;
  return lib;
}

std::string html_text(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

std::string base64(const std::string& bytes) {
  std::string out(4 * ((bytes.size() + 2) / 3) + 1, '\0');
  const int n = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data()),
                                reinterpret_cast<const unsigned char*>(bytes.data()), int(bytes.size()));
  out.resize(size_t(n));
  return out;
}

// Inside <script>: a "</" would end the element.
std::string script_safe(std::string text) {
  for (size_t at = 0; (at = text.find("</", at)) != std::string::npos; at += 3) text.replace(at, 2, "<\\/");
  return text;
}

std::string page_head(const std::string& title, const std::optional<ChartLibrary>& charts) {
  std::string o = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" + html_text(title) +
                  "</title>\n<style>" + kPageStyle + (charts ? charts->style : "") + "</style>\n";
  if (charts) o += "<script>" + script_safe(charts->script) + "</script>\n";
  return o + "</head><body>\n";
}

std::string page_tail(const std::string& data_json, const char* script) {
  // JSON has '<' only inside strings, where \u003c reads the same: nothing
  // in the data can then open or close an element.
  std::string safe;
  safe.reserve(data_json.size());
  for (size_t from = 0;;) {
    const size_t lt = data_json.find('<', from);
    safe.append(data_json, from, lt == std::string::npos ? std::string::npos : lt - from);
    if (lt == std::string::npos) break;
    safe += "\\u003c";
    from = lt + 1;
  }
  return "<script id=\"girtd-data\" type=\"application/json\">" + safe + "</script>\n<script>" +
         kPrologue + script + kEpilogue + "</script>\n</body></html>\n";
}

}  // namespace girtd
