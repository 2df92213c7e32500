#include "io/input_reader.hpp"

#include <cctype>
#include <filesystem>

#include "common/input_error.hpp"
#include "io/model_import.hpp"
#include "io/scene_reader.hpp"
#include "io/trace_reader.hpp"

namespace girtd {

FrameSource open_input(const std::string& path, std::optional<TraceLevel> level, const Params& params,
                       const std::string& camera) {
  if (!std::filesystem::exists(path)) throw InputError(path, 0, "no such file");
  if (!level && !has_trace_header(path)) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".json") return open_scene(path, params, camera);
    if (is_model_file(path)) return FrameSource(scene_from_model(path, params, camera));
  }
  if (!camera.empty()) throw InputError("--camera", 0, path + " is a trace: --camera picks a model file's camera");
  return FrameSource(read_trace(path, level, params));
}

}  // namespace girtd
