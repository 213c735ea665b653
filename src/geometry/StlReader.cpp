#include "geometry/StlReader.hpp"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace ondine::geometry {

TriangleMesh read_stl(const std::string& file) {
  if (std::filesystem::is_directory(file)) throw GeometryError("'" + file + "' is a folder; expected a binary or ASCII STL file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw GeometryError("cannot open '" + file + "'");
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) throw GeometryError("'" + file + "' is empty; expected a binary or ASCII STL file");
  // From memory with the hint "stl": assimp's STL reader whatever the file's extension.
  // No post-processing: in particular no joining of vertices, which we do ourselves
  // so that repeated triangles stay visible to the checks.
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, "stl");
  if (!scene) {
    std::string why = importer.GetErrorString();
    if (why.empty()) why = "unknown error";
    // assimp names the in-memory file by its magic name, and may quote the whole rest of the file
    const std::string magic = "$$$___magic___$$$.stl";
    for (auto at = why.find(magic); at != std::string::npos; at = why.find(magic)) why.replace(at, magic.size(), file);
    if (why.size() > 240) why = why.substr(0, 240) + "...";
    while (!why.empty() && (why.back() == '.' || why.back() == ' ')) why.pop_back();
    const std::string head(bytes.begin(), bytes.begin() + std::min<std::size_t>(bytes.size(), 5));
    if (head != "solid" && bytes.size() >= 84) {
      const std::uint32_t n = static_cast<std::uint8_t>(bytes[80]) | static_cast<std::uint8_t>(bytes[81]) << 8 |
                              static_cast<std::uint8_t>(bytes[82]) << 16 | static_cast<std::uint32_t>(static_cast<std::uint8_t>(bytes[83])) << 24;
      if (bytes.size() != 84 + 50 * static_cast<std::uint64_t>(n))
        why += "; as binary STL its header announces " + std::to_string(n) + " triangles, i.e. " +
               std::to_string(84 + 50 * static_cast<std::uint64_t>(n)) + " bytes, but it has " + std::to_string(bytes.size());
    }
    throw GeometryError("'" + file + "' cannot be read as STL (assimp: " + why +
                        "); expected a binary STL (80-byte header, triangle count, 50 bytes per triangle) or an ASCII "
                        "STL ('solid ... facet normal ... outer loop, vertex x y z ... endloop endfacet ... endsolid')");
  }
  std::vector<Point> corners;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* mesh = scene->mMeshes[i];
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3)
        throw GeometryError("'" + file + "': facet " + std::to_string(corners.size() / 3) + " (0-based) has " +
                            std::to_string(face.mNumIndices) + " vertices; expected 3");
      for (unsigned k = 0; k < 3; ++k) {
        const aiVector3D& v = mesh->mVertices[face.mIndices[k]];
        corners.push_back({v.x, v.y, v.z});
      }
    }
  }
  if (corners.empty()) throw GeometryError("'" + file + "' holds no triangles; expected a surface");
  TriangleMesh soup;
  soup.vertices = corners;
  return weld(corners, 1e-9 * bounding_box_diagonal(soup));
}

}  // namespace ondine::geometry
