#include "io/trace_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "common/input_error.hpp"
#include "common/triangle_setup.hpp"
#include "io/number_text.hpp"
#include "io/trace_writer.hpp"

namespace girtd {

void apply_q_override(Trace& trace, const Params& params) {
  if (!params.q_override || trace.level == TraceLevel::kThesis) return;
  for (TraceFrame& f : trace.frames) {
    apply_q_override(f.settings, params);
    for (DdaParams& d : f.dda) d.q = *params.q_override;
  }
}

void apply_q_override(FrameSettings& settings, const Params& params) {
  if (!params.q_override) return;
  settings.q = *params.q_override;
  settings.q_line = 0;
}

const char* level_name(TraceLevel level) {
  switch (level) {
    case TraceLevel::kTriangle: return "triangle";
    case TraceLevel::kDda: return "dda";
    case TraceLevel::kPolygon: return "polygon";
    case TraceLevel::kThesis: return "thesis";
  }
  return "?";
}

TraceLevel parse_level(const std::string& name, const std::string& origin, int line) {
  if (name == "triangle") return TraceLevel::kTriangle;
  if (name == "dda") return TraceLevel::kDda;
  if (name == "polygon" || name == "polygons") return TraceLevel::kPolygon;
  if (name == "thesis") return TraceLevel::kThesis;
  throw InputError(origin, line, "unknown trace level '" + name + "' (known: polygon, triangle, dda, thesis)");
}

size_t Trace::primitive_count() const {
  size_t n = 0;
  for (const TraceFrame& f : frames) n += f.primitive_count();
  return n;
}

namespace {

// Lines read with bounds: a path may name an endless stream (/dev/zero, a
// FIFO) or a file of one endless line.
class BoundedLines {
 public:
  BoundedLines(std::istream& in, const std::string& path) : in_(*in.rdbuf()), path_(path) {}
  // The next line, without its end; false at the end of the file.
  bool next(std::string& line) {
    line.clear();
    bool any = false;
    for (;;) {
      if (pos_ == end_) {
        pos_ = 0;
        end_ = static_cast<size_t>(std::max<std::streamsize>(0, in_.sgetn(buffer_, sizeof buffer_)));
        if (end_ == 0) break;
      }
      any = true;
      const char* start = buffer_ + pos_;
      const char* eol = static_cast<const char*>(std::memchr(start, '\n', end_ - pos_));
      const size_t take = eol ? static_cast<size_t>(eol - start) : end_ - pos_;
      line.append(start, take);
      pos_ += take + (eol ? 1 : 0);
      if (line.size() > kMaxTraceLineBytes)
        throw InputError(path_, number() + 1, "a line longer than " + std::to_string(kMaxTraceLineBytes >> 20) +
                                                 " MiB (the limit of a trace line)");
      if (eol) break;
    }
    if (!any) return false;
    ++number_;
    read_ += line.size() + 1;
    if (read_ > kMaxTraceBytes)
      throw InputError(path_, number(), "larger than " + std::to_string(kMaxTraceBytes >> 30) +
                                           " GiB, the limit of a trace (or an endless stream)");
    return true;
  }
  // Saturated: a 2 GiB trace of empty lines would count one past int.
  int number() const { return static_cast<int>(std::min<int64_t>(number_, INT32_MAX - 1)); }

 private:
  std::streambuf& in_;
  const std::string& path_;
  char buffer_[1 << 16];
  size_t pos_ = 0, end_ = 0;
  int64_t number_ = 0;
  uint64_t read_ = 0;
};

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
    double v = 0;
    if (read_real(s, v) == NumberRead::kNotANumber) fail(std::string(name) + ": '" + s + "' is not a number");
    // Below the smallest subnormal reads as zero; past the largest double, as infinity.
    if (!std::isfinite(v)) fail(std::string(name) + ": '" + s + "' is not finite");
    return v;
  }
  double real_in(size_t i, const char* name, double lo, double hi) const {
    const double v = real(i, name);
    if (v < lo || v > hi) fail(std::string(name) + " = " + f_[i] + " is outside " + num(lo) + ".." + num(hi));
    return v;
  }
  int64_t integer(size_t i, const char* name) const {
    const std::string& s = f_[i];
    int64_t v = 0;
    const NumberRead r = read_integer(s, v);
    if (r == NumberRead::kNotANumber) fail(std::string(name) + ": '" + s + "' is not an integer");
    if (r == NumberRead::kOutOfRange) fail(std::string(name) + ": '" + s + "' is out of range");
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

// Names and ranges of the 7 numbers of a vertex at one level.
struct VertexFields {
  const char* name[7];
  double lo[7], hi[7];
};
const VertexFields kScreenVertex = {{"X", "Y", "Z", "R", "G", "B", "T"},
                                    {-1e6, -1e6, 0, 0, 0, 0, 0},
                                    {1e6, 1e6, 65535, 255, 255, 255, 1}};
const VertexFields kThesisVertex = {{"x", "y", "z", "r", "g", "b", "t"},
                                    {-1e3, -1e3, 0, 0, 0, 0, 0},
                                    {1e3, 1e3, 1, 1, 1, 1, 1}};

// Three vertices of 7 numbers each, starting at field `first`.
Triangle read_triangle(const LineParser& p, size_t first, const VertexFields& f) {
  Triangle t;
  t.source_line = p.line();
  for (int i = 0; i < 3; ++i) {
    double c[7];
    for (int k = 0; k < 7; ++k) c[k] = p.real_in(first + 7 * i + k, f.name[k], f.lo[k], f.hi[k]);
    t.v[i] = Vertex{c[0], c[1], c[2], c[3], c[4], c[5], c[6]};
  }
  return t;
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
    if (k == "surface" || k == "lights" || k == "camera" || k == "focal" || k == "cull") return world_setting(p);
    if (k == "poly" || k == "vpoly") return polygon(p);
    if (k == "object") return object(p);
    if (level_ == TraceLevel::kThesis) return thesis_record(p);
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
    WorldFrame carried_world = current().world;
    carried_world.polygons.clear();
    carried_world.objects.clear();
    trace_.frames.emplace_back();
    current().settings = carried;
    current().world = std::move(carried_world);
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
    if (p.size() < 22 || p.size() > 24)
      p.expect_count(21, "numbers (X Y Z R G B T for each of 3 vertices), then optionally INTERIOR and SURFACE");
    Triangle t = read_triangle(p, 1, kScreenVertex);
    if (p.size() > 22) t.interior_edges = static_cast<uint8_t>(p.integer_in(22, "INTERIOR", 0, 7));
    if (p.size() > 23) t.surface = static_cast<int>(p.integer_in(23, "SURFACE", 0, kMaxSurfaceId));
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
    if (p.size() != 6 + 3 * kEpCount + 1)
      p.expect_count(5 + 3 * kEpCount, "integers (X0 Y0 XMIN XMAX YMAX, then value dx dy of 8 EPs), then optionally HARD");
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
    if (p.size() > 6 + 3 * kEpCount) d.hard_edges = static_cast<uint8_t>(p.integer_in(6 + 3 * kEpCount, "HARD", 0, 7));
    current().dda.push_back(d);
  }

  // Level polygon (traces/FORMAT.md): the world records carry over like settings.
  void world_setting(const LineParser& p) {
    require_level(p, TraceLevel::kPolygon);
    if (current().primitive_count() > 0)
      p.fail("'" + p.keyword() + "' must come before the first primitive of a frame");
    WorldFrame& w = current().world;
    const std::string& k = p.keyword();
    if (k == "surface") {
      p.expect_count(7 + kCreSteps, "numbers (ID R G B N TMIN TMAX and CRE at 0, 15, ..., 90 deg)");
      const size_t id = static_cast<size_t>(p.integer_in(1, "ID", 0, static_cast<int64_t>(w.surfaces.size())));
      Surface s;
      s.r = p.real_in(2, "R", 0, 255);
      s.g = p.real_in(3, "G", 0, 255);
      s.b = p.real_in(4, "B", 0, 255);
      s.n = p.real_in(5, "N", kMinSpecularExponent, kMaxSpecularExponent);
      s.t_min = p.real_in(6, "TMIN", 0, 1);
      s.t_max = p.real_in(7, "TMAX", 0, 1);
      for (int i = 0; i < kCreSteps; ++i) s.cre[static_cast<size_t>(i)] = p.real_in(8 + static_cast<size_t>(i), "CRE", 0, 1);
      if (id == w.surfaces.size()) w.surfaces.push_back(s);
      else w.surfaces[id] = s;
    } else if (k == "lights") {
      if (p.size() < 3) p.fail("'lights' takes ID K and then DX DY DZ IF for each of K lights");
      const int64_t count = p.integer_in(2, "K", 0, kMaxTraceLights);
      p.expect_count(2 + 4 * static_cast<size_t>(count), "numbers (ID K, then DX DY DZ IF per light)");
      w.lights.ambient = p.real_in(1, "ID", 0, 16);
      w.lights.directional.clear();
      for (size_t i = 0; i < static_cast<size_t>(count); ++i) {
        const size_t b = 3 + 4 * i;
        const Vec3 d{p.real_in(b, "DX", -1e6, 1e6), p.real_in(b + 1, "DY", -1e6, 1e6), p.real_in(b + 2, "DZ", -1e6, 1e6)};
        if (length(d) == 0) p.fail("light direction is the zero vector");
        w.lights.directional.push_back({normalized(d), p.real_in(b + 3, "IF", 0, 16)});
      }
    } else if (k == "camera") {
      p.expect_count(13, "numbers (CX CY CZ, RIGHT, UP, FORWARD as unit vectors, D/S)");
      Camera& c = w.camera;
      Vec3* v[4] = {&c.centre, &c.right, &c.up, &c.forward};
      for (size_t i = 0; i < 4; ++i) *v[i] = {p.real_in(1 + 3 * i, "camera", -1e12, 1e12), p.real_in(2 + 3 * i, "camera", -1e12, 1e12), p.real_in(3 + 3 * i, "camera", -1e12, 1e12)};
      c.d_over_s = p.real_in(13, "D/S", 1e-6, 1e6);
      const double tol = 1e-6;
      auto unit = [&](Vec3 a) { return std::fabs(length(a) - 1) <= tol; };
      if (!unit(c.right) || !unit(c.up) || !unit(c.forward) || std::fabs(dot(c.right, c.up)) > tol ||
          std::fabs(dot(c.up, c.forward)) > tol || std::fabs(dot(c.right, c.forward)) > tol)
        p.fail("camera axes must be orthonormal (right, up, forward)");
      camera_seen_ = true;
    } else if (k == "focal") {
      p.expect_count(1, "number (C > 0)");
      w.focal_distance = p.real_in(1, "C", 1e-12, 1e12);
      if (w.focal_distance <= 0) p.fail("C must be > 0");
      focal_seen_ = true;
    } else {
      p.expect_count(1, "integer (0 or 1)");
      w.cull_back_faces = p.integer_in(1, "cull", 0, 1) == 1;
    }
  }

  // Level thesis: `bg R G B`, `qq 0|1`, and triangles as 21 bare numbers.
  void thesis_record(const LineParser& p) {
    FrameSettings& s = current().settings;
    if (p.keyword() == "bg") {
      p.expect_count(3, "integers (R G B)");
      s.background = {static_cast<uint8_t>(p.integer_in(1, "R", 0, 255)),
                      static_cast<uint8_t>(p.integer_in(2, "G", 0, 255)),
                      static_cast<uint8_t>(p.integer_in(3, "B", 0, 255))};
      return;
    }
    if (p.keyword() == "qq") {
      p.expect_count(1, "flag (0 or 1)");
      s.qq = p.integer_in(1, "qq", 0, 1) == 1;
      return;
    }
    if (p.size() != 21) p.fail("a thesis triangle is 21 numbers (x y z r g b t for 3 vertices), got " +
                               std::to_string(p.size()) + " fields");
    current().triangles.push_back(read_triangle(p, 0, kThesisVertex));
  }

  // `poly SURFACE N X Y Z ...`, or `vpoly SURFACE N X Y Z R G B ...` whose
  // corners carry their own diffuse colour.
  void polygon(const LineParser& p) {
    require_level(p, TraceLevel::kPolygon);
    const std::string& k = p.keyword();
    const bool coloured = k == "vpoly";
    if (!camera_seen_ || !focal_seen_) p.fail("'" + k + "' before the 'camera' and 'focal' records");
    WorldFrame& w = current().world;
    const size_t per_corner = coloured ? 6 : 3;
    if (p.size() < 3)
      p.fail("'" + k + "' takes SURFACE N and then " + (coloured ? "X Y Z R G B" : "X Y Z") + " for each of N vertices");
    WorldPolygon poly;
    poly.source_line = p.line();
    poly.surface = static_cast<int>(p.integer_in(1, "SURFACE", 0, static_cast<int64_t>(w.surfaces.size()) - 1));
    const int64_t n = p.integer_in(2, "N", 3, kMaxTracePolygonVertices);
    p.expect_count(2 + per_corner * static_cast<size_t>(n),
                   coloured ? "numbers (SURFACE N, then X Y Z R G B per vertex)" : "numbers (SURFACE N, then X Y Z per vertex)");
    for (size_t i = 0; i < static_cast<size_t>(n); ++i) {
      const size_t at = 3 + per_corner * i;
      poly.p.push_back({p.real_in(at, "X", -1e12, 1e12), p.real_in(at + 1, "Y", -1e12, 1e12),
                        p.real_in(at + 2, "Z", -1e12, 1e12)});
      if (coloured)
        poly.colour.push_back({float(p.real_in(at + 3, "R", 0, 255)), float(p.real_in(at + 4, "G", 0, 255)),
                               float(p.real_in(at + 5, "B", 0, 255))});
    }
    w.polygons.push_back(std::move(poly));
    if (w.objects.empty()) w.objects.push_back({0, 0});  // polygons before any `object` record
    ++w.objects.back().count;
  }

  // The polygons that follow, up to the next `object`, are one object.
  void object(const LineParser& p) {
    require_level(p, TraceLevel::kPolygon);
    p.expect_count(0, "fields");
    WorldFrame& w = current().world;
    if (w.objects.empty() || w.objects.back().count > 0) w.objects.push_back({w.polygons.size(), 0});
  }

  static constexpr int64_t kMaxTracePolygonVertices = 65536;

  bool camera_seen_ = false, focal_seen_ = false;
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
  BoundedLines lines(in, path);
  int line_no = 0;
  bool header_done = false;
  for (std::string line; lines.next(line);) {
    line_no = lines.number();
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
  if (!level) throw InputError(path, 0, "empty trace: no header and no records");
  Trace t = builder.finish(*level);
  if (t.primitive_count() == 0) throw InputError(path, line_no, "the trace holds no primitives");
  apply_q_override(t, params);
  return t;
}

Trace read_trace(const std::string& path, std::optional<TraceLevel> forced_level, const Params& params) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open file");
  return read_trace(in, path, forced_level, params);
}

std::optional<TraceLevel> header_level(const std::string& path) {
  std::ifstream in(path);
  BoundedLines lines(in, path);
  for (std::string line; lines.next(line);) {
    const std::vector<std::string> f = split_fields(line);
    if (f.empty()) continue;
    if (f[0] != "girtd-trace" || f.size() != 3) return std::nullopt;
    return parse_level(f[2], path, 0);
  }
  return std::nullopt;
}

bool has_trace_header(const std::string& path) {
  std::ifstream in(path);
  BoundedLines lines(in, path);
  for (std::string line; lines.next(line);) {
    const std::vector<std::string> f = split_fields(line);
    if (f.empty()) continue;
    return f[0] == "girtd-trace";
  }
  return false;
}

}  // namespace girtd
