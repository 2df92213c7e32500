#include "wave/wave_recorder.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "common/input_error.hpp"
#include "config/params.hpp"
#include "io/subprocess.hpp"
#include "gtkwave/fstapi.h"
#include "rtl/backend_rtl.hpp"
#include "verilated_fst_c.h"

namespace girtd {
namespace fs = std::filesystem;

// Verilator's trace callbacks (verilated_trace.h): declare at open, then
// write every value in full once and the changes at each dump.
struct WaveRecorder::StageProbe {
  const StageActivity* a;
  const FifoActivity* fifo;
  uint32_t code = 0;
  uint32_t occupancy() const { return fifo ? uint32_t(fifo->pushed - fifo->popped) : 0; }

  static void init(void* self, VerilatedFst* t, uint32_t code) {
    auto* p = static_cast<StageProbe*>(self);
    p->code = code;
    t->pushNamePrefix("pipeline ");
    t->pushNamePrefix(p->a->name + " ");
    t->declBit(code + 0, "busy", -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1);
    t->declBit(code + 1, "starved", -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1);
    t->declBit(code + 2, "blocked", -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1);
    t->declBus(code + 3, "fifo_in", -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1, 31, 0);
    t->declBus(code + 4, "items_in", -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1, 31, 0);
    t->declBus(code + 5, "items_out", -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1, 31, 0);
    t->popNamePrefix(2);
  }
  template <bool kFull>
  static void write(void* self, VerilatedFst::Buffer* b) {
    auto* p = static_cast<StageProbe*>(self);
    uint32_t* o = b->oldp(p->code);
    const StageActivity& a = *p->a;
    const bool bits[3] = {a.state == StageState::kBusy, a.state == StageState::kStarved,
                          a.state == StageState::kBlocked};
    const uint32_t words[3] = {p->occupancy(), uint32_t(a.items), uint32_t(a.emitted)};
    for (int i = 0; i < 3; ++i) {
      if (kFull) b->fullBit(o + i, bits[i]);
      else b->chgBit(o + i, bits[i]);
    }
    for (int i = 0; i < 3; ++i) {
      if (kFull) b->fullIData(o + 3 + i, words[i], 32);
      else b->chgIData(o + 3 + i, words[i], 32);
    }
  }
};

struct WaveRecorder::TopProbe {
  const uint32_t* frame;
  uint32_t code = 0;
  static void init(void* self, VerilatedFst* t, uint32_t code) {
    auto* p = static_cast<TopProbe*>(self);
    p->code = code;
    t->pushNamePrefix("pipeline ");
    t->declBus(code, "frame", -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1, 31, 0);
    t->popNamePrefix(1);
  }
  template <bool kFull>
  static void write(void* self, VerilatedFst::Buffer* b) {
    auto* p = static_cast<TopProbe*>(self);
    if (kFull) b->fullIData(b->oldp(p->code), *p->frame, 32);
    else b->chgIData(b->oldp(p->code), *p->frame, 32);
  }
};

WaveRecorder::WaveRecorder(WaveOptions opt)
    : opt_(std::move(opt)), fst_tmp_(opt_.path + ".partial.fst"), pixels_tmp_(opt_.path + ".pixels.csv.partial") {
  tfp_ = std::make_unique<VerilatedFstC>();
  pixel_log_ = "time_ns,x,y\n";
}

WaveRecorder::~WaveRecorder() {
  if (finished_) return;
  if (tfp_ && tfp_->isOpen()) tfp_->close();
  std::error_code ec;
  for (const std::string& f : {fst_tmp_, pixels_tmp_, opt_.path + ".partial"}) fs::remove(f, ec);
  fs::remove(opt_.path.substr(0, opt_.path.size() - 4) + ".gtkw.partial", ec);
}

void WaveRecorder::add_rtl(BackendRtl& rtl) {
  rtl.trace(tfp_.get());
  has_rtl_ = true;
}

void WaveRecorder::add_stage(const StageActivity& a, const FifoActivity* in_fifo) {
  stages_.push_back(std::make_unique<StageProbe>(StageProbe{&a, in_fifo}));
  StageProbe* p = stages_.back().get();
  tfp_->spTrace()->addInitCb(&StageProbe::init, p);
  tfp_->spTrace()->addFullCb(&StageProbe::write<true>, p);
  tfp_->spTrace()->addChgCb(&StageProbe::write<false>, p);
  stage_names_.push_back(a.name);
}

void WaveRecorder::open() {
  top_ = std::make_unique<TopProbe>(TopProbe{&frame_});
  tfp_->spTrace()->addInitCb(&TopProbe::init, top_.get());
  tfp_->spTrace()->addFullCb(&TopProbe::write<true>, top_.get());
  tfp_->spTrace()->addChgCb(&TopProbe::write<false>, top_.get());
  // Verilator crashes on a file where the scope filter kept nothing: the
  // pipeline's frame is always kept.
  if (!opt_.scopes.empty()) {
    tfp_->dumpvars(1, "pipeline");
    for (const std::string& s : opt_.scopes) tfp_->dumpvars(99, s);
  }
  tfp_->set_time_resolution("1ns");
  std::error_code ec;
  fs::create_directories(fs::absolute(opt_.path).parent_path(), ec);
  if (ec) throw InputError(opt_.path, 0, "cannot make the waveform's directory: " + ec.message());
  tfp_->open(fst_tmp_.c_str());
  if (!tfp_->isOpen()) throw InputError(opt_.path, 0, "cannot write the waveform file");
}

void WaveRecorder::dump(double t_ns) {
  if (t_ns <= last_dump_ns_) return;  // one dump per time
  last_dump_ns_ = t_ns;
  tfp_->dump(static_cast<uint64_t>(t_ns + 0.5));
}

void WaveRecorder::log_pixel(double t_ns, int x, int y) {
  char line[64];
  std::snprintf(line, sizeof line, "%.0f,%d,%d\n", t_ns, x, y);
  pixel_log_ += line;
}

namespace {

struct FstVar {
  std::string scope, name;  // name as declared (a bus carries its range)
  uint32_t width;
};

std::vector<FstVar> read_hierarchy(const std::string& path) {
  void* ctx = fstReaderOpen(path.c_str());
  if (!ctx) throw std::runtime_error("cannot read back the waveform " + path);
  std::vector<FstVar> vars;
  std::vector<std::string> scope;
  fstReaderIterateHierRewind(ctx);
  while (fstHier* h = fstReaderIterateHier(ctx)) {
    if (h->htyp == FST_HT_SCOPE) scope.push_back(h->u.scope.name);
    else if (h->htyp == FST_HT_UPSCOPE && !scope.empty()) scope.pop_back();
    else if (h->htyp == FST_HT_VAR) {
      std::string s;
      for (const std::string& part : scope) s += (s.empty() ? "" : ".") + part;
      vars.push_back({s, h->u.var.name, h->u.var.length});
    }
  }
  fstReaderClose(ctx);
  return vars;
}

// GTKWave's name for a variable: scope.name, a bus with its range.
std::string gtkw_name(const FstVar& v) {
  std::string n = v.name;
  const size_t space = n.find(' ');
  if (space != std::string::npos) n.erase(space, 1);  // "x [9:0]" -> "x[9:0]"
  else if (v.width > 1) n += "[" + std::to_string(v.width - 1) + ":0]";
  return v.scope + "." + n;
}

std::string base_name(const std::string& declared) { return declared.substr(0, declared.find(' ')); }

// Signals grouped by stage: the SystemC stages in pipeline order, then the
// RTL blocks. GTKWave flags: 0x800000 group begin, 0x1000000 group end,
// 0x400000 closed, 0x200 blank; 28 = binary, 24 = decimal.
std::string gtkw_text(const std::vector<FstVar>& vars, const std::vector<std::string>& stages,
                      const std::string& dumpfile, double t0_ns) {
  std::map<std::string, std::vector<const FstVar*>> by_scope;
  for (const FstVar& v : vars) by_scope[v.scope].push_back(&v);
  std::ostringstream o;
  o << "[dumpfile] \"" << dumpfile << "\"\n[timestart] " << static_cast<uint64_t>(t0_ns) << "\n[size] 1600 1000\n"
    << "[sst_width] 280\n[signals_width] 300\n";
  auto group = [&](const std::string& title, const std::string& scope, bool open,
                   const std::vector<std::string>& only) {
    const auto it = by_scope.find(scope);
    if (it == by_scope.end()) return;
    std::vector<const FstVar*> chosen;
    for (const FstVar* v : it->second)
      if (only.empty() || std::find(only.begin(), only.end(), base_name(v->name)) != only.end()) chosen.push_back(v);
    if (chosen.empty()) return;
    o << (open ? "@800200\n" : "@c00200\n") << "-" << title << "\n";
    for (const FstVar* v : chosen) o << (v->width > 1 ? "@24\n" : "@28\n") << gtkw_name(*v) << "\n";
    o << (open ? "@1000200\n" : "@1401200\n") << "-" << title << "\n";
  };
  // Open: the stages next to the back end and the DDA's handshakes, state
  // and position; closed: the rest (a click away in GTKWave).
  group("SystemC: frame", "pipeline", true, {});
  for (const std::string& s : stages)
    group("SystemC: " + s, "pipeline." + s, s == "preparer" || s == "back_end", {});
  group("RTL: back end ports", "TOP.girtd_backend", false,
        {"clk_i", "in_valid_i", "in_ready_o", "clear_i", "flush_i", "swap_i", "idle_o", "front_o", "dda_state_o",
         "dda_active_o", "pixel_push_o", "pixel_x_o", "pixel_y_o", "pixels_generated_o", "page_misses_o"});
  // The DDA runs on its own clock and never holds inside (hw/README.md):
  // its handshake and stall are the top's.
  group("RTL: DDA clock and handshake", "TOP.girtd_backend", true,
        {"dda_clk_i", "dda_step_o", "dda_hold", "in_valid_i", "in_ready_o", "dda_active", "dda_stall", "out_valid",
         "fifo_full"});
  group("RTL: DDA", "TOP.girtd_backend.u_dda", true,
        {"out_valid_o", "out_x_o", "out_y_o", "out_z_o", "state_q", "emit", "x", "y", "y_past_end"});
  group("RTL: DDA, every signal", "TOP.girtd_backend.u_dda", false, {});
  group("RTL: DDA -> HAD FIFO", "TOP.girtd_backend.u_fifo", false, {});
  group("RTL: HAD", "TOP.girtd_backend.u_had", false, {});
  group("RTL: cache", "TOP.girtd_backend.u_had.u_cache", false, {});
  group("RTL: VRAM (ports and state; the array is not traced)", "TOP.girtd_backend.u_vram", false, {});
  return o.str();
}

bool fst2vcd(const std::string& fst, const std::string& vcd) {
  return run_process({"fst2vcd", "-f", fst, "-o", vcd}, true) == 0 && fs::exists(vcd);
}

// Scopes deep enough to name in a message.
std::string scope_list(const std::vector<FstVar>& vars) {
  std::string known;
  std::map<std::string, int> seen;
  for (const FstVar& v : vars)
    if (!seen[v.scope]++ && std::count(v.scope.begin(), v.scope.end(), '.') <= 2) known += " " + v.scope;
  return known;
}

bool under(const std::string& scope, const std::string& prefix) {
  return scope == prefix || scope.rfind(prefix + ".", 0) == 0;
}

}  // namespace

void check_pipeline_wave_scopes(const std::vector<std::string>& scopes, const std::vector<std::string>& stages) {
  for (const std::string& s : scopes) {
    if (!under(s, "pipeline")) continue;
    bool known = s == "pipeline";
    std::string names;
    for (const std::string& st : stages) {
      known = known || s == "pipeline." + st;
      names += " pipeline." + st;
    }
    if (!known) throw InputError("--wave-scope", 0, "'" + s + "': this run's stages are" + names);
  }
}

void check_rtl_wave_scopes(const std::vector<std::string>& scopes, const Params& p) {
  std::vector<std::string> rtl_scopes;
  for (const std::string& s : scopes)
    if (!under(s, "pipeline")) rtl_scopes.push_back(s);
  if (rtl_scopes.empty()) return;
  // One dump of a scratch traced instance, read back for its hierarchy.
  std::string path = (fs::temp_directory_path() / "girtd_scopes_XXXXXX").string();
  const int fd = mkstemp(path.data());
  if (fd < 0) throw std::runtime_error("cannot make a temporary file for the scope check");
  ::close(fd);
  struct Remove {
    std::string path;
    ~Remove() { std::remove(path.c_str()); }
  } remove_after{path};
  std::vector<FstVar> vars;
  {
    const std::unique_ptr<BackendRtl> rtl = make_backend_rtl(p, 0, true);
    VerilatedFstC tfp;
    rtl->trace(&tfp);
    tfp.open(path.c_str());
    tfp.dump(0);
    tfp.close();
    vars = read_hierarchy(path);
  }
  for (const std::string& s : rtl_scopes) {
    bool found = false;
    for (const FstVar& v : vars) found = found || under(v.scope, s);
    if (!found) throw InputError("--wave-scope", 0, "'" + s + "' names no part of the RTL (scopes include:" + scope_list(vars) + ")");
  }
}

WaveFiles WaveRecorder::finish(double run_end_ns) {
  tfp_->close();
  WaveFiles out;
  if (last_dump_ns_ < 0) {
    char what[160];
    std::snprintf(what, sizeof what, "the window %.0f..%.0f ns recorded nothing: the run ended at %.0f ns",
                  opt_.t0_ns, std::min(opt_.t1_ns, 1e15), run_end_ns);
    out.problem = InputError("--wave-window", 0, what);
    return out;
  }
  const std::vector<FstVar> vars = read_hierarchy(fst_tmp_);
  for (const std::string& s : opt_.scopes) {
    bool found = false;
    for (const FstVar& v : vars) found = found || under(v.scope, s);
    if (!found) {
      out.problem = InputError("--wave-scope", 0, "'" + s + "' recorded nothing (scopes include:" + scope_list(vars) + ")");
      return out;
    }
  }
  if (has_rtl_) std::ofstream(pixels_tmp_) << pixel_log_;  // approx pushes no RTL pixels
  else fs::remove(opt_.path.substr(0, opt_.path.size() - 4) + ".pixels.csv");  // not an earlier run's
  const std::string stem = opt_.path.substr(0, opt_.path.size() - 4);
  const std::string gtkw = stem + ".gtkw", pixels = stem + ".pixels.csv";
  std::ofstream(gtkw + ".partial") << gtkw_text(vars, stage_names_, fs::absolute(opt_.path).string(), opt_.t0_ns);
  if (opt_.vcd()) {
    if (!fst2vcd(fst_tmp_, opt_.path + ".partial")) {
      fs::remove(gtkw + ".partial");
      out.problem = InputError("--wave", 0, "writing VCD needs fst2vcd (Debian package gtkwave): install it or ask for .fst");
      return out;
    }
    fs::remove(fst_tmp_);
    fs::rename(opt_.path + ".partial", opt_.path);
  } else {
    fs::rename(fst_tmp_, opt_.path);
  }
  fs::rename(gtkw + ".partial", gtkw);
  finished_ = true;
  out.paths = {opt_.path, gtkw};
  if (has_rtl_) {
    fs::rename(pixels_tmp_, pixels);
    out.paths.push_back(pixels);
  }
  return out;
}

}  // namespace girtd
