// Scene files (JSON, traces/FORMAT.md "Scene files") and bare model files
// become polygon-level input: per frame, world-space polygons with surface
// ids, the surfaces, lights and camera. A scene is read and checked whole;
// its frames are placed one at a time as the run takes them (FrameSource).
// Unknown keys are errors; every problem is an InputError "FILE:LINE: what".
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "config/params.hpp"
#include "frontend/vec3.hpp"
#include "frontend/world_frame.hpp"
#include "io/frame_source.hpp"
#include "io/scene_defaults.hpp"
#include "io/trace.hpp"

namespace girtd {

// A frame's polygons are placed whole before the front end runs, so its
// polygon corners are capped: 30 M corners hold about 1.2 GB.
inline constexpr uint64_t kMaxSceneCorners = 30000000;

// `camera`: a model file's camera by name (--camera), over the scene's own;
// "" takes the scene's camera, else the first model file's, else auto-framed.
FrameSource open_scene(const std::string& path, const Params& params, const std::string& camera = "");
// Every frame placed at once (tests and tools on small scenes).
Trace read_scene(const std::string& path, const Params& params, const std::string& camera = "");

// A scene given as a document rather than a file (the library's
// RenderRequest::scene): the same keys, "mesh" models included; errors name
// `name` and the key ("NAME: \"models/0/mesh\" ..."); model paths are relative
// to the working directory.
FrameSource open_scene_document(const nlohmann::json& document, const std::string& name, const Params& params,
                                const std::string& camera = "");

// A bare model, one frame: its own camera (`camera` by name, else its first)
// or auto-framed; its own lights or the default one; its materials.
Trace scene_from_model(const std::string& path, const Params& params, const std::string& camera = "");

}  // namespace girtd
