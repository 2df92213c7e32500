// The glTF check: every accessor within its buffer view and every buffer
// view within its buffer, as the glTF specification requires, before assimp
// reads them. assimp 5.2.5 bounds an accessor's read by its view's length
// but starts it at the accessor's own byteOffset (glTF2 Accessor::ExtractData):
// an accessor with an offset reads past its view, and past the buffer where
// the view ends with it (testbench/fuzz/README.md, Findings). Unknown accessor
// types and component types are refused too: they are not glTF, and assimp
// reads such data with a size it guesses.
// Anything else wrong (JSON syntax, a missing field, an index out of range)
// is left to assimp, which refuses it with its own message.
#include <cstdint>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/json_lines.hpp"
#include "io/model_precheck.hpp"
#include "io/model_tokens.hpp"

namespace girtd {
namespace {

using nlohmann::json;

uint32_t u32_at(std::string_view data, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(data[at + static_cast<size_t>(i)]);
  return v;
}

// A binary glTF's JSON chunk (the first chunk, "JSON"), or nothing where the
// container is not one assimp would read as such (it refuses it itself).
std::optional<std::string> glb_json(std::string_view data) {
  if (data.size() < 20 || data.substr(0, 4) != "glTF" || u32_at(data, 4) != 2) return std::nullopt;
  const uint64_t length = u32_at(data, 12);
  if (data.substr(16, 4) != "JSON" || 20 + length > data.size()) return std::nullopt;
  return std::string(data.substr(20, static_cast<size_t>(length)));
}

// Bytes per component of a glTF componentType code (5124, a 32-bit int, is
// glTF 1.0's), 0 for an unknown one.
uint64_t component_bytes(int64_t code) {
  switch (code) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5124: case 5125: case 5126: return 4;
    default: return 0;
  }
}

// Components of a glTF accessor type, 0 for an unknown one.
uint64_t components(const std::string& type) {
  for (const auto& [name, n] : {std::pair{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                {"MAT2", 4}, {"MAT3", 9}, {"MAT4", 16}})
    if (type == name) return static_cast<uint64_t>(n);
  return 0;
}

class GltfCheck {
 public:
  GltfCheck(const std::string& path, const json& doc, const JsonLines& lines, bool binary)
      : path_(path), doc_(doc), lines_(lines), binary_(binary) {}

  void run() {
    for_each("bufferViews", [&](const std::string& at, const json& view) { check_view(at, view); });
    for_each("accessors", [&](const std::string& at, const json& accessor) { check_accessor(at, accessor); });
  }

 private:
  // Each member of a top-level array (glTF 2) or object keyed by id (glTF 1), with its JSON pointer.
  template <class F>
  void for_each(const char* collection, F&& f) const {
    const auto c = doc_.find(collection);
    if (c == doc_.end()) return;
    const std::string base = std::string("/") + collection + "/";
    if (c->is_array()) {
      for (size_t i = 0; i < c->size(); ++i) f(base + std::to_string(i), (*c)[i]);
    } else if (c->is_object()) {
      for (const auto& [key, value] : c->items()) f(base + pointer_token(key), value);
    }
  }

  static std::string pointer_token(const std::string& key) {
    std::string out;
    for (char ch : key) out += ch == '~' ? "~0" : ch == '/' ? "~1" : std::string(1, ch);
    return out;
  }

  // The member `ref` names in `collection`: an index (glTF 2) or an id (glTF 1); null where there is none.
  const json* lookup(const char* collection, const json& ref) const {
    const auto c = doc_.find(collection);
    if (c == doc_.end()) return nullptr;
    if (c->is_array() && ref.is_number_unsigned() && ref.get<uint64_t>() < c->size()) return &(*c)[ref.get<size_t>()];
    if (c->is_object() && ref.is_string() && c->contains(ref.get<std::string>())) return &(*c)[ref.get<std::string>()];
    return nullptr;
  }

  [[noreturn]] void refuse(const std::string& at, const std::string& what) const {
    const std::string where = at.substr(1, at.find('/', 1) - 1) == "accessors" ? "accessor " : "buffer view ";
    const std::string name = where + at.substr(at.rfind('/') + 1);
    const int line = lines_.line(at);
    if (!binary_) fail(path_, line, name + ": " + what);
    fail(path_, 0, name + " (line " + std::to_string(line) + " of the JSON chunk): " + what);
  }

  // A non-negative integer field (absent: `absent`).
  uint64_t count_field(const std::string& at, const json& object, const char* key, uint64_t absent) const {
    const auto f = object.find(key);
    if (f == object.end()) return absent;
    if (!f->is_number_unsigned() && !(f->is_number_integer() && f->get<int64_t>() >= 0))
      refuse(at, std::string("'") + key + "' is not a non-negative integer");
    return f->get<uint64_t>();
  }

  void check_view(const std::string& at, const json& view) const {
    if (!view.is_object()) return;
    const json* buffer = view.contains("buffer") ? lookup("buffers", view["buffer"]) : nullptr;
    if (!buffer || !buffer->is_object()) return;  // assimp refuses a view without a buffer
    const uint64_t offset = count_field(at, view, "byteOffset", 0), length = count_field(at, view, "byteLength", 0);
    const uint64_t buffer_length = count_field(at, *buffer, "byteLength", 0);
    if (static_cast<unsigned __int128>(offset) + length > buffer_length)
      refuse(at, "bytes " + std::to_string(offset) + " to " + std::to_string(offset + length) +
                     " of a buffer of " + std::to_string(buffer_length) + " (assimp 5.2.5 would read past it)");
  }

  // One accessor's bytes (its elements, or a sparse part) within the view `view_ref` names.
  void check_span(const std::string& at, const json& view_ref, uint64_t offset, uint64_t count, uint64_t element,
                  uint64_t stride, const char* part) const {
    const json* view = lookup("bufferViews", view_ref);
    if (!view || !view->is_object() || count == 0) return;
    const uint64_t view_length = count_field(at, *view, "byteLength", 0);
    using Wide = unsigned __int128;  // no field's size can make it wrap
    const Wide end = Wide{offset} + Wide{count - 1} * stride + element;
    if (end > view_length)
      refuse(at, std::string(part) + " run past its buffer view of " + std::to_string(view_length) +
                     " bytes (offset " + std::to_string(offset) + ", " + std::to_string(count) + " x " +
                     std::to_string(stride) + " bytes apart; assimp 5.2.5 would read past it)");
  }

  void check_accessor(const std::string& at, const json& accessor) const {
    if (!accessor.is_object()) return;
    const auto type = accessor.find("type");
    const uint64_t n = type != accessor.end() && type->is_string() ? components(type->get<std::string>()) : 0;
    if (type != accessor.end() && n == 0) refuse(at, "type " + type->dump() + " is not a glTF accessor type");
    const auto code = accessor.find("componentType");
    const uint64_t bytes = code != accessor.end() && code->is_number_integer() ? component_bytes(code->get<int64_t>()) : 0;
    if (code != accessor.end() && bytes == 0) refuse(at, "componentType " + code->dump() + " is not a glTF component type");
    if (n == 0 || bytes == 0) return;  // assimp refuses an accessor without them
    const uint64_t element = n * bytes, count = count_field(at, accessor, "count", 0);
    if (accessor.contains("bufferView")) {
      const json* view = lookup("bufferViews", accessor["bufferView"]);
      // The stride: the accessor's in glTF 1, the view's in glTF 2; 0 or none: packed.
      uint64_t stride = count_field(at, accessor, "byteStride", 0);
      if (stride == 0 && view && view->is_object()) stride = count_field(at, *view, "byteStride", 0);
      check_span(at, accessor["bufferView"], count_field(at, accessor, "byteOffset", 0), count, element,
                 stride == 0 ? element : stride, "its elements");
    }
    const auto sparse = accessor.find("sparse");
    if (sparse == accessor.end() || !sparse->is_object()) return;
    const uint64_t sparse_count = count_field(at, *sparse, "count", 0);
    const auto indices = sparse->find("indices"), values = sparse->find("values");
    if (indices != sparse->end() && indices->is_object() && indices->contains("bufferView")) {
      const auto index_code = indices->find("componentType");
      const uint64_t index_bytes =
          index_code != indices->end() && index_code->is_number_integer() ? component_bytes(index_code->get<int64_t>()) : 0;
      if (index_bytes != 0)
        check_span(at, (*indices)["bufferView"], count_field(at, *indices, "byteOffset", 0), sparse_count, index_bytes,
                   index_bytes, "its sparse indices");
    }
    if (values != sparse->end() && values->is_object() && values->contains("bufferView"))
      check_span(at, (*values)["bufferView"], count_field(at, *values, "byteOffset", 0), sparse_count, element, element,
                 "its sparse values");
  }

  const std::string& path_;
  const json& doc_;
  const JsonLines& lines_;
  bool binary_;  // a .glb: the lines are its JSON chunk's
};

}  // namespace

void precheck_gltf(const std::string& path, const std::string& data) {
  const bool binary = data.size() >= 4 && std::string_view(data).substr(0, 4) == "glTF";
  const std::optional<std::string> text = binary ? glb_json(data) : std::optional<std::string>(data);
  if (!text) return;
  check_json_nesting(*text, path);
  const json doc = json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (!doc.is_object()) return;  // not JSON (or not an object): assimp says why
  GltfCheck(path, doc, JsonLines(*text), binary).run();
}

}  // namespace girtd
