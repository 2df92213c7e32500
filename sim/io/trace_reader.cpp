#include "io/trace_reader.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"
#include "io/trace_writer.hpp"

namespace girtd {

const char* level_name(TraceLevel level) { return level == TraceLevel::kTriangle ? "triangle" : "dda"; }

TraceLevel parse_level(const std::string& name, const std::string& origin, int line) {
  if (name == "triangle") return TraceLevel::kTriangle;
  if (name == "dda") return TraceLevel::kDda;
  throw InputError(origin, line, "unknown trace level '" + name + "' (known: triangle, dda)");
}

size_t Trace::primitive_count() const {
  size_t n = 0;
  for (const TraceFrame& f : frames) n += f.primitive_count();
  return n;
}

namespace {

class LineParser {
 public:
  LineParser(const std::string& file, int line, std::vector<std::string> fields)
      : file_(file), line_(line), f_(std::move(fields)) {}

  const std::string& keyword() const { return f_[0]; }
  void expect_count(size_t n, const char* what) const {
    if (f_.size() - 1 != n)
      fail("'" + keyword() + "' takes " + std::to_string(n) + " " + what + ", got " +
           std::to_string(f_.size() - 1));
  }
  double real(size_t i, const char* name) const {
    const std::string& s = f_[i];
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    const bool hex = s.find_first_of("xX") != std::string::npos;  // strtod reads hex floats; the format is decimal
    if (end == s.c_str() || *end != '\0' || hex) fail(std::string(name) + ": '" + s + "' is not a number");
    // ERANGE on underflow is fine (a subnormal is finite); on overflow it is not.
    if (!std::isfinite(v) || (errno == ERANGE && std::fabs(v) == HUGE_VAL))
      fail(std::string(name) + ": '" + s + "' is not finite");
    return v;
  }
  double real_in(size_t i, const char* name, double lo, double hi) const {
    const double v = real(i, name);
    if (v < lo || v > hi) fail(std::string(name) + " = " + f_[i] + " is outside " + num(lo) + ".." + num(hi));
    return v;
  }
  int64_t integer(size_t i, const char* name) const {
    const std::string& s = f_[i];
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (end == s.c_str() || *end != '\0') fail(std::string(name) + ": '" + s + "' is not an integer");
    if (errno == ERANGE) fail(std::string(name) + ": '" + s + "' is out of range");
    return v;
  }
  int64_t integer_in(size_t i, const char* name, int64_t lo, int64_t hi) const {
    const int64_t v = integer(i, name);
    if (v < lo || v > hi)
      fail(std::string(name) + " = " + f_[i] + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    return v;
  }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, line_, what); }
  int line() const { return line_; }
  size_t size() const { return f_.size(); }
  const std::string& field(size_t i) const { return f_[i]; }

 private:
  static std::string num(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
  }
  std::string file_;
  int line_;
  std::vector<std::string> f_;
};

std::vector<std::string> split_fields(const std::string& raw) {
  std::string s = raw.substr(0, raw.find('#'));
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string tok; in >> tok;) out.push_back(tok);
  return out;
}

class TraceBuilder {
 public:
  TraceBuilder(const std::string& path, const Params& params) : params_(params) {
    trace_.path = path;
    trace_.frames.emplace_back();
  }

  void record(const LineParser& p) {
    const std::string& k = p.keyword();
    if (k == "girtd-trace") p.fail("header must be the first record");
    if (k == "frame") return new_frame(p);
    if (k == "window" || k == "background" || k == "q") return setting(p);
    if (k == "tri") return triangle(p);
    if (k == "format") return format(p);
    if (k == "dda") return dda(p);
    p.fail("unknown record '" + k + "'");
  }

  Trace finish(TraceLevel level) {
    trace_.level = level;
    // A trailing `frame` opens a frame that never gets a primitive: not kept.
    if (trace_.frames.size() > 1 && trace_.frames.back().primitive_count() == 0) trace_.frames.pop_back();
    return std::move(trace_);
  }

  void set_level(TraceLevel level) { level_ = level; }

 private:
  TraceFrame& current() { return trace_.frames.back(); }

  void new_frame(const LineParser& p) {
    p.expect_count(0, "fields");
    if (current().primitive_count() == 0) return;  // frames without primitives are not kept
    FrameSettings carried = current().settings;
    trace_.frames.emplace_back();
    current().settings = carried;
  }

  void setting(const LineParser& p) {
    if (current().primitive_count() > 0)
      p.fail("'" + p.keyword() + "' must come before the first primitive of a frame");
    FrameSettings& s = current().settings;
    if (p.keyword() == "window") {
      p.expect_count(4, "integers (X0 Y0 X1 Y1)");
      const int max = params_.screen_width - 1;
      s.window.x0 = static_cast<int>(p.integer_in(1, "X0", 0, max));
      s.window.y0 = static_cast<int>(p.integer_in(2, "Y0", 0, params_.screen_height - 1));
      s.window.x1 = static_cast<int>(p.integer_in(3, "X1", 0, max));
      s.window.y1 = static_cast<int>(p.integer_in(4, "Y1", 0, params_.screen_height - 1));
      if (s.window.x0 > s.window.x1 || s.window.y0 > s.window.y1) p.fail("window is empty (X0 > X1 or Y0 > Y1)");
    } else if (p.keyword() == "background") {
      p.expect_count(3, "integers (R G B)");
      s.background.r = static_cast<uint8_t>(p.integer_in(1, "R", 0, 255));
      s.background.g = static_cast<uint8_t>(p.integer_in(2, "G", 0, 255));
      s.background.b = static_cast<uint8_t>(p.integer_in(3, "B", 0, 255));
    } else {
      p.expect_count(1, "number (Q)");
      s.q = p.real_in(1, "Q", 0, 64);
      s.q_line = p.line();
    }
  }

  void require_level(const LineParser& p, TraceLevel want) {
    if (level_ != want)
      p.fail("'" + p.keyword() + "' belongs to level " + level_name(want) + ", this trace is level " +
             level_name(level_));
  }

  void triangle(const LineParser& p) {
    require_level(p, TraceLevel::kTriangle);
    p.expect_count(21, "numbers (X Y Z R G B T for each of 3 vertices)");
    Triangle t;
    t.source_line = p.line();
    for (int i = 0; i < 3; ++i) {
      const size_t b = 1 + 7 * i;
      Vertex& v = t.v[i];
      v.x = p.real_in(b + 0, "X", -1e6, 1e6);
      v.y = p.real_in(b + 1, "Y", -1e6, 1e6);
      v.z = p.real_in(b + 2, "Z", 0, 65535);
      v.r = p.real_in(b + 3, "R", 0, 255);
      v.g = p.real_in(b + 4, "G", 0, 255);
      v.b = p.real_in(b + 5, "B", 0, 255);
      v.t = p.real_in(b + 6, "T", 0, 1);
    }
    current().triangles.push_back(t);
  }

  void format(const LineParser& p) {
    require_level(p, TraceLevel::kDda);
    const std::string expected = dda_format_record(params_);
    std::string got = p.field(0);
    for (size_t i = 1; i < p.size(); ++i) got += " " + p.field(i);
    if (got != expected)
      p.fail("trace made for other EP formats ('" + got + "'); this configuration has '" + expected + "'");
    format_seen_ = true;
  }

  void dda(const LineParser& p) {
    require_level(p, TraceLevel::kDda);
    if (!format_seen_) p.fail("'dda' before the 'format' record");
    p.expect_count(5 + 3 * kEpCount, "integers (X0 Y0 XMIN XMAX YMAX, then value dx dy of 8 EPs)");
    const FrameSettings& s = current().settings;
    if (!is_hardware_q(s.q)) p.fail("the DDA takes Q = 0 or a power of two 1/16..8 (set by 'q')");
    DdaParams d;
    d.source_line = p.line();
    d.q = s.q;
    const int64_t xy_max = params_.screen_width - 1;
    d.x0 = static_cast<int>(p.integer_in(1, "X0", 0, xy_max));
    d.y0 = static_cast<int>(p.integer_in(2, "Y0", 0, xy_max));
    d.xmin = static_cast<int>(p.integer_in(3, "XMIN", 0, xy_max));
    d.xmax = static_cast<int>(p.integer_in(4, "XMAX", 0, xy_max));
    d.ymax = static_cast<int>(p.integer_in(5, "YMAX", 0, xy_max));
    if (d.xmin > d.xmax) p.fail("XMIN > XMAX");
    if (d.x0 < d.xmin || d.x0 > d.xmax) p.fail("X0 is outside XMIN..XMAX");
    for (int e = 0; e < kEpCount; ++e) {
      const FixFormat& f = e <= kEpB ? params_.ep_color : e == kEpT ? params_.ep_t : e == kEpZ ? params_.ep_z : params_.ep_d;
      const size_t b = 6 + 3 * e;
      d.ep[e].v = p.integer_in(b, kEpNames[e], f.raw_min(), f.raw_max());
      d.ep[e].dx = p.integer_in(b + 1, kEpNames[e], f.raw_min(), f.raw_max());
      d.ep[e].dy = p.integer_in(b + 2, kEpNames[e], f.raw_min(), f.raw_max());
    }
    current().dda.push_back(d);
  }

  const Params& params_;
  Trace trace_;
  TraceLevel level_ = TraceLevel::kTriangle;
  bool format_seen_ = false;
};

}  // namespace

Trace read_trace(std::istream& in, const std::string& path, std::optional<TraceLevel> forced_level,
                 const Params& params) {
  TraceBuilder builder(path, params);
  std::optional<TraceLevel> level;
  int line_no = 0;
  bool header_done = false;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    std::vector<std::string> fields = split_fields(line);
    if (fields.empty()) continue;
    LineParser p(path, line_no, std::move(fields));
    if (!header_done) {
      header_done = true;
      if (p.keyword() == "girtd-trace") {
        p.expect_count(2, "fields (VERSION LEVEL)");
        if (p.field(1) != "1") p.fail("trace version " + p.field(1) + " is not supported (this reader knows 1)");
        level = parse_level(p.field(2), path, line_no);
        if (forced_level && *forced_level != *level)
          p.fail(std::string("--level ") + level_name(*forced_level) + " contradicts the header's level " +
                 level_name(*level));
        builder.set_level(*level);
        continue;
      }
      if (!forced_level) p.fail("not a GIRTD trace: no 'girtd-trace 1 LEVEL' header (name the level with --level)");
      level = forced_level;
      builder.set_level(*level);
    }
    builder.record(p);
  }
  if (in.bad()) throw InputError(path, line_no, "read error");
  if (!level) throw InputError(path, 0, "empty trace: no header and no records");
  Trace t = builder.finish(*level);
  if (t.primitive_count() == 0) throw InputError(path, line_no, "the trace holds no primitives");
  return t;
}

Trace read_trace(const std::string& path, std::optional<TraceLevel> forced_level, const Params& params) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open file");
  return read_trace(in, path, forced_level, params);
}

bool has_trace_header(const std::string& path) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> f = split_fields(line);
    if (f.empty()) continue;
    return f[0] == "girtd-trace";
  }
  return false;
}

}  // namespace girtd
