#include "io/sweep_spec.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "common/file_text.hpp"
#include "common/input_error.hpp"
#include "common/json_text.hpp"
#include "config/params.hpp"

namespace girtd {
namespace fs = std::filesystem;
using json = nlohmann::json;

nlohmann::json SweepAxis::settings(size_t i) const {
  return values.at(i).is_object() ? values[i] : json{{name, values[i]}};
}

size_t SweepSpec::point_count() const {
  size_t n = 1;
  for (const SweepAxis& a : axes) n *= a.values.size();
  return n;
}

namespace {

// An axis key must be a configuration key (config/README.md) and its value
// of the key's kind: config/girtd.json's number, true/false or text; a key
// that is null there takes a number or null.
template <class Fail>
void check_config_key(const std::string& key, const json& value, Fail fail) {
  static const json defaults = Params::defaults().source;
  const json* node = &defaults;
  size_t at = 0;
  for (;;) {
    const size_t dot = key.find('.', at);
    const std::string part = key.substr(at, dot == std::string::npos ? std::string::npos : dot - at);
    if (part.empty() || !node->is_object() || !node->contains(part))
      throw fail("'" + key + "' is not a configuration key (config/README.md)");
    node = &(*node)[part];
    if (dot == std::string::npos) break;
    at = dot + 1;
  }
  const bool ok = node->is_object()    ? false
                  : node->is_boolean() ? value.is_boolean()
                  : node->is_number()  ? value.is_number()
                  : node->is_string()  ? value.is_string()
                                       : value.is_null() || value.is_number();
  if (!ok) throw fail("'" + key + "': " + value.dump() + " is not a value of this key's kind (config/README.md)");
}

}  // namespace

SweepSpec parse_sweep_spec(const std::string& text, const std::string& path,
                           const std::vector<std::string>& timed_backends) {
  const json j = parse_json_text(text, path);
  const std::map<std::string, int> lines = json_key_lines(text);
  auto line = [&](const std::string& key) {
    const auto it = lines.find(key);
    return it == lines.end() ? 1 : it->second;
  };
  auto fail = [&](const std::string& key, const std::string& what) -> InputError {
    return InputError(path, line(key), (key.empty() ? "" : key + ": ") + what);
  };
  if (!j.is_object()) throw fail("", "a sweep spec is a JSON object");
  static const std::set<std::string> known = {"inputs", "backend", "base", "repeat", "spot_check", "axes"};
  for (const auto& [k, v] : j.items())
    if (!known.count(k)) throw fail(k, "unknown key (inputs, backend, base, repeat, spot_check, axes)");
  SweepSpec s;
  s.path = path;
  // The axes first: what a spec is about, and what a fuzzer should reach.
  if (!j.contains("axes") || !j["axes"].is_object() || j["axes"].empty())
    throw fail(j.contains("axes") ? "axes" : "", "\"axes\" must be a non-empty object of axis: [values]");
  std::set<std::string> reserved = {"point", "input", "valid", "invalid", "cost", "rtl_agrees"};
  for (const ReportColumn& c : kReportColumns) reserved.insert(c.name);
  std::map<std::string, std::string> key_axis;  // every key an axis sets, and which axis
  size_t points = 1;
  for (const auto& [name, values] : j["axes"].items()) {
    const std::string key = "axes." + name;
    if (reserved.count(name) || name.rfind("cost_", 0) == 0) throw fail(key, "a result column's name: call the axis otherwise");
    if (!values.is_array() || values.empty()) throw fail(key, "an axis is a non-empty list of values");
    SweepAxis a{name, {}};
    const bool objects = values.front().is_object();
    std::set<std::string> seen;
    for (const json& v : values) {
      if (v.is_object() != objects) throw fail(key, "values are all objects (several keys) or all plain values");
      if (v.is_array()) throw fail(key, "a value is a number, text, true/false, null or an object of keys");
      if (objects && v.empty()) throw fail(key, "an object value sets at least one key");
      if (!seen.insert(v.dump()).second) throw fail(key, "the value " + v.dump() + " twice");
      const json settings = objects ? v : json{{name, v}};
      for (const auto& [k, x] : settings.items()) {
        check_config_key(k, x, [&](const std::string& what) { return fail(key, what); });
        const auto [it, fresh] = key_axis.emplace(k, name);
        if (!fresh && it->second != name) throw fail(key, "'" + k + "' is set by axis '" + it->second + "' too");
      }
      a.values.push_back(v);
    }
    if ((points *= a.values.size()) > 1000000) throw fail("axes", "more than 1,000,000 points");
    s.axes.push_back(a);
  }
  const fs::path dir = fs::path(path).parent_path();
  auto files = [&](const char* key, bool required) {
    std::vector<std::string> out;
    if (!j.contains(key)) {
      if (required) throw fail("", std::string("no \"") + key + "\"");
      return out;
    }
    if (!j[key].is_array() || (required && j[key].empty())) throw fail(key, "must be a non-empty list of paths");
    for (const json& f : j[key]) {
      if (!f.is_string()) throw fail(key, "must be a list of paths (strings)");
      const std::string resolved = (dir / f.get<std::string>()).lexically_normal().string();
      if (!fs::is_regular_file(resolved)) throw fail(key, "'" + f.get<std::string>() + "': no such file (paths are relative to the spec's folder)");
      if (std::count(out.begin(), out.end(), resolved)) throw fail(key, "'" + f.get<std::string>() + "' twice");
      out.push_back(resolved);
    }
    return out;
  };
  s.inputs = files("inputs", true);
  s.base = files("base", false);
  if (j.contains("backend")) {
    if (!j["backend"].is_string() ||
        std::find(timed_backends.begin(), timed_backends.end(), j["backend"].get<std::string>()) == timed_backends.end()) {
      std::string choices;
      for (const std::string& b : timed_backends) choices += (choices.empty() ? "\"" : " or \"") + b + "\"";
      throw fail("backend", "must be " + choices + " (a sweep judges modeled time)");
    }
    s.backend = j["backend"];
  }
  auto count = [&](const char* key, int lo, int hi) {
    if (!j.contains(key)) return -1;
    if (!j[key].is_number_integer() || j[key].get<int64_t>() < lo || j[key].get<int64_t>() > hi)
      throw fail(key, "must be a whole number " + std::to_string(lo) + ".." + std::to_string(hi));
    return j[key].get<int>();
  };
  if (int r = count("repeat", 1, 1000); r > 0) s.repeat = r;
  if (int k = count("spot_check", 0, 100000); k >= 0) s.spot_check = k;
  return s;
}

SweepSpec read_sweep_spec(const std::string& path, const std::vector<std::string>& timed_backends) {
  const std::optional<std::string> text = read_file_text(path);
  if (!text) throw InputError(path, 0, "cannot read the file");
  return parse_sweep_spec(*text, path, timed_backends);
}

}  // namespace girtd
