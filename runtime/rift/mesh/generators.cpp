#include "rift/mesh/generators.hpp"

#include <charconv>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rift/core/huge_pages.hpp"

namespace rift {

const char* const kGeneratorHelp =
    "  grid:quad:NxM     N by M quads over the unit square (2D map)\n"
    "  grid:tri:NxM      the same grid, each quad split into two triangles\n"
    "  grid:mix:NxM      the same grid, every other quad split (the paper's Mix mesh)\n"
    "  block:hex:NxMxK   N by M by K hexahedra over the unit cube (3D map)\n"
    "  block:tet:NxMxK   the same block, each cube split into six tetrahedra\n";

namespace {

constexpr int kMaxCells = 1 << 24;

void check_counts(std::initializer_list<int> counts) {
  long long total = 1;
  for (int c : counts) {
    if (c < 1) throw std::invalid_argument("cell counts must be at least 1");
    total *= c;
    if (total > kMaxCells) throw std::invalid_argument("too many cells (at most 16777216)");
  }
}

}  // namespace

MeshData make_grid(GridKind kind, int nx, int ny) {
  check_counts({nx, ny});
  MeshData mesh;
  mesh.dimension = 2;
  const char* names[] = {"quad", "tri", "mix"};
  mesh.source = "grid:" + std::string(names[static_cast<int>(kind)]) + ":" + std::to_string(nx) +
                "x" + std::to_string(ny);
  reserve_huge(mesh.points, static_cast<std::size_t>(nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      mesh.points.emplace_back(Real(i) / nx, Real(j) / ny, 0.0);
    }
  }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
  reserve_huge(mesh.elements, static_cast<std::size_t>(nx) * ny * 2);
  reserve_huge(mesh.element_vertices, static_cast<std::size_t>(nx) * ny * 6);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      const bool split = kind == GridKind::Tri || (kind == GridKind::Mix && (i + j) % 2 == 0);
      if (split) {
        mesh.add_element(ElementType::Polygon, {a, b, c});
        mesh.add_element(ElementType::Polygon, {a, c, d});
      } else {
        mesh.add_element(ElementType::Polygon, {a, b, c, d});
      }
    }
  }
  return mesh;
}

MeshData make_block(BlockKind kind, int nx, int ny, int nz) {
  check_counts({nx, ny, nz});
  MeshData mesh;
  mesh.dimension = 3;
  mesh.source = std::string("block:") + (kind == BlockKind::Hex ? "hex:" : "tet:") +
                std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz);
  // Sized once, advised for huge pages: grown by doubling, a 10^6-element
  // block's arrays were copied ~20 times and faulted in 4 KiB at a time.
  const std::size_t cells = static_cast<std::size_t>(nx) * ny * nz;
  const std::size_t per_cell = kind == BlockKind::Hex ? 1 : 6;
  reserve_huge(mesh.points, static_cast<std::size_t>(nx + 1) * (ny + 1) * (nz + 1));
  reserve_huge(mesh.elements, cells * per_cell);
  reserve_huge(mesh.element_vertices, cells * (kind == BlockKind::Hex ? 8 : 24));
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) {
        mesh.points.emplace_back(Real(i) / nx, Real(j) / ny, Real(k) / nz);
      }
    }
  }
  auto id = [&](int i, int j, int k) {
    return static_cast<std::uint32_t>((k * (ny + 1) + j) * (nx + 1) + i);
  };
  // The six axis orders of the Kuhn subdivision: a tetrahedron walks from the
  // cube's corner (0,0,0) to (1,1,1) adding one axis at a time.
  static constexpr int kAxisOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                            {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        if (kind == BlockKind::Hex) {
          mesh.add_element(
              ElementType::Hexa,
              {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
               id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
          continue;
        }
        for (const auto& axes : kAxisOrders) {
          int c[3] = {i, j, k};
          std::uint32_t v[4];
          v[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[axes[s]];
            v[s + 1] = id(c[0], c[1], c[2]);
          }
          // Odd axis permutations give negatively oriented tetrahedra.
          const bool odd = (axes[0] > axes[1]) ^ (axes[0] > axes[2]) ^ (axes[1] > axes[2]);
          if (odd) std::swap(v[1], v[2]);
          mesh.add_element(ElementType::Tetra, v, v + 4);
        }
      }
    }
  }
  return mesh;
}

bool is_generator_spec(std::string_view spec) {
  return spec.starts_with("grid:") || spec.starts_with("block:");
}

namespace {

std::vector<int> parse_counts(std::string_view text, std::size_t expected, std::string_view spec) {
  std::vector<int> counts;
  std::size_t pos = 0;
  while (true) {
    int value = 0;
    const char* begin = text.data() + pos;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr == begin) {
      throw std::invalid_argument("'" + std::string(spec) + "': expected " +
                                  (expected == 2 ? "NxM" : "NxMxK") +
                                  " cell counts after the kind");
    }
    counts.push_back(value);
    pos = static_cast<std::size_t>(ptr - text.data());
    if (pos == text.size()) break;
    if (text[pos] != 'x') {
      throw std::invalid_argument("'" + std::string(spec) + "': unexpected '" +
                                  std::string(1, text[pos]) + "' in the cell counts");
    }
    ++pos;
  }
  if (counts.size() != expected) {
    throw std::invalid_argument("'" + std::string(spec) + "': expected " +
                                std::to_string(expected) + " cell counts, got " +
                                std::to_string(counts.size()));
  }
  return counts;
}

}  // namespace

namespace {

/// What a generator spelling names: a grid or a block, its kind and counts.
struct GeneratorSpec {
  bool grid = true;
  GridKind grid_kind = GridKind::Quad;
  BlockKind block_kind = BlockKind::Hex;
  std::vector<int> counts;
};

GeneratorSpec parse_generator_spec(std::string_view spec) {
  const std::size_t c1 = spec.find(':');
  const std::size_t c2 = c1 == std::string_view::npos ? c1 : spec.find(':', c1 + 1);
  if (c2 == std::string_view::npos) {
    throw std::invalid_argument("'" + std::string(spec) +
                                "' is not a generator spelling such as grid:quad:10x10");
  }
  const std::string_view family = spec.substr(0, c1);
  const std::string_view kind = spec.substr(c1 + 1, c2 - c1 - 1);
  const std::string_view counts = spec.substr(c2 + 1);
  if (family == "grid") {
    GridKind k;
    if (kind == "quad") {
      k = GridKind::Quad;
    } else if (kind == "tri") {
      k = GridKind::Tri;
    } else if (kind == "mix") {
      k = GridKind::Mix;
    } else {
      throw std::invalid_argument("'" + std::string(spec) + "': unknown grid kind '" +
                                  std::string(kind) + "' (quad, tri or mix)");
    }
    return GeneratorSpec{true, k, BlockKind::Hex, parse_counts(counts, 2, spec)};
  }
  if (family == "block") {
    BlockKind k;
    if (kind == "hex") {
      k = BlockKind::Hex;
    } else if (kind == "tet") {
      k = BlockKind::Tet;
    } else {
      throw std::invalid_argument("'" + std::string(spec) + "': unknown block kind '" +
                                  std::string(kind) + "' (hex or tet)");
    }
    return GeneratorSpec{false, GridKind::Quad, k, parse_counts(counts, 3, spec)};
  }
  throw std::invalid_argument("'" + std::string(spec) + "': unknown generator '" +
                              std::string(family) + "' (grid or block)");
}

}  // namespace

void check_generator_spec(std::string_view spec) {
  const std::vector<int> n = parse_generator_spec(spec).counts;
  if (n.size() == 2) {
    check_counts({n[0], n[1]});
  } else {
    check_counts({n[0], n[1], n[2]});
  }
}

MeshData make_generated_mesh(std::string_view spec) {
  const GeneratorSpec g = parse_generator_spec(spec);
  const std::vector<int>& n = g.counts;
  return g.grid ? make_grid(g.grid_kind, n[0], n[1]) : make_block(g.block_kind, n[0], n[1], n[2]);
}

}  // namespace rift
