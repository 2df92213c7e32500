// The model import's child process (sim/io/import_child.hpp): whatever the
// importer does inside it, this process gets the mesh or one error line
// naming the file, and goes on.
#include <catch2/catch.hpp>

#include <csignal>
#include <functional>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "io/import_child.hpp"

using namespace girtd;

namespace {

constexpr ImportLimits kSmall{2.0, uint64_t(512) << 20};

std::string error_of(const std::function<Mesh(std::vector<std::string>&)>& import) {
  std::vector<std::string> warnings;
  try {
    import_in_child("model.glb", kSmall, import, warnings);
  } catch (const InputError& e) {
    return e.formatted();
  }
  return "";
}

}  // namespace

TEST_CASE("model import child: the mesh and the warnings come back as made", "[frontend]") {
  std::vector<std::string> warnings = {"before"};
  const Mesh got = import_in_child("m.obj", kSmall, [](std::vector<std::string>& w) {
    w.push_back("m.obj: a warning");
    Mesh m;
    m.positions = {{0, 0, 0}, {1.5, 0, -2}, {0, 1e-300, 3}, {1, 1, 1}};
    m.polygons = {{0, 1, 2}, {0, 2, 3, 1}};
    return m;
  }, warnings);
  CHECK(got.positions == std::vector<Vec3>{{0, 0, 0}, {1.5, 0, -2}, {0, 1e-300, 3}, {1, 1, 1}});
  CHECK(got.polygons == std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3, 1}});
  CHECK(warnings == std::vector<std::string>{"before", "m.obj: a warning"});
}

TEST_CASE("model import child: the importer's error keeps its line and byte offset", "[frontend]") {
  CHECK(error_of([](std::vector<std::string>&) -> Mesh { throw InputError("model.glb", 7, "bad accessor"); }) ==
        "model.glb:7: bad accessor");
  CHECK(error_of([](std::vector<std::string>&) -> Mesh { throw InputError::at_byte("model.glb", 84, "short"); }) ==
        "model.glb:@84: short");
}

TEST_CASE("model import child: a crash, a hang or an exhausted memory is one line", "[frontend]") {
  CHECK(error_of([](std::vector<std::string>&) -> Mesh {
          std::raise(SIGSEGV);
          return {};
        }).rfind("model.glb: cannot read the model: the importer crashed (signal ", 0) == 0);  // 11; 6 under ASan's abort_on_error
  CHECK(error_of([](std::vector<std::string>&) -> Mesh {
          volatile bool forever = true;  // an empty endless loop may be compiled away
          while (forever) {
          }
          return {};
        }) == "model.glb: cannot read the model: the importer took longer than its limit of 2 s (stopped)");
#if !defined(__SANITIZE_ADDRESS__)  // the address-space limit is off under ASan
  CHECK(error_of([](std::vector<std::string>&) -> Mesh {
          std::vector<char> huge(size_t(1) << 30, 1);  // 1 GiB against a 512 MiB limit
          return {};
        }) == "model.glb: cannot read the model: the importer ran out of memory (its limit: 512 MiB more than the "
              "process held)");
#endif
}
