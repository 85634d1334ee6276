#include "rift/io/read_mesh.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "rift/io/readers.hpp"

namespace rift {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string read_whole_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw MeshError(path, 0, "cannot open the file");
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw MeshError(path, 0, "cannot read the file");
  return std::move(text).str();
}

}  // namespace

MeshData read_mesh_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw MeshError(path, 0, "no such file");
  if (fs::is_directory(path, ec)) throw MeshError(path, 0, "is a directory, not a mesh file");
  const std::string ext = lower(fs::path(path).extension().string());
  MeshData (*reader)(const std::string&, std::string_view) = nullptr;
  if (ext == ".obj") {
    reader = io::read_obj;
  } else if (ext == ".msh") {
    reader = io::read_gmsh;
  } else if (ext == ".mesh") {
    reader = io::read_medit;
  } else if (ext == ".vtk") {
    reader = io::read_vtk_legacy;
  } else if (ext == ".vtu") {
    reader = io::read_vtu;
  } else if (ext == ".meshb") {
    throw MeshError(path, 0, "binary Medit files (.meshb) are not supported; save as .mesh");
  } else {
    throw MeshError(path, 0,
                    "unknown mesh format '" + ext + "' (rift reads .obj, .msh, .mesh, .vtk, .vtu)");
  }
  const std::string text = read_whole_file(path);
  if (std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c) != 0; })) {
    throw MeshError(path, 0, "the file is empty");
  }
  return reader(path, text);
}

}  // namespace rift
