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

std::string error_of(const std::function<ImportedModel(std::vector<std::string>&)>& import) {
  std::vector<std::string> warnings;
  try {
    import_in_child("model.glb", kSmall, import, warnings);
  } catch (const InputError& e) {
    return e.formatted();
  }
  return "";
}

}  // namespace

TEST_CASE("model import child: the model and the warnings come back as made", "[frontend]") {
  std::vector<std::string> warnings = {"before"};
  Surface red;
  red.r = 255, red.g = 0, red.b = 0, red.n = 7, red.t_min = red.t_max = 0.5;
  red.cre = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
  const ImportedModel got = import_in_child("m.obj", kSmall, [&](std::vector<std::string>& w) {
    w.push_back("m.obj: a warning");
    ImportedModel m;
    m.mesh.positions = {{0, 0, 0}, {1.5, 0, -2}, {0, 1e-300, 3}, {1, 1, 1}};
    m.mesh.corners = {0, 1, 2, 0, 2, 3, 1};
    m.mesh.first = {0, 3, 7};
    m.mesh.material = {1, 0};
    m.mesh.corner_colour = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {10, 11, 12}, {13, 14, 15}, {16, 17, 18}, {19, 20, 21}};
    m.materials = {std::nullopt, red};
    m.cameras = {{"cam", {1, 2, 3}, {0, 0, -1}, {0, 1, 0}, 35.5, 0.25, false}};
    m.lights = {{"sun", ModelLightKind::kSpot, {4, 5, 6}, {0, -1, 0}, 2.5, true}};
    return m;
  }, warnings);
  CHECK(got.mesh.positions == std::vector<Vec3>{{0, 0, 0}, {1.5, 0, -2}, {0, 1e-300, 3}, {1, 1, 1}});
  CHECK(got.mesh.corners == std::vector<int>{0, 1, 2, 0, 2, 3, 1});
  CHECK(got.mesh.first == std::vector<uint64_t>{0, 3, 7});
  CHECK(got.mesh.material == std::vector<int>{1, 0});
  REQUIRE(got.mesh.corner_colour.size() == 7);
  CHECK(got.mesh.corner_colour[6].b == 21);
  REQUIRE(got.materials.size() == 2);
  CHECK(!got.materials[0]);
  REQUIRE(got.materials[1]);
  CHECK((got.materials[1]->r == 255 && got.materials[1]->n == 7 && got.materials[1]->t_max == 0.5 &&
         got.materials[1]->cre == red.cre));
  REQUIRE(got.cameras.size() == 1);
  CHECK((got.cameras[0].name == "cam" && got.cameras[0].eye == Vec3{1, 2, 3} && got.cameras[0].fov_deg == 35.5 &&
         got.cameras[0].near == 0.25));
  REQUIRE(got.lights.size() == 1);
  CHECK((got.lights[0].kind == ModelLightKind::kSpot && got.lights[0].position == Vec3{4, 5, 6} &&
         got.lights[0].strength == 2.5 && got.lights[0].coloured));
  CHECK(warnings == std::vector<std::string>{"before", "m.obj: a warning"});
}

TEST_CASE("model import child: the importer's error keeps its line and byte offset", "[frontend]") {
  CHECK(error_of([](std::vector<std::string>&) -> ImportedModel { throw InputError("model.glb", 7, "bad accessor"); }) ==
        "model.glb:7: bad accessor");
  CHECK(error_of([](std::vector<std::string>&) -> ImportedModel { throw InputError::at_byte("model.glb", 84, "short"); }) ==
        "model.glb:@84: short");
}

TEST_CASE("model import child: a crash, a hang or an exhausted memory is one line", "[frontend]") {
  CHECK(error_of([](std::vector<std::string>&) -> ImportedModel {
          std::raise(SIGSEGV);
          return {};
        }).rfind("model.glb: cannot read the model: the importer crashed (signal ", 0) == 0);  // 11; 6 under ASan's abort_on_error
  CHECK(error_of([](std::vector<std::string>&) -> ImportedModel {
          volatile bool forever = true;  // an empty endless loop may be compiled away
          while (forever) {
          }
          return {};
        }) == "model.glb: cannot read the model: the importer took longer than its limit of 2 s (stopped)");
#if !defined(__SANITIZE_ADDRESS__)  // the address-space limit is off under ASan
  CHECK(error_of([](std::vector<std::string>&) -> ImportedModel {
          std::vector<char> huge(size_t(1) << 30, 1);  // 1 GiB against a 512 MiB limit
          return {};
        }) == "model.glb: cannot read the model: the importer ran out of memory (its limit: 512 MiB more than the "
              "process held)");
#endif
}
