#include "rift/io/read_mesh.hpp"

#include <filesystem>

namespace rift {

MeshData read_mesh_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw MeshError(path, 0, "no such file");
  const std::string ext = fs::path(path).extension().string();
  throw MeshError(path, 0, "unknown mesh format '" + ext + "'");
}

}  // namespace rift
