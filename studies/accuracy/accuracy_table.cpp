#include "accuracy/accuracy_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "io/csv_field.hpp"

namespace girtd {

using json = nlohmann::json;

namespace {

std::string num(const json& v, const char* fmt = "%.4g") {
  if (v.is_null()) return "—";
  if (v.is_string()) return v.get<std::string>();
  char b[64];
  std::snprintf(b, sizeof b, fmt, v.get<double>());
  return b;
}

std::string pct(const json& v) {
  if (v.is_null()) return "—";
  char b[64];
  std::snprintf(b, sizeof b, "%+.3f %%", 100 * v.get<double>());
  return b;
}

}  // namespace

json picture_error_cell(const ImageError& image, const DepthError& depth) {
  return {{"max_abs", image.max_abs},
          {"mean_abs", image.mean_abs},
          {"rmse", image.rmse},
          {"psnr_db", image.psnr_db ? json(*image.psnr_db) : json()},
          {"coverage_diff", depth.coverage_diff},
          {"z_max_abs", depth.z_max_abs}};
}

json level_summary(const json& rows) {
  std::map<std::string, std::vector<const json*>> by_level;
  std::vector<std::string> order;
  for (const json& r : rows) {
    if (r.value("time_error", json()).is_null()) continue;  // invalid rows have none
    const std::string level = r["level"];
    if (!by_level.count(level)) order.push_back(level);
    by_level[level].push_back(&r);
  }
  json out = json::array();
  for (const std::string& level : order) {
    const auto& rs = by_level[level];
    double wall = 0, sum = 0, worst = 0, sq = 0;
    int under1 = 0, under10 = 0;
    for (const json* r : rs) {
      const double e = std::abs((*r)["time_error"].get<double>());
      wall += (*r)["wall_s"].get<double>();
      sum += e, sq += e * e, worst = std::max(worst, e);
      under1 += e < 0.01, under10 += e < 0.10;
    }
    const double n = double(rs.size());
    out.push_back({{"level", level}, {"rows", rs.size()}, {"wall_s_mean", wall / n}, {"time_error_mean_abs", sum / n},
                   {"time_error_max_abs", worst}, {"time_error_rms", std::sqrt(sq / n)}, {"under_1pct", under1},
                   {"under_10pct", under10}});
  }
  // On the front: no other level is at once no slower and no less accurate
  // (by the maximum error), and better in one.
  for (json& a : out) {
    bool dominated = false;
    for (const json& b : out)
      dominated = dominated || (&a != &b && b["wall_s_mean"] <= a["wall_s_mean"] &&
                                b["time_error_max_abs"] <= a["time_error_max_abs"] &&
                                (b["wall_s_mean"] < a["wall_s_mean"] || b["time_error_max_abs"] < a["time_error_max_abs"]));
    a["on_front"] = !dominated;
  }
  return out;
}

json counter_summary(const json& rows) {
  std::map<std::string, std::map<std::string, std::pair<double, double>>> acc;  // level -> counter -> (sum, max)
  std::map<std::string, int> n;
  std::vector<std::string> order;
  for (const json& r : rows) {
    if (!r.contains("counter_error") || r["counter_error"].is_null()) continue;
    const std::string level = r["level"];
    if (!n.count(level)) order.push_back(level);
    ++n[level];
    for (const auto& [k, v] : r["counter_error"].items()) {
      if (v.is_null()) continue;
      auto& [sum, worst] = acc[level][k];
      sum += std::abs(v.get<double>());
      worst = std::max(worst, std::abs(v.get<double>()));
    }
  }
  json out = json::array();
  for (const std::string& level : order)
    for (const auto& [k, sm] : acc[level])
      out.push_back({{"level", level}, {"counter", k}, {"mean_abs", sm.first / n[level]}, {"max_abs", sm.second}});
  return out;
}

json rtl_agreement(const json& rows, const std::string& yardstick, const std::string& exact) {
  std::map<std::pair<std::string, std::string>, std::string> rtl_sha;
  for (const json& r : rows)
    if (r["level"] == yardstick && r.contains("image_sha256")) rtl_sha[{r["input"], r["variant"]}] = r["image_sha256"];
  json out = json::array();
  for (const auto& [key, sha] : rtl_sha) {
    json levels = json::array();
    bool agrees = true;
    for (const json& r : rows)
      if (r["input"] == key.first && r["variant"] == key.second && r["level"] != yardstick && r["level"] != exact &&
          r.value("complete", false) && r.contains("image_sha256")) {
        levels.push_back(r["level"]);
        agrees = agrees && r["image_sha256"] == sha;
      }
    // nothing to compare with: no verdict
    out.push_back({{"input", key.first}, {"variant", key.second}, {"compared", levels},
                   {"agrees", levels.empty() ? json() : json(agrees)}});
  }
  return out;
}

std::string accuracy_markdown(const json& rows, const json& levels, const json& counters, const json& agreement) {
  std::ostringstream o;
  if (!agreement.empty()) {
    o << "## The same picture on rtl (image SHA-256)\n\n| input | variant | against | agrees |\n|---|---|---|---|\n";
    for (const json& a : agreement) {
      std::string against;
      for (const json& l : a["compared"]) against += (against.empty() ? "" : ", ") + l.get<std::string>();
      o << "| " << a["input"].get<std::string>() << " | " << a["variant"].get<std::string>() << " | " << against
        << " | " << (a["agrees"].is_null() ? "—" : a["agrees"].get<bool>() ? "yes" : "**NO**") << " |\n";
    }
    o << "\n";
  }
  o << "## Timing estimate: modeled time against rtl\n\n"
       "| level | rows | mean wall s | mean abs error | max abs error | rms | under 1 % | under 10 % | on the front |\n"
       "|---|---|---|---|---|---|---|---|---|\n";
  for (const json& l : levels)
    o << "| " << l["level"].get<std::string>() << " | " << l["rows"] << " | " << num(l["wall_s_mean"]) << " | "
      << num(json(100 * l["time_error_mean_abs"].get<double>()), "%.3f %%") << " | "
      << num(json(100 * l["time_error_max_abs"].get<double>()), "%.3f %%") << " | "
      << num(json(100 * l["time_error_rms"].get<double>()), "%.3f %%") << " | " << l["under_1pct"] << " | "
      << l["under_10pct"] << " | " << (l["on_front"].get<bool>() ? "yes" : "") << " |\n";
  o << "\n## Counters against rtl (relative difference)\n\n| level | counter | mean abs | max abs |\n|---|---|---|---|\n";
  for (const json& c : counters)
    o << "| " << c["level"].get<std::string>() << " | " << c["counter"].get<std::string>() << " | "
      << num(json(100 * c["mean_abs"].get<double>()), "%.4f %%") << " | "
      << num(json(100 * c["max_abs"].get<double>()), "%.4f %%") << " |\n";
  o << "\n## Every row\n\nPicture error is against the reference back end (0..255 per channel; coverage in pixels); "
       "llvmpipe only for opaque, Q = 0 triangle-level inputs.\n\n"
       "| input | level | variant | wall s | sim Mpixel/s | modeled s | time error | max abs | mean abs | PSNR dB | "
       "coverage diff | llvmpipe max abs | llvmpipe coverage diff |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const json& r : rows) {
    if (r.contains("invalid")) {
      o << "| " << r["input"].get<std::string>() << " | " << r["level"].get<std::string>() << " | "
        << r["variant"].get<std::string>() << " | invalid: " << r["invalid"].get<std::string>() << " |||||||||| \n";
      continue;
    }
    const json& im = r["image"];
    const json& lp = r["llvmpipe"];
    o << "| " << r["input"].get<std::string>() << " | " << r["level"].get<std::string>() << " | "
      << r["variant"].get<std::string>() << " | " << num(r["wall_s"]) << " | "
      << num(r["sim_pixels_per_s"].is_null() ? json() : json(r["sim_pixels_per_s"].get<double>() / 1e6)) << " | "
      << num(r["modeled_time_s"]) << " | " << pct(r["time_error"]) << " | "
      << (im.is_null() ? "—" : num(im["max_abs"], "%g")) << " | " << (im.is_null() ? "—" : num(im["mean_abs"])) << " | "
      << (im.is_null() ? "—" : num(im["psnr_db"], "%.2f")) << " | " << (im.is_null() ? "—" : num(im["coverage_diff"], "%g"))
      << " | " << (lp.is_null() ? "—" : num(lp["max_abs"], "%g")) << " | "
      << (lp.is_null() ? "—" : num(lp["coverage_diff"], "%g")) << " |\n";
  }
  return o.str();
}

std::string variants_markdown(const json& variants) {
  std::ostringstream o;
  o << "## Variants: what the formats cost and how far the EPs drift\n\n"
       "EP error after N steps in one direction (claims/ep_precision.hpp; budget: 1 LSB, 0.125 px for D, plus half a "
       "fraction LSB for the start value).\n\n"
       "| variant | colour 1,024 / 2,048 LSB | T | Z | D px | register bits | adder bits |\n|---|---|---|---|---|---|---|\n";
  for (const json& v : variants) {
    if (v.contains("invalid")) {
      o << "| " << v["variant"].get<std::string>() << " | invalid ||||||\n";
      continue;
    }
    o << "| " << v["variant"].get<std::string>() << " | ";
    for (const char* ep : {"color", "t", "z", "d"}) {
      const json& e = v["ep_error"][ep];
      const bool over = e["after_1024"].get<double>() > e["bound_1024"].get<double>();
      o << (over ? "**" : "") << num(e["after_1024"], "%.3f") << (over ? "**" : "") << " / "
        << num(e["after_2048"], "%.3f") << " (" << e["frac_bits"] << " bits) | ";
    }
    o << v["register_bits"] << " | " << v["adder_bits"] << " |\n";
  }
  return o.str();
}

std::string accuracy_csv(const json& rows) {
  static const char* kColumns[] = {"input", "level", "variant", "wall_s", "sim_pixels_per_s", "dda_clocks_per_s",
                                   "modeled_time_s", "time_error", "time_ci_half_s"};
  static const char* kPicture[] = {"max_abs", "mean_abs", "rmse", "psnr_db", "coverage_diff", "z_max_abs"};
  std::ostringstream o;
  for (const char* c : kColumns) o << c << ",";
  for (const char* cell : {"image", "llvmpipe"})
    for (const char* k : kPicture) o << cell << "." << k << ",";
  o << "invalid\n";
  for (const json& r : rows) {
    for (const char* c : kColumns) o << csv_field(r.value(c, json())) << ",";
    for (const char* cell : {"image", "llvmpipe"})
      for (const char* k : kPicture) o << (r.value(cell, json()).is_null() ? "" : csv_field(r[cell][k])) << ",";
    o << csv_field(r.value("invalid", json())) << "\n";
  }
  return o.str();
}

}  // namespace girtd
