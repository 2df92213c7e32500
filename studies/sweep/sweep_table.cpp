#include "sweep/sweep_table.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "io/csv_field.hpp"
#include "io/text_format.hpp"

namespace girtd {

using json = nlohmann::json;

namespace {

std::string text(const json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

}  // namespace

double judged_rate(const json& row) {
  const json& s = row.value("sustained_mpixels_per_s", json());
  return s.is_null() ? row.value("modeled_mpixels_per_s", 0.0) : s.get<double>();
}

void mark_pareto_front(json& points) {
  for (json& p : points) {
    bool dominated = !p["valid"].get<bool>();
    for (const json& q : points)
      if (!dominated && q["valid"].get<bool>() && q["point"] != p["point"]) {
        const double qc = q["cost"], pc = p["cost"], qr = q["min_mpixels_per_s"], pr = p["min_mpixels_per_s"];
        dominated = qc <= pc && qr >= pr && (qc < pc || qr > pr);
      }
    p["on_front"] = !dominated;
  }
}

SweepSummary summarize_sweep(const json& rows, const std::vector<std::string>& axes, size_t inputs) {
  std::map<std::string, json> by_point;
  std::vector<std::string> order;
  for (const json& r : rows) {
    const std::string id = r["point"];
    if (!by_point.count(id)) {
      order.push_back(id);
      json p = {{"point", id}, {"valid", true}, {"rows", 0}, {"min_mpixels_per_s", nullptr}, {"meets_target", true},
                {"cost", r.value("cost", json())}, {"bottlenecks", json::array()}, {"rtl_agrees", nullptr}};
      for (const std::string& a : axes) p[a] = r.value(a, json());
      if (r.contains("invalid")) p["invalid"] = r["invalid"];
      by_point[id] = p;
    }
    json& p = by_point[id];
    p["rows"] = p["rows"].get<int>() + 1;
    if (!r["valid"].get<bool>()) {
      p["valid"] = false;
      if (r.contains("invalid")) p["invalid"] = r["invalid"];
      continue;
    }
    const double rate = judged_rate(r);
    if (p["min_mpixels_per_s"].is_null() || rate < p["min_mpixels_per_s"].get<double>()) p["min_mpixels_per_s"] = rate;
    p["meets_target"] = p["meets_target"].get<bool>() && r["target_met"] == true;
    if (!r["bottleneck"].is_null()) p["bottlenecks"].push_back(r["bottleneck"]);
    if (!r["rtl_agrees"].is_null()) p["rtl_agrees"] = p["rtl_agrees"] == false ? json(false) : r["rtl_agrees"];
  }
  std::vector<json> valid;
  for (const std::string& id : order) {
    json& p = by_point[id];
    if (!p["valid"].get<bool>() || p["rows"].get<size_t>() < inputs) {
      p["valid"] = false;
      p["meets_target"] = false;
    } else {
      valid.push_back(p);
    }
  }
  SweepSummary s;
  s.points = json::array();
  for (const std::string& id : order) s.points.push_back(by_point[id]);
  mark_pareto_front(s.points);
  std::vector<json> front, meeting;
  for (const json& p : s.points) {
    if (p["on_front"].get<bool>()) front.push_back(p);
    if (p["meets_target"].get<bool>()) meeting.push_back(p);
  }
  // Cheapest first; at equal cost the faster, then the point's name: the
  // same order on every run.
  auto by_cost = [](const json& a, const json& b) {
    const double ca = a["cost"], cb = b["cost"], ra = a["min_mpixels_per_s"], rb = b["min_mpixels_per_s"];
    if (ca != cb) return ca < cb;
    if (ra != rb) return ra > rb;
    return a["point"].get<std::string>() < b["point"].get<std::string>();
  };
  std::sort(front.begin(), front.end(), by_cost);
  std::sort(meeting.begin(), meeting.end(), by_cost);
  const size_t invalid = s.points.size() - valid.size();

  std::ostringstream md, head;
  md << s.points.size() << " points (" << invalid << " invalid) x " << inputs << " input(s) = " << rows.size()
     << " rows. A point's rate is its slowest input's (sustained where the input ran as several frames); cost is "
        "`models/cost/hardware_cost.hpp`'s chip estimate.\n\n";
  auto point_line = [&](const json& p) {
    std::string line = "| `" + p["point"].get<std::string>() + "` | ";
    for (const std::string& a : axes) line += text(p[a]) + " | ";
    std::string b;
    for (const json& x : p["bottlenecks"]) b += (b.empty() ? "" : ", ") + x.get<std::string>();
    line += format_numbers("%.0f", p["cost"].get<double>()) + " | " + format_numbers("%.2f", p["min_mpixels_per_s"].get<double>()) + " | " +
            (p["meets_target"].get<bool>() ? "yes" : "") + " | " + b + " | " +
            (p["rtl_agrees"].is_null() ? "" : p["rtl_agrees"].get<bool>() ? "agrees" : "**DISAGREES**") + " |\n";
    return line;
  };
  std::string header = "| point | ";
  for (const std::string& a : axes) header += "`" + a + "` | ";
  header += "cost | Mpixel/s (worst input) | meets target | bottleneck per input | rtl |\n|---|";
  for (size_t i = 0; i < axes.size() + 5; ++i) header += "---|";
  header += "\n";
  if (!meeting.empty()) md << "## Cheapest point meeting the target on every input\n\n" << header << point_line(meeting.front()) << "\n";
  else md << "## No point meets the target on every input\n\n";
  md << "## Pareto front: rate against cost\n\n" << header;
  for (const json& p : front) md << point_line(p);
  md << "\n## Every valid point\n\n" << header;
  for (const json& p : s.points)
    if (p["valid"].get<bool>()) md << point_line(p);
  if (invalid) {
    md << "\n## Invalid points\n\n| point | why |\n|---|---|\n";
    for (const json& p : s.points)
      if (!p["valid"].get<bool>()) md << "| `" << p["point"].get<std::string>() << "` | " << text(p.value("invalid", json("incomplete"))) << " |\n";
  }
  s.markdown = md.str();
  head << valid.size() << " valid point(s), " << invalid << " invalid; " << front.size() << " on the front; ";
  if (meeting.empty()) head << "none meets the target on every input\n";
  else head << meeting.size() << " meet the target, the cheapest " << meeting.front()["point"].get<std::string>()
            << " (cost " << format_numbers("%.0f", meeting.front()["cost"].get<double>()) << ")\n";
  s.headline = head.str();
  return s;
}

std::string sweep_csv(const json& rows, const std::vector<std::string>& axes) {
  std::vector<std::string> columns = {"point", "input", "valid"};
  for (const ReportColumn& c : kReportColumns) columns.push_back(c.name);
  for (const char* c : {"cost", "cost_dda_chips", "cost_fifo_chips", "cost_had_chips", "cost_vram_chips",
                        "cost_board_chips", "cost_yosys_dda_cells", "rtl_agrees", "invalid"})
    columns.push_back(c);
  std::ostringstream o;
  for (const std::string& a : axes) o << csv_field(json(a)) << ",";
  for (size_t i = 0; i < columns.size(); ++i) o << columns[i] << (i + 1 < columns.size() ? "," : "\n");
  for (const json& r : rows) {
    for (const std::string& a : axes) o << csv_field(r.value(a, json())) << ",";
    for (size_t i = 0; i < columns.size(); ++i)
      o << csv_field(r.value(columns[i], json())) << (i + 1 < columns.size() ? "," : "\n");
  }
  return o.str();
}

}  // namespace girtd
