// girtd_assimp_import FILE: assimp's import of FILE and nothing else
// (Assimp::Importer::ReadFile with no post-processing), the yardstick
// `girtd bench --scale` times the front door against. Prints the meshes'
// triangle count so that a run that read nothing is seen.
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: girtd_assimp_import FILE\n");
    return 2;
  }
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(argv[1], 0);
  if (!scene) {
    std::fprintf(stderr, "%s: %s\n", argv[1], importer.GetErrorString());
    return 2;
  }
  unsigned long long faces = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) faces += scene->mMeshes[i]->mNumFaces;
  std::printf("%llu\n", faces);
  return 0;
}
