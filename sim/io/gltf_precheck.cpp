// The glTF check: every accessor's bytes within its buffer view and every
// view an accessor reads within its buffer, before assimp reads them.
// assimp 5.2.5's glTF 2 reader bounds an accessor's read by its view's length
// but starts it at the accessor's own byteOffset (Accessor::ExtractData), and
// its glTF 1 reader does not bound a view by its buffer: either reads past
// the data, into whatever memory holds (testbench/fuzz/README.md, Findings).
// The rules are the glTF specification's, applied with assimp's reading of
// the file: the stride is the view's (glTF 2) or the accessor's (glTF 1), a
// missing componentType or type is assimp's default (BYTE, SCALAR), and the
// document must be JSON as nlohmann reads it, with no key given twice (where
// parsers differ, assimp's RapidJSON may read other numbers than these).
// A view no accessor reads is not checked: assimp does not read it either.
// Anything else wrong (a missing field, an index out of range) is left to
// assimp, which refuses it with its own message.
#include <cstdint>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json_lines.hpp"
#include "io/model_precheck.hpp"
#include "io/model_tokens.hpp"

namespace girtd {
namespace {

using nlohmann::json;

// A binary glTF's JSON chunk (the first chunk, "JSON"), or nothing where the
// container is not one assimp would read as such (it refuses it itself).
std::optional<std::string> glb_json(std::string_view data) {
  if (data.size() < 20 || data.substr(0, 4) != "glTF" || u32_at(data.data() + 4) != 2) return std::nullopt;
  const uint64_t length = u32_at(data.data() + 12);
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

// The first key given twice in one object (RapidJSON keeps the first, nlohmann
// the last), with the pointer of its object; and whether the text parsed.
class DuplicateKeys : public nlohmann::json_sax<json> {
 public:
  std::optional<std::pair<std::string, std::string>> found;  // object's pointer, key
  std::string error;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    Level& top = levels_.back();
    if (!top.keys.insert(k).second && !found) found = {pointer(levels_.size() - 1), k};
    top.name = k;
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    error = e.what();
    return false;
  }

 private:
  struct Level {
    bool object;
    std::set<std::string> keys;
    std::string name;  // the member's key (object) or the element's index (array) being read
    size_t items = 0;
  };
  bool value() {
    if (!levels_.empty() && !levels_.back().object) levels_.back().name = std::to_string(levels_.back().items++);
    return true;
  }
  bool open(bool object) {
    value();
    levels_.push_back({object, {}, {}, 0});
    return true;
  }
  bool close() {
    levels_.pop_back();
    return true;
  }
  // The pointer of the container at depth `depth` (0: the root).
  std::string pointer(size_t depth) const {
    std::string p;
    for (size_t i = 0; i < depth; ++i) p += "/" + levels_[i].name;
    return p;
  }
  std::vector<Level> levels_;
};

class GltfCheck {
 public:
  GltfCheck(const std::string& path, const json& doc, const JsonLines& lines, bool binary)
      : path_(path), doc_(doc), lines_(lines), binary_(binary) {}

  void run() {
    const auto accessors = doc_.find("accessors");
    if (accessors == doc_.end()) return;
    if (accessors->is_array()) {
      for (size_t i = 0; i < accessors->size(); ++i)
        check_accessor({"/accessors/" + std::to_string(i), "accessor " + std::to_string(i)}, (*accessors)[i], true);
    } else if (accessors->is_object()) {  // glTF 1: keyed by id
      for (const auto& [id, accessor] : accessors->items())
        check_accessor({"/accessors/" + pointer_token(id), "accessor " + id}, accessor, false);
    }
  }

 private:
  struct Place {
    std::string pointer;  // where it is, for its line
    std::string name;     // what the message calls it
  };

  static std::string pointer_token(const std::string& key) {
    std::string out;
    for (char ch : key) out += ch == '~' ? "~0" : ch == '/' ? "~1" : std::string(1, ch);
    return out;
  }

  [[noreturn]] void refuse(const Place& at, const std::string& what) const {
    const int line = lines_.line(at.pointer);
    if (!binary_) fail(path_, line, at.name + ": " + what);
    fail(path_, 0, at.name + " (line " + std::to_string(line) + " of the JSON chunk): " + what);
  }

  // The member `ref` names in the top-level `collection` (an index in
  // glTF 2, an id in glTF 1) and its place; nothing where there is none.
  std::optional<std::pair<const json*, Place>> lookup(const char* collection, const char* kind, const json& ref) const {
    const auto c = doc_.find(collection);
    if (c == doc_.end()) return std::nullopt;
    const std::string base = std::string("/") + collection + "/";
    if (c->is_array() && ref.is_number_unsigned() && ref.get<uint64_t>() < c->size())
      return std::pair{&(*c)[ref.get<size_t>()], Place{base + std::to_string(ref.get<size_t>()),
                                                       std::string(kind) + " " + std::to_string(ref.get<size_t>())}};
    if (c->is_object() && ref.is_string() && c->contains(ref.get<std::string>()))
      return std::pair{&(*c)[ref.get<std::string>()],
                       Place{base + pointer_token(ref.get<std::string>()), std::string(kind) + " " + ref.get<std::string>()}};
    return std::nullopt;
  }

  // A byte count or offset of `object` (absent: `absent`); anything but a
  // non-negative integer is refused.
  uint64_t byte_field(const Place& at, const json& object, const char* key, uint64_t absent) const {
    const auto f = object.find(key);
    if (f == object.end()) return absent;
    if (!f->is_number_unsigned() && !(f->is_number_integer() && f->get<int64_t>() >= 0))
      refuse(at, std::string("'") + key + "' is " + f->dump() + ", not a non-negative integer");
    return f->get<uint64_t>();
  }

  // The view an accessor reads: within its buffer where the buffer gives its
  // length (glTF 1 need not); its length and the stride it sets (0: none).
  struct View {
    uint64_t length = 0, stride = 0;
  };
  std::optional<View> read_view(const json& ref) const {
    const auto found = lookup("bufferViews", "buffer view", ref);
    if (!found || !found->first->is_object()) return std::nullopt;  // assimp refuses a missing view
    const auto& [view, at] = *found;
    View v{byte_field(at, *view, "byteLength", 0), byte_field(at, *view, "byteStride", 0)};
    const uint64_t offset = byte_field(at, *view, "byteOffset", 0);
    const auto buffer = view->contains("buffer") ? lookup("buffers", "buffer", (*view)["buffer"]) : std::nullopt;
    if (buffer && buffer->first->is_object() && buffer->first->contains("byteLength")) {
      const uint64_t buffer_length = byte_field(buffer->second, *buffer->first, "byteLength", 0);
      if (static_cast<unsigned __int128>(offset) + v.length > buffer_length)
        refuse(at, "bytes " + std::to_string(offset) + " to " + std::to_string(offset + v.length) + " of " +
                       buffer->second.name + " of " + std::to_string(buffer_length) +
                       " bytes (a view lies within its buffer; assimp 5.2.5's glTF 1 reader reads past it)");
    }
    return v;
  }

  // `count` elements of `element` bytes, `stride` apart, from `offset` in the view `ref` names.
  void check_span(const Place& at, const json& ref, uint64_t offset, uint64_t count, uint64_t element,
                  uint64_t stride, const char* part) const {
    const std::optional<View> view = read_view(ref);
    if (!view || count == 0) return;
    using Wide = unsigned __int128;  // no field's size can make it wrap
    if (Wide{offset} + Wide{count - 1} * stride + element > view->length)
      refuse(at, std::string(part) + " run past its buffer view of " + std::to_string(view->length) +
                     " bytes (offset " + std::to_string(offset) + ", " + std::to_string(count) + " x " +
                     std::to_string(stride) + " bytes apart; assimp 5.2.5 would read past it)");
  }

  void check_accessor(const Place& at, const json& accessor, bool gltf2) const {
    if (!accessor.is_object()) return;
    // assimp's defaults where a field is missing: SCALAR, BYTE.
    const auto type = accessor.find("type");
    const uint64_t n = type == accessor.end() ? 1 : type->is_string() ? components(type->get<std::string>()) : 0;
    if (n == 0) refuse(at, "type " + type->dump() + " is not a glTF accessor type");
    const auto code = accessor.find("componentType");
    const uint64_t bytes =
        code == accessor.end() ? 1 : code->is_number_integer() ? component_bytes(code->get<int64_t>()) : 0;
    if (bytes == 0) refuse(at, "componentType " + code->dump() + " is not a glTF component type");
    const uint64_t element = n * bytes, count = byte_field(at, accessor, "count", 0);
    if (accessor.contains("bufferView")) {
      const std::optional<View> view = read_view(accessor["bufferView"]);
      // glTF 2 reads the view's stride, glTF 1 the accessor's; 0 or none: packed.
      const uint64_t stride = gltf2 ? (view ? view->stride : 0) : byte_field(at, accessor, "byteStride", 0);
      if (stride != 0 && stride < element)
        refuse(at, "a stride of " + std::to_string(stride) + " bytes, less than its elements' " +
                       std::to_string(element) + " (glTF asks for at least that; assimp 5.2.5 reads past the view)");
      check_span(at, accessor["bufferView"], byte_field(at, accessor, "byteOffset", 0), count, element,
                 stride == 0 ? element : stride, "its elements");
    }
    const auto sparse = accessor.find("sparse");
    if (sparse == accessor.end() || !sparse->is_object()) return;
    const uint64_t sparse_count = byte_field(at, *sparse, "count", 0);
    const auto indices = sparse->find("indices"), values = sparse->find("values");
    if (indices != sparse->end() && indices->is_object() && indices->contains("bufferView")) {
      const auto index_code = indices->find("componentType");
      const uint64_t index_bytes =
          index_code != indices->end() && index_code->is_number_integer() ? component_bytes(index_code->get<int64_t>()) : 0;
      if (index_bytes != 0)
        check_span(at, (*indices)["bufferView"], byte_field(at, *indices, "byteOffset", 0), sparse_count, index_bytes,
                   index_bytes, "its sparse indices");
    }
    if (values != sparse->end() && values->is_object() && values->contains("bufferView"))
      check_span(at, (*values)["bufferView"], byte_field(at, *values, "byteOffset", 0), sparse_count, element, element,
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
  const std::string where = binary ? " (in its JSON chunk)" : "";
  DuplicateKeys keys;
  if (!json::sax_parse(*text, &keys)) fail(path, 0, "not JSON as glTF asks" + where + ": " + keys.error);
  const json doc = json::parse(*text);
  const JsonLines lines(*text);
  if (keys.found) {
    const int line = lines.line(keys.found->first);
    fail(path, binary ? 0 : line, "the key \"" + keys.found->second + "\" twice in one object" +
                                      (binary ? " (line " + std::to_string(line) + " of the JSON chunk)" : "") +
                                      " (assimp 5.2.5 reads the first, this check the last)");
  }
  if (!doc.is_object()) return;  // assimp says why
  GltfCheck(path, doc, lines, binary).run();
}

}  // namespace girtd
