// Helpers shared by the importer tests: temporary mesh files, the counts of a
// G-map, and the same counts computed independently from the element lists.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

#include "rift/io/read_mesh.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/element_faces.hpp"
#include "rift/mesh/map_statistics.hpp"

namespace rift::test {

/// Writes `text` to a file named `name` in a directory of its own for the
/// current test, and returns its path.
inline std::string write_temp(const std::string& name, const std::string& text) {
  const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "rift_io_tests" /
                              (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

/// The shared test meshes, or "" (and the caller skips) where they are absent.
inline std::string shared_mesh(const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(RIFT_SHARED_MESHES) / name;
  return std::filesystem::exists(path) ? path.string() : std::string();
}

struct Counts {
  std::size_t darts = 0, vertices = 0, edges = 0, faces = 0, volumes = 0, components = 0,
              boundary = 0;
  bool operator==(const Counts&) const = default;
};

inline std::ostream& operator<<(std::ostream& os, const Counts& c) {
  return os << "darts=" << c.darts << " vertices=" << c.vertices << " edges=" << c.edges
            << " faces=" << c.faces << " volumes=" << c.volumes << " components=" << c.components
            << " boundary=" << c.boundary;
}

inline Counts counts_of(const GMap& map) {
  const MapStatistics s = compute_statistics(map);
  return {s.darts, s.vertices, s.edges, s.faces, s.volumes, s.components, s.boundary};
}

/// Counts for a manifold mesh, derived from the element lists alone: distinct
/// points, edges and faces as sorted vertex sets, boundary entities used by one
/// element, components by union-find over elements that share a side. Darts:
/// two per edge of each polygon (2D) or of each face of each solid (3D).
inline Counts expected_counts(const MeshData& mesh) {
  Counts c;
  std::set<std::uint32_t> points;
  std::set<std::array<std::uint32_t, 2>> edges;
  std::map<std::vector<std::uint32_t>, std::vector<std::size_t>> sides;  // side -> elements
  auto add_edge = [&](std::uint32_t a, std::uint32_t b) {
    edges.insert({std::min(a, b), std::max(a, b)});
  };
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const MeshElement& el = mesh.elements[e];
    const std::uint32_t* v = mesh.vertices_of(el);
    points.insert(v, v + el.count);
    if (mesh.dimension == 2) {
      c.darts += 2 * el.count;
      for (std::uint32_t i = 0; i < el.count; ++i) {
        const std::uint32_t a = v[i], b = v[(i + 1) % el.count];
        add_edge(a, b);
        sides[{std::min(a, b), std::max(a, b)}].push_back(e);
      }
      continue;
    }
    for (const LocalFace& f : element_faces(el.type)) {
      c.darts += 2 * f.count;
      std::vector<std::uint32_t> face;
      for (int i = 0; i < f.count; ++i) {
        face.push_back(v[f.v[static_cast<std::size_t>(i)]]);
        add_edge(v[f.v[static_cast<std::size_t>(i)]],
                 v[f.v[static_cast<std::size_t>((i + 1) % f.count)]]);
      }
      std::sort(face.begin(), face.end());
      sides[face].push_back(e);
    }
  }
  std::vector<std::size_t> parent(mesh.elements.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](std::size_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [side, users] : sides) {
    if (users.size() == 1) ++c.boundary;
    for (std::size_t u = 1; u < users.size(); ++u)
      parent[root(users[u])] = root(users[0]);
  }
  for (std::size_t e = 0; e < parent.size(); ++e)
    c.components += root(e) == e ? 1 : 0;
  c.vertices = points.size();
  c.edges = edges.size();
  if (mesh.dimension == 2) {
    c.faces = mesh.elements.size();
  } else {
    c.faces = sides.size();
    c.volumes = mesh.elements.size();
  }
  return c;
}

/// Reads and assembles `path`, expecting a MeshError whose text starts with
/// "path:line: error: " (or "path: error: " for line 0) and contains `problem`.
inline void expect_mesh_error(const std::string& path, int line, const std::string& problem) {
  try {
    const MeshData mesh = read_mesh_file(path);
    assemble_gmap(mesh);
    ADD_FAILURE() << path << ": expected an error containing '" << problem << "', got none";
  } catch (const MeshError& e) {
    const std::string prefix =
        path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": error: ";
    const std::string what = e.what();
    EXPECT_EQ(what.substr(0, prefix.size()), prefix) << what;
    EXPECT_NE(what.find(problem), std::string::npos) << "'" << problem << "' not in: " << what;
    EXPECT_EQ(e.line(), line) << what;
  } catch (const std::exception& e) {
    ADD_FAILURE() << path << ": expected a MeshError, got " << typeid(e).name() << ": " << e.what();
  }
}

/// Writes `text` as `name` and expects the error described above.
inline void expect_broken(const std::string& name, const std::string& text, int line,
                          const std::string& problem) {
  SCOPED_TRACE(name);
  expect_mesh_error(write_temp(name, text), line, problem);
}

/// Reads, assembles and checks validity; returns the counts.
inline Counts read_counts(const std::string& path, AssemblyReport* report = nullptr) {
  const MeshData mesh = read_mesh_file(path);
  const GMap map = assemble_gmap(mesh, report);
  EXPECT_EQ(map.check_validity(), std::vector<std::string>{}) << path;
  return counts_of(map);
}

}  // namespace rift::test
