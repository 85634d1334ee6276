#include "rift/mesh/element_faces.hpp"

namespace rift {

namespace {
// Face orientation does not matter to a G-map (it is not oriented), and the
// faces below are not consistently outward: only their vertex sets and edge
// cycles are used.
constexpr LocalFace kTetraFaces[] = {
    {3, {0, 2, 1, 0}}, {3, {0, 1, 3, 0}}, {3, {1, 2, 3, 0}}, {3, {0, 3, 2, 0}}};
constexpr LocalFace kHexaFaces[] = {{4, {0, 3, 2, 1}}, {4, {4, 5, 6, 7}}, {4, {0, 1, 5, 4}},
                                    {4, {1, 2, 6, 5}}, {4, {2, 3, 7, 6}}, {4, {3, 0, 4, 7}}};
constexpr LocalFace kWedgeFaces[] = {
    {3, {0, 2, 1, 0}}, {3, {3, 4, 5, 0}}, {4, {0, 1, 4, 3}}, {4, {1, 2, 5, 4}}, {4, {2, 0, 3, 5}}};
constexpr LocalFace kPyramidFaces[] = {
    {4, {0, 3, 2, 1}}, {3, {0, 1, 4, 0}}, {3, {1, 2, 4, 0}}, {3, {2, 3, 4, 0}}, {3, {3, 0, 4, 0}}};
}  // namespace

std::span<const LocalFace> element_faces(ElementType type) {
  switch (type) {
    case ElementType::Polygon:
      return {};
    case ElementType::Tetra:
      return kTetraFaces;
    case ElementType::Hexa:
      return kHexaFaces;
    case ElementType::Wedge:
      return kWedgeFaces;
    case ElementType::Pyramid:
      return kPyramidFaces;
  }
  return {};
}

int element_vertex_count(ElementType type) {
  switch (type) {
    case ElementType::Polygon:
      return 0;
    case ElementType::Tetra:
      return 4;
    case ElementType::Hexa:
      return 8;
    case ElementType::Wedge:
      return 6;
    case ElementType::Pyramid:
      return 5;
  }
  return 0;
}

const char* element_name(ElementType type) {
  switch (type) {
    case ElementType::Polygon:
      return "polygon";
    case ElementType::Tetra:
      return "tetrahedron";
    case ElementType::Hexa:
      return "hexahedron";
    case ElementType::Wedge:
      return "wedge";
    case ElementType::Pyramid:
      return "pyramid";
  }
  return "?";
}

}  // namespace rift
