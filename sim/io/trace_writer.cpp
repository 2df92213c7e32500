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
  out_ << "\n";
}

void TraceWriter::write(const DdaParams& p) {
  out_ << "dda " << p.x0 << " " << p.y0 << " " << p.xmin << " " << p.xmax << " " << p.ymax;
  for (const EpInit& e : p.ep) out_ << "  " << e.v << " " << e.dx << " " << e.dy;
  out_ << "\n";
}

void TraceWriter::commit() {
  out_.close();
  if (!out_ || std::rename(tmp_path_.c_str(), path_.c_str()) != 0)
    throw InputError(path_, 0, "could not write file");
  committed_ = true;
}

}  // namespace girtd
