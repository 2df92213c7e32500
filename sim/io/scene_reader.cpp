#include "io/scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

#include <nlohmann/json.hpp>

#include "common/file_text.hpp"
#include "common/input_error.hpp"
#include "common/json_text.hpp"
#include "frontend/polygon_shape.hpp"
#include "frontend/position_weld.hpp"
#include "frontend/rotation.hpp"
#include "frontend/surface_groups.hpp"
#include "frontend/view_transform.hpp"
#include "io/json_lines.hpp"
#include "io/model_import.hpp"
#include "io/scene_placement.hpp"
#include "io/frame_source.hpp"

namespace girtd {
namespace fs = std::filesystem;
using nlohmann::json;
using Ptr = json::json_pointer;  // built with operator/, which escapes ~ and / in names

namespace {

constexpr int kSceneVersion = 1;
constexpr size_t kMaxFrames = 100000;

// The camera as the scene gives it; "auto" frames the first frame's polygons.
struct CameraSpec {
  bool automatic = true;
  Camera camera;
  std::optional<double> near;  // a model file's camera: its near clip plane
};

// One frame as the scene file says it: read and checked before any is placed.
// It holds only what it changes, so a scene's plan grows with its text.
struct FramePlan {
  CameraSpec camera;
  std::vector<std::pair<size_t, Transform>> moved;  // instance, its transform in this frame
  int source_line = 0;                              // the frame's line (the polygons' source)
};

// Places a scene's frames one at a time, in order, as the run takes them.
struct ScenePlacer {
  WorldFrame base;  // lights, back-face culling
  std::vector<Instance> instances;
  std::vector<Transform> transforms;  // each instance's, the scene's own
  std::vector<FramePlan> frames;
  std::optional<double> focal;
  std::optional<Camera> auto_camera;  // framed once, on the first frame that needs it
  double auto_focal = 0;

  TraceFrame place_frame(size_t f, const FrameSettings& settings) {
    const FramePlan& plan = frames.at(f);
    for (size_t k = 0; k < instances.size(); ++k) instances[k].transform = transforms[k];
    for (const auto& [k, t] : plan.moved) instances[k].transform = t;
    TraceFrame tf;
    tf.settings = settings;
    tf.world.cull_back_faces = base.cull_back_faces;
    tf.world.lights = base.lights;
    place(instances, tf.world);
    for (WorldPolygon& p : tf.world.polygons) p.source_line = plan.source_line;
    if (plan.camera.automatic) {
      // So an animation does not zoom.
      if (!auto_camera) {
        auto_frame(tf.world, SceneDefaults::kFovDeg, focal);
        auto_camera = tf.world.camera;
        auto_focal = tf.world.focal_distance;
      }
      tf.world.camera = *auto_camera;
      tf.world.focal_distance = auto_focal;
    } else {
      tf.world.camera = plan.camera.camera;
      tf.world.focal_distance = focal ? *focal : plan.camera.near ? *plan.camera.near : SceneDefaults::kFocalDistance;
    }
    return tf;
  }
};


class SceneReader {
 public:
  SceneReader(const std::string& path, const Params& params, const std::string& camera_name)
      : path_(path), params_(params), camera_name_(camera_name) {
    std::optional<std::string> text = read_file_text(path);
    if (!text) throw InputError(path, 0, "cannot open file");
    text_ = std::move(*text);
    check_json_nesting(text_, path);
    root_ = parse_json_text(text_, path);
    lines_ = std::make_unique<JsonLines>(text_);
  }
  // A document with no text: errors name `name` and the key, line 0.
  SceneReader(const json& document, const std::string& name, const Params& params, const std::string& camera_name)
      : path_(name), params_(params), camera_name_(camera_name), root_(document) {}

  FrameSource read() {
    const Ptr root;
    keys(root_, root, {"girtd_scene", "comment", "window", "background", "q", "cull_back_faces", "focal_distance",
                       "camera", "lights", "materials", "models", "frames"});
    if (!root_.contains("girtd_scene")) fail(root, "not a GIRTD scene: no \"girtd_scene\": 1");
    if (integer(root / "girtd_scene", 1, 1000) != kSceneVersion)
      fail(root / "girtd_scene",
           "scene version " + root_["girtd_scene"].dump() + " is not supported (this reader knows 1)");
    FrameSettings settings;
    if (root_.contains("window")) {
      const Ptr wp = root / "window";
      const json& w = at(wp);
      if (!w.is_array() || w.size() != 4) fail(wp, "window is [X0, Y0, X1, Y1]");
      settings.window.x0 = static_cast<int>(integer(wp / size_t{0}, 0, params_.screen_width - 1));
      settings.window.y0 = static_cast<int>(integer(wp / size_t{1}, 0, params_.screen_height - 1));
      settings.window.x1 = static_cast<int>(integer(wp / size_t{2}, 0, params_.screen_width - 1));
      settings.window.y1 = static_cast<int>(integer(wp / size_t{3}, 0, params_.screen_height - 1));
      if (settings.window.x0 > settings.window.x1 || settings.window.y0 > settings.window.y1)
        fail(wp, "window is empty (X0 > X1 or Y0 > Y1)");
    }
    if (root_.contains("background")) {
      const Ptr bp = root / "background";
      const json& b = at(bp);
      if (!b.is_array() || b.size() != 3) fail(bp, "background is [R, G, B]");
      settings.background = {static_cast<uint8_t>(integer(bp / size_t{0}, 0, 255)),
                             static_cast<uint8_t>(integer(bp / size_t{1}, 0, 255)),
                             static_cast<uint8_t>(integer(bp / size_t{2}, 0, 255))};
    }
    if (root_.contains("q")) {
      settings.q = number(root / "q", 0, 64);
      settings.q_line = line(root / "q");
    }
    WorldFrame base;
    base.cull_back_faces = root_.contains("cull_back_faces") ? boolean(root / "cull_back_faces") : false;
    std::optional<double> focal;
    if (root_.contains("focal_distance")) focal = number(root / "focal_distance", kMinFocalDistance, kMaxFocalDistance);
    const std::map<std::string, Surface> materials = read_materials();
    std::vector<Instance> instances = read_models(materials);
    // The scene's lights and camera, else the model files' own, else the defaults.
    std::optional<LightSet> from_files;
    if (!root_.contains("lights")) from_files = file_lights(instances, warnings_);
    base.lights = root_.contains("lights") ? lights(root / "lights") : from_files ? *from_files : default_lights();
    CameraSpec base_camera = root_.contains("camera") ? camera(root / "camera") : CameraSpec{};
    if (!camera_name_.empty() || !root_.contains("camera"))
      if (std::optional<PlacedCamera> c = file_camera(instances, camera_name_, "--camera", warnings_))
        base_camera = CameraSpec{false, c->camera, c->near};

    // Every frame's keys are read and checked now; its polygons are placed
    // only when the run takes it (ScenePlacer).
    auto placer = std::make_shared<ScenePlacer>();
    const bool has_frames = root_.contains("frames");
    const size_t n_frames = has_frames ? frames_count() : 1;
    check_corners(instances, root / "models");
    for (size_t f = 0; f < n_frames; ++f) {
      const Ptr fp = root / "frames" / f;
      FramePlan plan{base_camera, {}, line(has_frames ? fp : root / "models")};
      if (has_frames) {
        keys(at(fp), fp, {"camera", "models", "comment"});
        if (at(fp).contains("camera") && camera_name_.empty()) plan.camera = camera(fp / "camera");  // --camera wins
        if (at(fp).contains("models")) frame_models(fp / "models", instances, plan.moved);
      }
      placer->frames.push_back(std::move(plan));
    }
    apply_q_override(settings, params_);
    placer->base = std::move(base);
    placer->focal = focal;
    for (const Instance& in : instances) placer->transforms.push_back(in.transform);
    const uint64_t objects = n_frames * instances.size();  // place() makes one object an instance
    placer->instances = std::move(instances);
    return FrameSource(path_, TraceLevel::kPolygon, std::vector<FrameSettings>(n_frames, settings), objects,
                       warnings_, [placer, settings](size_t f) { return placer->place_frame(f, settings); });
  }

 private:
  int line(const Ptr& ptr) const { return lines_ ? lines_->line(ptr.to_string()) : 0; }
  [[noreturn]] void fail(const Ptr& ptr, const std::string& what) const {
    // A document (a Python Scene) has no lines: the key's path says where.
    if (!lines_ && !ptr.empty() && what.find(key_name(ptr)) == std::string::npos)
      throw InputError(path_, 0, key_name(ptr) + ": " + what);
    throw InputError(path_, line(ptr), what);
  }

  // "scene", or the key's path in quotes ("materials/glass/n"), names unescaped.
  static std::string key_name(Ptr ptr) {
    if (ptr.empty()) return "scene";
    std::string s;
    for (; !ptr.empty(); ptr.pop_back()) s = ptr.back() + (s.empty() ? "" : "/") + s;
    return "\"" + s + "\"";
  }

  const json& at(const Ptr& ptr) const { return root_.at(ptr); }

  void keys(const json& obj, const Ptr& ptr, std::initializer_list<const char*> allowed) const {
    if (!obj.is_object()) fail(ptr, key_name(ptr) + " must be an object");
    const std::set<std::string> ok(allowed.begin(), allowed.end());
    for (auto it = obj.begin(); it != obj.end(); ++it)
      if (!ok.count(it.key())) {
        std::string list;
        for (const std::string& k : ok) list += (list.empty() ? "" : ", ") + k;
        fail(ptr / it.key(), "unknown key \"" + it.key() + "\" in " + key_name(ptr) + " (known: " + list + ")");
      }
  }

  double number(const Ptr& ptr, double lo, double hi) const {
    const json& v = at(ptr);
    if (!v.is_number()) fail(ptr, key_name(ptr) + " must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi) {
      std::ostringstream o;
      o << key_name(ptr) << " = " << v.dump() << " is outside " << lo << ".." << hi;
      fail(ptr, o.str());
    }
    return d;
  }

  int64_t integer(const Ptr& ptr, int64_t lo, int64_t hi) const {
    const json& v = at(ptr);
    if (!v.is_number_integer()) fail(ptr, key_name(ptr) + " must be an integer");
    const int64_t i = v.get<int64_t>();
    if (i < lo || i > hi)
      fail(ptr, key_name(ptr) + " = " + v.dump() + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    return i;
  }

  bool boolean(const Ptr& ptr) const {
    const json& v = at(ptr);
    if (!v.is_boolean()) fail(ptr, key_name(ptr) + " must be true or false");
    return v.get<bool>();
  }

  std::string string(const Ptr& ptr) const {
    const json& v = at(ptr);
    if (!v.is_string()) fail(ptr, key_name(ptr) + " must be a string");
    return v.get<std::string>();
  }

  Vec3 vec3(const Ptr& ptr, double limit = 1e12) const {
    const json& v = at(ptr);
    if (!v.is_array() || v.size() != 3) fail(ptr, key_name(ptr) + " must be [x, y, z]");
    return {number(ptr / size_t{0}, -limit, limit), number(ptr / size_t{1}, -limit, limit),
            number(ptr / size_t{2}, -limit, limit)};
  }

  LightSet lights(const Ptr& ptr) const {
    keys(at(ptr), ptr, {"ambient", "directional"});
    LightSet l;
    l.ambient = at(ptr).contains("ambient") ? number(ptr / "ambient", 0, 16) : 0.0;
    if (!at(ptr).contains("directional")) return l;
    const json& d = at(ptr / "directional");
    if (!d.is_array()) fail(ptr / "directional", "\"directional\" must be a list of lights");
    for (size_t i = 0; i < d.size(); ++i) {
      const Ptr lp = ptr / "directional" / i;
      keys(at(lp), lp, {"toward", "intensity"});
      if (!at(lp).contains("toward")) fail(lp, "a directional light needs \"toward\" (the direction toward the light)");
      const Vec3 t = vec3(lp / "toward");
      if (length(t) == 0) fail(lp / "toward", "\"toward\" is the zero vector");
      l.directional.push_back({normalized(t), at(lp).contains("intensity") ? number(lp / "intensity", 0, 16) : 1.0});
    }
    return l;
  }

  std::map<std::string, Surface> read_materials() const {
    std::map<std::string, Surface> out;
    if (!root_.contains("materials")) return out;
    const Ptr ms = Ptr() / "materials";
    const json& m = at(ms);
    if (!m.is_object()) fail(ms, "\"materials\" must be an object of named materials");
    for (auto it = m.begin(); it != m.end(); ++it) {
      const Ptr mp = ms / it.key();
      keys(it.value(), mp, {"colour", "cre", "n", "t_min", "t_max"});
      Surface s = SceneDefaults::material();
      if (it->contains("colour")) {
        const Vec3 c = vec3(mp / "colour", 1e12);
        for (size_t k = 0; k < 3; ++k) number(mp / "colour" / k, 0, 255);
        s.r = c.x, s.g = c.y, s.b = c.z;
      }
      if (it->contains("cre")) {
        const json& c = at(mp / "cre");
        if (!c.is_array() || c.size() != static_cast<size_t>(kCreSteps))
          fail(mp / "cre", "\"cre\" must list CRE at 0, 15, 30, 45, 60, 75 and 90 degrees (7 numbers)");
        for (size_t k = 0; k < static_cast<size_t>(kCreSteps); ++k) s.cre[k] = number(mp / "cre" / k, 0, 1);
      }
      if (it->contains("n")) s.n = number(mp / "n", kMinSpecularExponent, kMaxSpecularExponent);
      if (it->contains("t_min")) s.t_min = number(mp / "t_min", 0, 1);
      if (it->contains("t_max")) s.t_max = number(mp / "t_max", 0, 1);
      out[it.key()] = s;
    }
    return out;
  }

  void transform_keys(const Ptr& ptr, Transform& t) const {
    const json& j = at(ptr);
    if (j.contains("scale")) {
      if (at(ptr / "scale").is_number()) {
        const double s = number(ptr / "scale", -1e9, 1e9);
        t.scale = {s, s, s};
      } else {
        t.scale = vec3(ptr / "scale", 1e9);
      }
      if (t.scale.x == 0 || t.scale.y == 0 || t.scale.z == 0) fail(ptr / "scale", "a scale of 0 flattens the model");
    }
    if (j.contains("rotate_deg")) t.rotate_deg = vec3(ptr / "rotate_deg", 1e6);
    if (j.contains("translate")) t.translate = vec3(ptr / "translate");
  }

  // A model file, imported once per scene; its errors are the scene's, at
  // the "file" key's line, with the model's own FILE:LINE after "model".
  std::shared_ptr<const ImportedModel> model_file(const Ptr& file_ptr,
                                                  std::map<std::string, std::shared_ptr<const ImportedModel>>& cache) {
    fs::path file = string(file_ptr);
    if (file.is_relative()) file = fs::path(path_).parent_path() / file;
    const std::string key = file.lexically_normal().string();
    if (!fs::exists(key)) fail(file_ptr, "model file " + key + " does not exist");
    if (!cache.count(key)) {
      try {
        cache[key] = std::make_shared<const ImportedModel>(import_model(key, warnings_));
      } catch (const InputError& e) {
        fail(file_ptr, "model " + e.formatted());
      }
    }
    return cache[key];
  }

  // {"vertices": [[x, y, z], ...], "polygons": [[i, j, k, ...], ...]}: a
  // model given in the scene (the Python module's Scene.add_mesh). Built as
  // a model file is (model_import.cpp): corners at the same position are one
  // vertex, so a mesh with a vertex per face corner is shaded smooth alike,
  // and a corner repeated in a polygon is dropped.
  std::shared_ptr<const ImportedModel> inline_mesh(const Ptr& ptr) const {
    keys(at(ptr), ptr, {"vertices", "polygons"});
    for (const char* k : {"vertices", "polygons"})
      if (!at(ptr).contains(k) || !at(ptr / k).is_array() || at(ptr / k).empty())
        fail(ptr, std::string("a mesh needs a non-empty list \"") + k + "\"");
    auto model = std::make_shared<ImportedModel>();
    Mesh* m = &model->mesh;
    const size_t n = at(ptr / "vertices").size();
    if (n > size_t(std::numeric_limits<int>::max())) fail(ptr / "vertices", "too many vertices");
    std::vector<int> index_of(n);
    PositionWeld weld;
    for (size_t i = 0; i < n; ++i) index_of[i] = weld.index_of(vec3(ptr / "vertices" / i), m->positions);
    const json& polys = at(ptr / "polygons");
    if (polys.size() > kMaxModelPolygons) fail(ptr / "polygons", "more than " + std::to_string(kMaxModelPolygons) + " polygons");
    for (size_t i = 0; i < polys.size(); ++i) {
      const Ptr pp = ptr / "polygons" / i;
      if (!polys[i].is_array() || polys[i].size() < 3 || polys[i].size() > kMaxPolygonVertices)
        fail(pp, key_name(pp) + " must list 3 to " + std::to_string(kMaxPolygonVertices) + " vertex indices");
      std::vector<int> poly;
      poly.reserve(polys[i].size());
      for (size_t k = 0; k < polys[i].size(); ++k) poly.push_back(index_of[size_t(integer(pp / k, 0, int64_t(n) - 1))]);
      drop_repeated_corners(poly, [](int a, int b) { return a == b; });
      if (poly.size() >= 3) m->add_polygon(poly.begin(), poly.end());
    }
    if (m->polygon_count() == 0) fail(ptr / "polygons", "the mesh has no polygon with three distinct corners");
    return model;
  }

  std::vector<Instance> read_models(const std::map<std::string, Surface>& materials) {
    const Ptr ms = Ptr() / "models";
    if (!root_.contains("models")) fail(Ptr(), "the scene has no \"models\"");
    const json& m = at(ms);
    if (!m.is_array() || m.empty()) fail(ms, "\"models\" must be a non-empty list");
    std::vector<Instance> out;
    std::map<std::string, std::shared_ptr<const ImportedModel>> cache;
    for (size_t i = 0; i < m.size(); ++i) {
      const Ptr mp = ms / i;
      keys(at(mp), mp, {"name", "file", "mesh", "material", "crease_deg", "scale", "rotate_deg", "translate"});
      Instance in;
      in.name = at(mp).contains("name") ? string(mp / "name") : "model" + std::to_string(i);
      for (const Instance& o : out)
        if (o.name == in.name) fail(mp / "name", "two models are named \"" + in.name + "\"");
      if (at(mp).contains("file") == at(mp).contains("mesh")) fail(mp, "a model needs \"file\" or \"mesh\" (one of them)");
      in.model = at(mp).contains("file") ? model_file(mp / "file", cache) : inline_mesh(mp / "mesh");
      std::optional<Surface> chosen;  // the scene's material, over the file's
      if (at(mp).contains("material")) {
        const std::string name = string(mp / "material");
        auto it = materials.find(name);
        if (it == materials.end()) fail(mp / "material", "no material named \"" + name + "\" in \"materials\"");
        chosen = it->second;
      }
      const double crease = at(mp).contains("crease_deg") ? number(mp / "crease_deg", 0, 180) : kDefaultCreaseDeg;
      in.groups = surface_groups(in.mesh(), crease, !chosen);
      choose_surfaces(in, chosen);
      transform_keys(mp, in.transform);
      out.push_back(std::move(in));
    }
    return out;
  }

  CameraSpec camera(const Ptr& ptr) const {
    const json& c = at(ptr);
    if (c.is_string() && c.get<std::string>() == "auto") return CameraSpec{};
    keys(c, ptr, {"eye", "target", "up", "centre", "angles_deg", "fov_deg"});
    const double fov = c.contains("fov_deg") ? number(ptr / "fov_deg", 1, 170) : SceneDefaults::kFovDeg;
    CameraSpec s;
    s.automatic = false;
    const bool look_at = c.contains("eye") || c.contains("target") || c.contains("up");
    const bool angles = c.contains("centre") || c.contains("angles_deg");
    if (look_at == angles)
      fail(ptr, "camera is either {\"eye\", \"target\", \"up\"} or {\"centre\", \"angles_deg\"} (or \"auto\")");
    if (look_at) {
      if (!c.contains("eye") || !c.contains("target")) fail(ptr, "a look-at camera needs \"eye\" and \"target\"");
      const Vec3 up = c.contains("up") ? vec3(ptr / "up") : Vec3{0, 1, 0};
      const std::optional<Camera> cam = camera_look_at(vec3(ptr / "eye"), vec3(ptr / "target"), up, fov);
      if (!cam) fail(ptr, "eye equals target, or up is parallel to the view direction");
      s.camera = *cam;
    } else {
      if (!c.contains("centre") || !c.contains("angles_deg"))
        fail(ptr, "an angle camera needs \"centre\" and \"angles_deg\" [yaw, pitch, roll]");
      const Vec3 a = vec3(ptr / "angles_deg", 1e6);
      s.camera = camera_from_angles(vec3(ptr / "centre"), a.x, a.y, a.z, fov);
    }
    return s;
  }

  size_t frames_count() const {
    const Ptr fp = Ptr() / "frames";
    const json& f = at(fp);
    if (!f.is_array() || f.empty()) fail(fp, "\"frames\" must be a non-empty list");
    if (f.size() > kMaxFrames) fail(fp, "more than " + std::to_string(kMaxFrames) + " frames");
    return f.size();
  }

  // A frame's polygons are placed whole before the front end runs: their
  // corners are capped (kMaxSceneCorners).
  void check_corners(const std::vector<Instance>& instances, const Ptr& where) const {
    uint64_t corners = 0;
    for (const Instance& in : instances) corners += in.mesh().corners.size();
    if (corners > kMaxSceneCorners)
      fail(where, std::to_string(corners) + " polygon corners in a frame is more than the " +
                      std::to_string(kMaxSceneCorners) + " a scene may place: use smaller models or fewer of them");
  }

  // A frame's transforms of the named models, each over the scene's.
  void frame_models(const Ptr& ptr, const std::vector<Instance>& instances,
                    std::vector<std::pair<size_t, Transform>>& moved) const {
    const json& m = at(ptr);
    if (!m.is_object()) fail(ptr, "a frame's \"models\" is an object: model name -> transform");
    for (auto it = m.begin(); it != m.end(); ++it) {
      const Ptr mp = ptr / it.key();
      auto in = std::find_if(instances.begin(), instances.end(), [&](const Instance& x) { return x.name == it.key(); });
      if (in == instances.end()) fail(mp, "no model named \"" + it.key() + "\"");
      keys(it.value(), mp, {"scale", "rotate_deg", "translate"});
      Transform t = in->transform;
      transform_keys(mp, t);
      moved.emplace_back(size_t(in - instances.begin()), t);
    }
  }

  std::string path_, text_;
  const Params& params_;
  std::string camera_name_;  // --camera: a model file's camera, over the scene's
  std::vector<std::string> warnings_;  // the models' (each imported once)
  json root_;
  std::unique_ptr<JsonLines> lines_;
};

}  // namespace

FrameSource open_scene(const std::string& path, const Params& params, const std::string& camera) {
  return SceneReader(path, params, camera).read();
}

FrameSource open_scene_document(const nlohmann::json& document, const std::string& name, const Params& params,
                                const std::string& camera) {
  return SceneReader(document, name, params, camera).read();
}

Trace read_scene(const std::string& path, const Params& params, const std::string& camera) {
  return open_scene(path, params, camera).all();
}

Trace scene_from_model(const std::string& path, const Params& params, const std::string& camera) {
  std::vector<std::string> warnings;
  std::vector<Instance> one(1);
  Instance& in = one[0];
  in.name = path;
  in.model = std::make_shared<const ImportedModel>(import_model(path, warnings));
  in.groups = surface_groups(in.mesh(), kDefaultCreaseDeg);
  choose_surfaces(in, std::nullopt);
  TraceFrame tf;
  const std::optional<LightSet> lights = file_lights(one, warnings);
  tf.world.lights = lights ? *lights : default_lights();
  place(one, tf.world);
  if (const std::optional<PlacedCamera> c = file_camera(one, camera, "--camera", warnings)) {
    tf.world.camera = c->camera;
    tf.world.focal_distance = c->near ? *c->near : SceneDefaults::kFocalDistance;
  } else {
    auto_frame(tf.world, SceneDefaults::kFovDeg, std::nullopt);
  }
  one.clear();  // the mesh is placed: its memory goes before the front end's
  Trace trace;
  trace.path = path;
  trace.level = TraceLevel::kPolygon;
  trace.warnings = std::move(warnings);
  trace.frames.push_back(std::move(tf));
  apply_q_override(trace, params);
  return trace;
}

}  // namespace girtd
