// _girtd: the library (sim/api/girtd.hpp) for Python. Requests and reports
// cross as JSON text, pictures as numpy arrays; girtd/__init__.py is the
// module users import. A back end that elaborates SystemC renders in a child
// process, so a script can render on it any number of times.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>

#include "api/girtd.hpp"
#include "io/png_io.hpp"

namespace py = pybind11;
using nlohmann::json;

namespace {

std::vector<girtd::ConfigLayer> config_layers(const json& list) {
  std::vector<girtd::ConfigLayer> layers;
  for (const json& l : list) {
    if (l.contains("file")) layers.push_back({l["file"].get<std::string>(), nullptr, l["file"].get<std::string>()});
    else layers.push_back({"", l["patch"], l.value("origin", std::string("config"))});
  }
  return layers;
}

girtd::RenderRequest request_from(const json& r) {
  girtd::RenderRequest q;
  q.input = r.at("input");
  if (r.contains("scene")) q.scene = r["scene"];
  q.backend = r.value("backend", q.backend);
  q.config = config_layers(r.value("config", json::array()));
  q.level = r.value("level", std::string());
  q.camera = r.value("camera", std::string());
  q.repeat = r.value("repeat", 1);
  q.keep_all_frames = r.value("keep_all_frames", false);
  q.prune = r.value("prune", true);
  if (r.contains("aa")) q.aa = r["aa"].get<double>();
  if (r.contains("sample_timing")) q.sample_timing = r["sample_timing"].get<double>();
  q.dump = r.value("dump", std::string());
  q.progress = r.value("progress", false);
  q.print_warnings = r.value("print_warnings", true);
  return q;
}

py::array_t<uint8_t> rgb_array(const girtd::RgbImage& img) {
  py::array_t<uint8_t> a({img.height, img.width, 3});
  std::memcpy(a.mutable_data(), img.rgb.data(), img.rgb.size());
  return a;
}

py::array_t<uint16_t> z_array(const std::vector<uint16_t>& z, int width, int height) {
  py::array_t<uint16_t> a({height, width});
  std::memcpy(a.mutable_data(), z.data(), z.size() * sizeof(uint16_t));
  return a;
}

// girtd.InputError(formatted, file, line, message), raised from the C++ one.
[[noreturn]] void raise_input_error(const girtd::InputError& e) {
  py::object cls = py::module_::import("girtd").attr("InputError");
  py::object err = cls(e.formatted(), girtd::one_line(e.file()), e.line(), girtd::one_line(e.what()));
  PyErr_SetObject(cls.ptr(), err.ptr());
  throw py::error_already_set();
}

py::dict render(const std::string& request_json) {
  const girtd::RenderRequest q = request_from(json::parse(request_json));
  girtd::RenderResult r;
  try {
    py::gil_scoped_release unlocked;
    r = girtd::runs_once_per_process(q.backend) ? girtd::render_in_child_process(q) : girtd::render(q);
  } catch (const girtd::InputError& e) {
    raise_input_error(e);
  }
  if (r.problem) raise_input_error(*r.problem);
  py::dict out;
  out["report"] = r.report.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  out["frame"] = rgb_array(r.frame);
  out["z"] = z_array(r.z, r.frame.width, r.frame.height);
  py::list frames;
  for (const girtd::RgbImage& f : r.per_frame) frames.append(rgb_array(f));
  out["frames"] = frames;
  out["wave_files"] = r.wave_files;
  return out;
}

template <class F>
auto checked(F f) {
  try {
    return f();
  } catch (const girtd::InputError& e) {
    raise_input_error(e);
  }
}

}  // namespace

PYBIND11_MODULE(_girtd, m) {
  m.doc() = "GIRTD-sim's library (sim/api/girtd.hpp); import girtd, not this";
  // Where the driver is (tools/girtd): a render that needs an RTL variant runs through it.
  m.attr("source_dir") = GIRTD_SOURCE_DIR;
  m.def("render", &render, "render a request (JSON text): report JSON text, frame, z, frames");
  m.def("backends", [] { return girtd::backend_list().dump(); });
  m.def("merged_config", [](const std::string& layers) {
    return checked([&] { return girtd::merged_config(config_layers(json::parse(layers))).dump(); });
  });
  m.def("needs_rtl_variant", [](const std::string& layers) {
    return checked([&] { return !girtd::holds_rtl_key(girtd::needed_rtl_key(config_layers(json::parse(layers)))); });
  });
  m.def("read_png_rgb", [](const std::string& path) {
    return checked([&] { return rgb_array(girtd::read_png_rgb(path)); });
  });
  m.def("read_png_gray16", [](const std::string& path) {
    return checked([&] {
      int w = 0, h = 0;
      const std::vector<uint16_t> z = girtd::read_png_gray16(path, w, h);
      return z_array(z, w, h);
    });
  });
}
