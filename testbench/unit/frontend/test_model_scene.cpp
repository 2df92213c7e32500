// A model file's materials, lights and camera on GIRTD's model
// (sim/io/model_materials.hpp, sim/io/model_lights.hpp), against values
// worked out by hand from the rules in sim/io/README.md.
#include <catch2/catch.hpp>

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/model_lights.hpp"
#include "io/model_materials.hpp"

using namespace girtd;

namespace {

// A scene holding the given materials (it owns and frees them).
struct MaterialScene {
  aiScene scene;
  explicit MaterialScene(std::vector<aiMaterial*> materials) {
    scene.mNumMaterials = static_cast<unsigned>(materials.size());
    scene.mMaterials = new aiMaterial*[materials.size()];
    for (size_t i = 0; i < materials.size(); ++i) scene.mMaterials[i] = materials[i];
  }
};

aiMaterial* material(const std::string& name) {
  auto* m = new aiMaterial;
  aiString s(name);
  m->AddProperty(&s, AI_MATKEY_NAME);
  return m;
}

bool has(const std::vector<std::string>& lines, const std::string& part) {
  for (const std::string& l : lines)
    if (l.find(part) != std::string::npos) return true;
  return false;
}

ModelLight light(ModelLightKind kind, Vec3 position, Vec3 direction, double strength) {
  ModelLight l;
  l.kind = kind, l.position = position, l.direction = direction, l.strength = strength;
  return l;
}

}  // namespace

TEST_CASE("model materials: colour, shininess, roughness and opacity", "[frontend]") {
  aiMaterial* plain = material("plain");
  const aiColor4D orange(1.0f, 0.5f, 0.0f, 1.0f);
  plain->AddProperty(&orange, 1, AI_MATKEY_COLOR_DIFFUSE);
  const float shiny = 300;  // above the hardware's n = 200
  plain->AddProperty(&shiny, 1, AI_MATKEY_SHININESS);

  aiMaterial* rough = material("rough");
  const float roughness = 0.5f;  // n = 2 / 0.5^4 - 2 = 30
  rough->AddProperty(&roughness, 1, AI_MATKEY_ROUGHNESS_FACTOR);
  const float made_up_shininess = 250;  // assimp's glTF reader writes (1 - r)^2 x 1000 beside it
  rough->AddProperty(&made_up_shininess, 1, AI_MATKEY_SHININESS);
  const float quarter = 0.25f;  // opacity 0.25: Tf = 0.75 at every angle
  rough->AddProperty(&quarter, 1, AI_MATKEY_OPACITY);

  aiMaterial* invisible = material("invisible");
  const float zero = 0;
  invisible->AddProperty(&zero, 1, AI_MATKEY_OPACITY);

  // glTF: alpha is a transparency in BLEND mode only.
  const aiColor4D half_alpha(1.0f, 1.0f, 1.0f, 0.5f);
  aiMaterial* opaque_mode = material("opaque_mode");
  opaque_mode->AddProperty(&half_alpha, 1, AI_MATKEY_BASE_COLOR);
  aiString opaque("OPAQUE");
  opaque_mode->AddProperty(&opaque, AI_MATKEY_GLTF_ALPHAMODE);
  aiMaterial* blend_mode = material("blend_mode");
  blend_mode->AddProperty(&half_alpha, 1, AI_MATKEY_BASE_COLOR);
  aiString blend("BLEND");
  blend_mode->AddProperty(&blend, AI_MATKEY_GLTF_ALPHAMODE);

  MaterialScene s({plain, rough, invisible, material(AI_DEFAULT_MATERIAL_NAME), opaque_mode, blend_mode});
  ModelLook look(s.scene, "/nowhere/model.obj");
  const auto& got = look.surfaces();
  REQUIRE(got.size() == 6);
  REQUIRE(got[0]);
  CHECK(got[0]->r == Approx(255));
  CHECK(got[0]->g == Approx(127.5));
  CHECK(got[0]->b == Approx(0));
  CHECK(got[0]->n == Approx(200));
  CHECK(got[0]->t_min == 0);  // opaque: T = 0 (the default)
  REQUIRE(got[1]);
  CHECK(got[1]->r == Approx(200));  // no colour given: the default grey
  CHECK(got[1]->n == Approx(30));
  CHECK(got[1]->t_min == Approx(0.75));
  CHECK(got[1]->t_max == Approx(0.75));
  REQUIRE(got[2]);
  CHECK(got[2]->t_max == 0);  // opacity 0 is drawn opaque
  CHECK_FALSE(got[3]);        // assimp's filler: the scene's default material
  REQUIRE(got[4]);
  CHECK(got[4]->t_max == 0);
  REQUIRE(got[5]);
  CHECK(got[5]->t_min == Approx(0.5));
  CHECK(got[5]->t_max == Approx(0.5));
  const std::vector<std::string> notes = look.warnings();
  CHECK(has(notes, "roughness sets the specular exponent"));
  CHECK(has(notes, "opacity 0 (invisible) is drawn opaque"));

  // OFF, PLY and STL hold no materials: the unnamed grey assimp adds is not the file's.
  MaterialScene off({material("")});
  CHECK_FALSE(ModelLook(off.scene, "/nowhere/model.off").surfaces()[0]);
  CHECK(ModelLook(off.scene, "/nowhere/model.dae").surfaces()[0]);
}

TEST_CASE("model materials: a texture's mean over a face", "[frontend]") {
  // An embedded raw 2 x 1 texture, red left, blue right (texels are BGRA).
  auto* tex = new aiTexture;
  tex->mWidth = 2, tex->mHeight = 1;
  tex->pcData = new aiTexel[2];
  tex->pcData[0] = aiTexel{0, 0, 255, 255};
  tex->pcData[1] = aiTexel{255, 0, 0, 255};
  aiMaterial* m = material("textured");
  aiString path("*0");
  m->AddProperty(&path, AI_MATKEY_TEXTURE_DIFFUSE(0));
  MaterialScene s({m, material("untextured")});
  s.scene.mNumTextures = 1;
  s.scene.mTextures = new aiTexture*[1]{tex};
  ModelLook look(s.scene, "/nowhere/model.obj");

  auto mean = [&](unsigned mat, std::vector<aiVector3D> uv) { return look.texture_mean(mat, uv); };
  // A face over the left half: red only.
  auto left = mean(0, {{0.05f, 0.1f, 0}, {0.45f, 0.1f, 0}, {0.45f, 0.9f, 0}, {0.05f, 0.9f, 0}});
  REQUIRE(left);
  CHECK(left->r == Approx(1));
  CHECK(left->b == Approx(0));
  // Over the whole texture: half and half, within the 9 samples per triangle
  // (the diagonal's samples fall 4 : 5 on either side at worst).
  auto whole = mean(0, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  REQUIRE(whole);
  CHECK(whole->r == Approx(0.5).margin(0.12));
  CHECK(whole->r + whole->b == Approx(1));
  CHECK(whole->g == 0);
  // Coordinates outside 0..1 repeat: u 1.05..1.45 is the left half again.
  auto wrapped = mean(0, {{1.05f, 0.1f, 0}, {1.45f, 0.1f, 0}, {1.45f, 0.9f, 0}});
  REQUIRE(wrapped);
  CHECK(wrapped->r == Approx(1));
  CHECK_FALSE(mean(1, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}));  // no texture
  CHECK(has(look.warnings(), "textures are drawn as their mean colour"));
}

TEST_CASE("model lights: directions and intensities normalised to the default light", "[frontend]") {
  std::vector<std::string> warnings;
  // A directional light shining down -y (toward the light: +y), strength 1,
  // and a point light at (0, 0, 10) over a scene centred at (0, 0, 2),
  // strength 3: toward +z. Together 0.75: 0.1875 and 0.5625.
  auto set = map_model_lights({light(ModelLightKind::kDirectional, {}, {0, -1, 0}, 1),
                               light(ModelLightKind::kPoint, {0, 0, 10}, {}, 3)},
                              {0, 0, 2}, "m.gltf", warnings);
  REQUIRE(set);
  CHECK(set->ambient == Approx(0.25));
  REQUIRE(set->directional.size() == 2);
  CHECK(set->directional[0].toward.y == Approx(1));
  CHECK(set->directional[0].intensity == Approx(0.1875));
  CHECK(set->directional[1].toward.z == Approx(1));
  CHECK(set->directional[1].intensity == Approx(0.5625));
  CHECK(warnings.empty());
}

TEST_CASE("model lights: what cannot be used is warned, never drawn wrong", "[frontend]") {
  std::vector<std::string> warnings;
  ModelLight coloured = light(ModelLightKind::kSpot, {3, 4, 0}, {-1, 0, 0}, 2);
  coloured.coloured = true;
  auto set = map_model_lights({light(ModelLightKind::kAmbient, {}, {}, 1), light(ModelLightKind::kPoint, {}, {}, 5),
                               coloured},
                              {0, 0, 0}, "m.fbx", warnings);
  REQUIRE(set);
  REQUIRE(set->directional.size() == 1);  // the ambient and the point at the centre are left out
  CHECK(set->directional[0].toward.x == Approx(0.6));
  CHECK(set->directional[0].toward.y == Approx(0.8));
  CHECK(set->directional[0].intensity == Approx(0.75));
  CHECK(has(warnings, "m.fbx: ambient lights are not taken"));
  CHECK(has(warnings, "m.fbx: a light with no direction toward the scene"));
  CHECK(has(warnings, "m.fbx: spot lights' cones are not modelled"));
  CHECK(has(warnings, "m.fbx: light colours are dropped"));

  warnings.clear();
  CHECK_FALSE(map_model_lights({light(ModelLightKind::kAmbient, {}, {}, 1)}, {}, "a.dae", warnings));
  CHECK(has(warnings, "a.dae: none of its lights can be used"));
  warnings.clear();
  CHECK_FALSE(map_model_lights({}, {}, "none.obj", warnings));
  CHECK(warnings.empty());  // no lights: the default, silently
}

TEST_CASE("model lights: more than a trace holds keeps the brightest", "[frontend]") {
  std::vector<ModelLight> lights;
  for (int i = 0; i < 65; ++i) lights.push_back(light(ModelLightKind::kDirectional, {}, {0, 0, -1}, i == 7 ? 0.5 : 1));
  std::vector<std::string> warnings;
  auto set = map_model_lights(lights, {}, "many.dae", warnings);
  REQUIRE(set);
  REQUIRE(set->directional.size() == 64);  // light 7, the weakest, left out; the rest share 0.75
  for (const DirectionalLight& d : set->directional) CHECK(d.intensity == Approx(0.75 / 64));
  CHECK(has(warnings, "many.dae: 65 lights: the 64 brightest are drawn"));
}

TEST_CASE("model camera: field of view clamped, an up along the view replaced", "[frontend]") {
  ModelCamera c;
  c.eye = {0, 0, 5}, c.forward = {0, 0, -1}, c.up = {0, 0, 1};  // up along the view
  c.fov_deg = 90;
  auto cam = map_model_camera(c);
  REQUIRE(cam);
  CHECK(cam->forward.z == Approx(-1));
  CHECK(cam->up.y == Approx(1));  // the first replacement, +y
  CHECK(cam->d_over_s == Approx(1));  // 1 / tan(45 deg)
  c.fov_deg = 400;
  REQUIRE(map_model_camera(c));
  CHECK(map_model_camera(c)->d_over_s == Approx(1 / std::tan(85 * M_PI / 180)));
  c.forward = {0, 0, 0};
  CHECK_FALSE(map_model_camera(c));
}
