#include "rift/io/vtk_cells.hpp"

#include <array>
#include <string>

namespace rift::io {

namespace {

enum VtkType : std::int64_t {
  kVertex = 1,
  kPolyVertex = 2,
  kLine = 3,
  kPolyLine = 4,
  kTriangle = 5,
  kTriangleStrip = 6,
  kPolygon = 7,
  kPixel = 8,
  kQuad = 9,
  kTetra = 10,
  kVoxel = 11,
  kHexahedron = 12,
  kWedge = 13,
  kPyramid = 14,
};

struct Fixed {
  std::size_t points;
  ElementType type;
  const char* name;
};

bool fixed_type(std::int64_t code, Fixed& out) {
  switch (code) {
    case kTriangle:
      out = {3, ElementType::Polygon, "triangle"};
      return true;
    case kPixel:
      out = {4, ElementType::Polygon, "pixel"};
      return true;
    case kQuad:
      out = {4, ElementType::Polygon, "quad"};
      return true;
    case kTetra:
      out = {4, ElementType::Tetra, "tetra"};
      return true;
    case kVoxel:
      out = {8, ElementType::Hexa, "voxel"};
      return true;
    case kHexahedron:
      out = {8, ElementType::Hexa, "hexahedron"};
      return true;
    case kWedge:
      out = {6, ElementType::Wedge, "wedge"};
      return true;
    case kPyramid:
      out = {5, ElementType::Pyramid, "pyramid"};
      return true;
    default:
      return false;
  }
}

}  // namespace

std::uint32_t vtk_point_id(const TextCursor& in, Token id, std::size_t points, std::size_t cell) {
  return vtk_point_id(in, in.to_integer(id, "a point id"), id.line, points, cell);
}

std::uint32_t vtk_point_id(const TextCursor& in, std::int64_t value, int line, std::size_t points,
                           std::size_t cell) {
  if (value < 0 || value >= static_cast<std::int64_t>(points)) {
    in.fail(line, "cell " + std::to_string(cell) + " refers to point " + std::to_string(value) +
                      ", but the file has " + std::to_string(points) + " points (numbered from 0)");
  }
  return static_cast<std::uint32_t>(value);
}

void add_vtk_cell(const TextCursor& in, ElementCollector& out, Token type_token,
                  std::span<const std::uint32_t> ids, int line, std::size_t cell) {
  add_vtk_cell(in, out, in.to_integer(type_token, "a cell type"), type_token.line, ids, line, cell);
}

void add_vtk_cell(const TextCursor& in, ElementCollector& out, std::int64_t code, int type_line,
                  std::span<const std::uint32_t> ids, int line, std::size_t cell,
                  std::optional<std::int64_t> group) {
  const std::string which = "cell " + std::to_string(cell);
  switch (code) {
    case kVertex:
    case kPolyVertex:
    case kLine:
    case kPolyLine:
      out.ignore_lower_dimensional();
      return;
    case kPolygon:
    case kTriangleStrip:
      if (ids.size() < 3) {
        in.fail(line, which + " (" + (code == kPolygon ? "polygon" : "triangle strip") + ") has " +
                          std::to_string(ids.size()) + " points, at least 3 are needed");
      }
      if (code == kPolygon) {
        out.add(ElementType::Polygon, ids, line, group);
        return;
      }
      // Strip triangle k is (k, k+1, k+2); every other one is flipped so that
      // all of them keep the strip's orientation.
      for (std::size_t k = 0; k + 2 < ids.size(); ++k) {
        const std::array<std::uint32_t, 3> tri = k % 2 == 0
                                                     ? std::array{ids[k], ids[k + 1], ids[k + 2]}
                                                     : std::array{ids[k + 1], ids[k], ids[k + 2]};
        out.add(ElementType::Polygon, tri, line, group);
      }
      return;
    default:
      break;
  }
  Fixed f{};
  if (!fixed_type(code, f)) {
    in.fail(type_line, "unknown or unsupported element type " + std::to_string(code) + " (" +
                           which +
                           "; rift reads linear VTK cells: 1 to 14, lines and points "
                           "being ignored)");
  }
  if (ids.size() != f.points) {
    in.fail(line, which + " (" + f.name + ") has " + std::to_string(ids.size()) +
                      " points, expected " + std::to_string(f.points));
  }
  if (code == kPixel || code == kVoxel) {
    // Pixels and voxels number their points along the axes (x fastest), not
    // around the faces: swap 2/3 (and 6/7) to get a quad or hexahedron.
    std::array<std::uint32_t, 8> v{};
    for (std::size_t k = 0; k < f.points; ++k)
      v[k] = ids[k];
    std::swap(v[2], v[3]);
    std::swap(v[6], v[7]);
    out.add(f.type, std::span(v.data(), f.points), line, group);
    return;
  }
  out.add(f.type, ids, line, group);
}

}  // namespace rift::io
