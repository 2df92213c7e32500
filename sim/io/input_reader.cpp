#include "io/input_reader.hpp"

#include <cctype>
#include <filesystem>

#include "common/input_error.hpp"
#include "io/model_import.hpp"
#include "io/scene_reader.hpp"
#include "io/trace_reader.hpp"

namespace girtd {

Trace read_input(const std::string& path, std::optional<TraceLevel> level, const Params& params) {
  if (!std::filesystem::exists(path)) throw InputError(path, 0, "no such file");
  if (!level && !has_trace_header(path)) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".json") return read_scene(path, params);
    if (is_model_file(path)) return scene_from_model(path, params);
  }
  return read_trace(path, level, params);
}

}  // namespace girtd
