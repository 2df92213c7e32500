#include "io/trace_writer.hpp"

#include <cstdio>
#include <iomanip>
#include <sstream>

#include "common/input_error.hpp"

namespace girtd {

std::string dda_format_record(const Params& p) {
  std::ostringstream o;
  auto fmt = [&](const char* name, const FixFormat& f, bool out) {
    o << " " << name << " " << f.int_bits << " " << f.frac_bits;
    if (out) o << " " << f.out_bits;
  };
  o << "format";
  fmt("color", p.ep_color, true);
  fmt("t", p.ep_t, true);
  fmt("z", p.ep_z, true);
  fmt("d", p.ep_d, false);
  o << " xy " << p.xy_bits;
  return o.str();
}

TraceWriter::TraceWriter(const std::string& path, TraceLevel level, const Params& params,
                         const std::string& comment)
    : path_(path), tmp_path_(path + ".partial") {
  out_.open(tmp_path_);
  if (!out_) throw InputError(path, 0, "cannot write file");
  out_ << "girtd-trace 1 " << level_name(level) << "\n";
  if (!comment.empty()) out_ << "# " << comment << "\n";
  if (level == TraceLevel::kDda) out_ << dda_format_record(params) << "\n";
  out_ << std::setprecision(17);
}

TraceWriter::~TraceWriter() {
  if (!committed_) {
    out_.close();
    std::remove(tmp_path_.c_str());
  }
}

void TraceWriter::begin_frame(const FrameSettings& s) {
  if (!first_frame_) out_ << "frame\n";
  first_frame_ = false;
  out_ << "window " << s.window.x0 << " " << s.window.y0 << " " << s.window.x1 << " " << s.window.y1 << "\n";
  out_ << "background " << int(s.background.r) << " " << int(s.background.g) << " " << int(s.background.b)
       << "\n";
  out_ << "q " << s.q << "\n";
}

void TraceWriter::write(const Triangle& t) {
  out_ << "tri";
  for (const Vertex& v : t.v) out_ << "  " << v.x << " " << v.y << " " << v.z << " " << v.r << " " << v.g << " " << v.b << " " << v.t;
  if (t.surface >= 0) out_ << "  " << int(t.interior_edges) << " " << t.surface;
  else if (t.interior_edges) out_ << "  " << int(t.interior_edges);
  out_ << "\n";
}

void TraceWriter::write(const DdaParams& p) {
  out_ << "dda " << p.x0 << " " << p.y0 << " " << p.xmin << " " << p.xmax << " " << p.ymax;
  for (const EpInit& e : p.ep) out_ << "  " << e.v << " " << e.dx << " " << e.dy;
  if (p.hard_edges) out_ << "  " << int(p.hard_edges);
  out_ << "\n";
}

namespace {

bool same_surface(const Surface& a, const Surface& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.n == b.n && a.t_min == b.t_min && a.t_max == b.t_max &&
         a.cre == b.cre;
}

}  // namespace

void TraceWriter::write(const WorldFrame& w) {
  for (size_t i = 0; i < w.surfaces.size(); ++i) {
    const Surface& s = w.surfaces[i];
    if (i < written_surfaces_.size() && same_surface(written_surfaces_[i], s)) continue;
    out_ << "surface " << i << " " << s.r << " " << s.g << " " << s.b << " " << s.n << " " << s.t_min << " " << s.t_max;
    for (double c : s.cre) out_ << " " << c;
    out_ << "\n";
  }
  written_surfaces_ = w.surfaces;
  out_ << "lights " << w.lights.ambient << " " << w.lights.directional.size();
  for (const DirectionalLight& l : w.lights.directional)
    out_ << "  " << l.toward.x << " " << l.toward.y << " " << l.toward.z << " " << l.intensity;
  out_ << "\n";
  const Camera& c = w.camera;
  out_ << "camera";
  for (const Vec3& v : {c.centre, c.right, c.up, c.forward}) out_ << "  " << v.x << " " << v.y << " " << v.z;
  out_ << "  " << c.d_over_s << "\n";
  out_ << "focal " << w.focal_distance << "\ncull " << (w.cull_back_faces ? 1 : 0) << "\n";
  const std::vector<WorldObject> objects = frame_objects(w);
  size_t next_object = 0;
  for (size_t i = 0; i < w.polygons.size(); ++i) {
    const WorldPolygon& poly = w.polygons[i];
    bool starts = false;  // an object starts here (skip empty ones)
    while (next_object < objects.size() && objects[next_object].first == i) starts = objects[next_object++].count > 0;
    if (starts && objects.size() > 1) out_ << "object\n";
    out_ << (poly.colour.empty() ? "poly " : "vpoly ") << poly.surface << " " << poly.p.size();
    for (size_t k = 0; k < poly.p.size(); ++k) {
      out_ << "  " << poly.p[k].x << " " << poly.p[k].y << " " << poly.p[k].z;
      if (!poly.colour.empty()) out_ << " " << poly.colour[k].r << " " << poly.colour[k].g << " " << poly.colour[k].b;
    }
    out_ << "\n";
  }
}

void TraceWriter::commit() {
  out_.close();
  if (!out_ || std::rename(tmp_path_.c_str(), path_.c_str()) != 0)
    throw InputError(path_, 0, "could not write file");
  committed_ = true;
}

}  // namespace girtd
