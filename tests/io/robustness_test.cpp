// Cut and corrupted input: whatever the damage, a reader returns a mesh that
// assembles, or throws a MeshError. No other exception, no crash, no hang.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "io_test_support.hpp"
#include "rift/io/readers.hpp"
#include "shapes.hpp"
#include "shared_test_data.hpp"

namespace rift::test {
namespace {

using Reader = MeshData (*)(const std::string&, std::string_view);

Reader reader_for(const std::string& name) {
  const std::string ext = name.substr(name.rfind('.') + 1);
  if (ext == "obj") return io::read_obj;
  if (ext == "msh") return io::read_gmsh;
  if (ext == "mesh") return io::read_medit;
  if (ext == "vtk") return io::read_vtk_legacy;
  return io::read_vtu;
}

// Returns "" when the text reads and assembles, else the MeshError's text.
// Anything else thrown fails the test.
std::string outcome(Reader read, const std::string& name, std::string_view text) {
  try {
    const MeshData mesh = read(name, text);
    const GMap map = assemble_gmap(mesh);
    EXPECT_TRUE(map.is_valid()) << name;
    return "";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << name << ": " << typeid(e).name() << ": " << e.what();
    return "";
  }
}

std::vector<std::pair<std::string, std::string>> small_files() {
  std::vector<std::pair<std::string, std::string>> files;
  for (const Shape& s : shapes()) {
    if (s.dimension == 2) files.emplace_back(s.name + ".obj", to_obj(s));
    files.emplace_back(s.name + "_1.msh", to_gmsh12(s, 1));
    files.emplace_back(s.name + "_2.msh", to_gmsh12(s, 2));
    files.emplace_back(s.name + "_4.msh", to_gmsh41(s));
    files.emplace_back(s.name + ".mesh", to_medit(s));
    files.emplace_back(s.name + ".vtk", to_vtk(s, false));
    files.emplace_back(s.name + "_5.vtk", to_vtk(s, true));
    files.emplace_back(s.name + ".vtu", to_vtu(s));
  }
  return files;
}

TEST(Robustness, EveryPrefixOfTheSmallFiles) {
  for (const auto& [name, text] : small_files()) {
    const Reader read = reader_for(name);
    for (std::size_t cut = 0; cut < text.size(); ++cut) {
      SCOPED_TRACE(name + " cut at byte " + std::to_string(cut));
      outcome(read, name, std::string_view(text).substr(0, cut));
    }
  }
}

TEST(Robustness, RandomByteDamageToTheSmallFiles) {
  std::mt19937 rng(12345);
  const std::string alphabet = "0123456789 \n-+.eE$#/abcnaif\x01\xff";
  for (const auto& [name, text] : small_files()) {
    const Reader read = reader_for(name);
    for (int trial = 0; trial < 200; ++trial) {
      std::string damaged = text;
      const int edits = 1 + static_cast<int>(rng() % 3);
      for (int e = 0; e < edits; ++e) {
        const std::size_t at = rng() % damaged.size();
        const char c = alphabet[rng() % alphabet.size()];
        switch (rng() % 3) {
          case 0:
            damaged[at] = c;
            break;
          case 1: {
            // Built by appending: GCC 12 misreads string::insert (-Wrestrict).
            std::string grown(damaged, 0, at);
            grown.push_back(c);
            grown.append(damaged, at, std::string::npos);
            damaged = std::move(grown);
            break;
          }
          default:
            damaged.erase(at, 1 + rng() % 8);
        }
        if (damaged.empty()) damaged.push_back(' ');
      }
      SCOPED_TRACE(name + " damage trial " + std::to_string(trial));
      outcome(read, name, damaged);
    }
  }
}

TEST(Robustness, PrefixesOfTheSharedMeshes) {
  RIFT_EXPECT_SHARED_MESHES(!shared_mesh("liver.msh").empty());
  for (const char* file : {"liver.msh", "liver.obj", "cube_low_res.msh", "msh4_cube.msh",
                           "square3.msh", "triangleGrid_10_10.obj", "cube.mesh"}) {
    std::ifstream in(shared_mesh(file), std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    const Reader read = reader_for(file);
    // About a hundred cuts per file, at line ends and in the middle of lines.
    const std::size_t step = std::max<std::size_t>(1, text.size() / 100);
    for (std::size_t cut = 0; cut < text.size(); cut += step) {
      SCOPED_TRACE(std::string(file) + " cut at byte " + std::to_string(cut));
      const std::string message = outcome(read, file, std::string_view(text).substr(0, cut));
      // A cut volume or Gmsh file always loses its closing section or keyword.
      const std::string f = file;
      if (f.ends_with(".msh") || f.ends_with(".mesh")) {
        EXPECT_FALSE(message.empty());
      }
    }
  }
}

}  // namespace
}  // namespace rift::test
