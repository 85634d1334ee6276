// Small meshes with cell counts worked out by hand, and test-only writers that
// spell them in every format the importers read. Writing the same shape in
// every format makes the formats' readers check one another.
#pragma once

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "io_test_support.hpp"

namespace rift::test {

struct ShapeElement {
  ElementType type;
  std::vector<std::uint32_t> v;  // 0-based, VTK ordering
};

struct Shape {
  std::string name;
  int dimension;
  std::vector<Vec3> points;
  std::vector<ShapeElement> elements;
  Counts expected;  // by hand, see shapes()
};

inline std::vector<Shape> shapes() {
  std::vector<Shape> s;
  // Unit square cut along a diagonal: 4 corners, 4 sides + 1 diagonal.
  s.push_back({"two_triangles",
               2,
               {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
               {{ElementType::Polygon, {0, 1, 2}}, {ElementType::Polygon, {0, 2, 3}}},
               {12, 4, 5, 2, 0, 1, 4}});
  // A quad with a triangle on its right side: 6 edges, 5 on the boundary.
  s.push_back({"quad_and_triangle",
               2,
               {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}},
               {{ElementType::Polygon, {0, 1, 2, 3}}, {ElementType::Polygon, {1, 4, 2}}},
               {14, 5, 6, 2, 0, 1, 5}});
  // Two tetrahedra glued on triangle 0 1 2: 9 edges, 4 + 4 - 1 faces, 24 darts each.
  s.push_back({"two_tets",
               3,
               {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}},
               {{ElementType::Tetra, {0, 1, 2, 3}}, {ElementType::Tetra, {0, 2, 1, 4}}},
               {48, 5, 9, 7, 2, 1, 6}});
  // A unit cube with a pyramid on its top face: 12 + 4 edges, 6 + 4 faces.
  s.push_back(
      {"hex_and_pyramid",
       3,
       {{0, 0, 0},
        {1, 0, 0},
        {1, 1, 0},
        {0, 1, 0},
        {0, 0, 1},
        {1, 0, 1},
        {1, 1, 1},
        {0, 1, 1},
        {0.5, 0.5, 2}},
       {{ElementType::Hexa, {0, 1, 2, 3, 4, 5, 6, 7}}, {ElementType::Pyramid, {4, 5, 6, 7, 8}}},
       {80, 9, 16, 10, 2, 1, 9}});
  // A wedge (VTK order: the first triangle's normal points away from the
  // second) with a tetrahedron on its top triangle: 9 + 3 edges, 5 + 3 faces.
  s.push_back({"wedge_and_tet",
               3,
               {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 0, 1}, {0, 0, 2}},
               {{ElementType::Wedge, {0, 1, 2, 3, 4, 5}}, {ElementType::Tetra, {3, 5, 4, 6}}},
               {60, 7, 12, 8, 2, 1, 7}});
  return s;
}

// Gmsh node tags of the writers: sparse and listed in reverse, as a mesher
// that renumbers may leave them.
inline long gmsh_tag(std::size_t i) {
  return 7 + 3 * static_cast<long>(i);
}

inline int gmsh_type(const ShapeElement& e) {
  switch (e.type) {
    case ElementType::Polygon:
      return e.v.size() == 3 ? 2 : 3;
    case ElementType::Tetra:
      return 4;
    case ElementType::Hexa:
      return 5;
    case ElementType::Wedge:
      return 6;
    case ElementType::Pyramid:
      return 7;
  }
  return 0;
}

// Gmsh lists a prism's triangles the other way round from VTK.
inline std::vector<std::uint32_t> gmsh_order(const ShapeElement& e) {
  if (e.type != ElementType::Wedge) return e.v;
  return {e.v[0], e.v[2], e.v[1], e.v[3], e.v[5], e.v[4]};
}

inline std::string point_text(const Vec3& p) {
  std::ostringstream os;
  os << p.x() << ' ' << p.y() << ' ' << p.z();
  return os.str();
}

inline std::string to_obj(const Shape& s) {
  std::ostringstream os;
  os << "# " << s.name << "\no " << s.name << "\n";
  for (const Vec3& p : s.points)
    os << "v " << point_text(p) << "\n";
  for (const ShapeElement& e : s.elements) {
    os << "f";
    for (std::uint32_t v : e.v)
      os << ' ' << v + 1;
    os << "\n";
  }
  return os.str();
}

/// Gmsh 1 or 2.2. A volume shape also gets a boundary-marker triangle and a line.
inline std::string to_gmsh12(const Shape& s, int version) {
  std::ostringstream os;
  const bool v1 = version == 1;
  if (!v1) os << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  os << (v1 ? "$NOD\n" : "$Nodes\n") << s.points.size() << "\n";
  for (std::size_t i = s.points.size(); i-- > 0;)
    os << gmsh_tag(i) << ' ' << point_text(s.points[i]) << "\n";
  os << (v1 ? "$ENDNOD\n$ELM\n" : "$EndNodes\n$Elements\n") << s.elements.size() + 2 << "\n";
  int number = 1;
  auto element = [&](int type, const std::vector<std::uint32_t>& v) {
    os << number++ << ' ' << type << (v1 ? " 1 1 " + std::to_string(v.size()) : " 2 1 1");
    for (std::uint32_t i : v)
      os << ' ' << gmsh_tag(i);
    os << "\n";
  };
  element(1, {s.elements[0].v[0], s.elements[0].v[1]});
  for (const ShapeElement& e : s.elements)
    element(gmsh_type(e), gmsh_order(e));
  if (s.dimension == 3) {
    element(2, {s.elements[0].v[0], s.elements[0].v[1], s.elements[0].v[2]});
  } else {
    element(15, {s.elements[0].v[0]});
  }
  os << (v1 ? "$ENDELM\n" : "$EndElements\n");
  return os.str();
}

/// Gmsh 4.1: one node block per point (entity of dimension 0) and one element
/// block per element, plus a line block that must be ignored.
inline std::string to_gmsh41(const Shape& s) {
  std::ostringstream os;
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  os << "$Entities\n0 0 0 1\n1 0 0 0 1 1 1 0 0\n$EndEntities\n";
  // All nodes in one block; parametric nodes are covered by a dedicated test.
  os << "$Nodes\n1 " << s.points.size() << " 1 " << gmsh_tag(s.points.size()) << "\n";
  os << s.dimension << " 1 0 " << s.points.size() << "\n";
  for (std::size_t i = s.points.size(); i-- > 0;)
    os << gmsh_tag(i) << "\n";
  for (std::size_t i = s.points.size(); i-- > 0;)
    os << point_text(s.points[i]) << "\n";
  os << "$EndNodes\n$Elements\n"
     << s.elements.size() + 1 << ' ' << s.elements.size() + 1 << " 1 " << s.elements.size() + 1
     << "\n";
  os << "1 1 1 1\n100 " << gmsh_tag(s.elements[0].v[0]) << ' ' << gmsh_tag(s.elements[0].v[1])
     << "\n";
  int tag = 1;
  for (const ShapeElement& e : s.elements) {
    os << s.dimension << " 1 " << gmsh_type(e) << " 1\n" << tag++;
    for (std::uint32_t i : gmsh_order(e))
      os << ' ' << gmsh_tag(i);
    os << "\n";
  }
  os << "$EndElements\n";
  return os.str();
}

inline std::string to_medit(const Shape& s) {
  std::ostringstream os;
  os << "MeshVersionFormatted 2\n\nDimension\n"
     << (s.dimension == 3 ? 3 : 2) << "\n\nVertices\n"
     << s.points.size() << "\n";
  for (const Vec3& p : s.points) {
    if (s.dimension == 3) {
      os << point_text(p) << " 0\n";
    } else {
      os << p.x() << ' ' << p.y() << " 0\n";
    }
  }
  auto section = [&](const char* name, ElementType type, std::size_t size) {
    std::ostringstream body;
    std::size_t n = 0;
    for (const ShapeElement& e : s.elements) {
      if (e.type != type || (type == ElementType::Polygon && e.v.size() != size)) continue;
      ++n;
      for (std::uint32_t v : e.v)
        body << v + 1 << ' ';
      body << "3\n";
    }
    if (n > 0) os << name << "\n" << n << "\n" << body.str();
  };
  section("Triangles", ElementType::Polygon, 3);
  section("Quadrilaterals", ElementType::Polygon, 4);
  section("Tetrahedra", ElementType::Tetra, 4);
  section("Hexahedra", ElementType::Hexa, 8);
  section("Prisms", ElementType::Wedge, 6);
  os << "Edges\n1\n1 2 0\nEnd\n";
  return os.str();
}

inline int vtk_type(const ShapeElement& e) {
  switch (e.type) {
    case ElementType::Polygon:
      return e.v.size() == 3 ? 5 : e.v.size() == 4 ? 9 : 7;
    case ElementType::Tetra:
      return 10;
    case ElementType::Hexa:
      return 12;
    case ElementType::Wedge:
      return 13;
    case ElementType::Pyramid:
      return 14;
  }
  return 0;
}

/// Legacy VTK, classic cell layout (version 3.0) or offsets layout (5.1).
inline std::string to_vtk(const Shape& s, bool offsets_layout) {
  std::ostringstream os;
  os << "# vtk DataFile Version " << (offsets_layout ? "5.1" : "3.0") << "\n"
     << s.name << "\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " << s.points.size() << " double\n";
  for (const Vec3& p : s.points)
    os << point_text(p) << "\n";
  std::size_t size = 0;
  for (const ShapeElement& e : s.elements)
    size += e.v.size();
  if (offsets_layout) {
    os << "CELLS " << s.elements.size() + 1 << ' ' << size << "\nOFFSETS vtktypeint64\n0";
    std::size_t end = 0;
    for (const ShapeElement& e : s.elements)
      os << ' ' << (end += e.v.size());
    os << "\nCONNECTIVITY vtktypeint64\n";
    for (const ShapeElement& e : s.elements) {
      for (std::uint32_t v : e.v)
        os << v << ' ';
      os << "\n";
    }
  } else {
    os << "CELLS " << s.elements.size() << ' ' << size + s.elements.size() << "\n";
    for (const ShapeElement& e : s.elements) {
      os << e.v.size();
      for (std::uint32_t v : e.v)
        os << ' ' << v;
      os << "\n";
    }
  }
  os << "CELL_TYPES " << s.elements.size() << "\n";
  for (const ShapeElement& e : s.elements)
    os << vtk_type(e) << "\n";
  os << "POINT_DATA " << s.points.size() << "\nSCALARS id int 1\nLOOKUP_TABLE default\n";
  for (std::size_t i = 0; i < s.points.size(); ++i)
    os << i << "\n";
  return os.str();
}

inline std::string to_vtu(const Shape& s) {
  std::ostringstream os;
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
     << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << s.points.size()
     << "\" NumberOfCells=\"" << s.elements.size() << "\">\n      <Points>\n"
     << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& p : s.points)
    os << "          " << point_text(p) << "\n";
  os << "        </DataArray>\n      </Points>\n      <Cells>\n"
     << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const ShapeElement& e : s.elements) {
    os << "         ";
    for (std::uint32_t v : e.v)
      os << ' ' << v;
    os << "\n";
  }
  os << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
        "format=\"ascii\">\n         ";
  std::size_t end = 0;
  for (const ShapeElement& e : s.elements)
    os << ' ' << (end += e.v.size());
  os << "\n        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" "
        "format=\"ascii\">\n         ";
  for (const ShapeElement& e : s.elements)
    os << ' ' << vtk_type(e);
  os << "\n        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
        "</VTKFile>\n";
  return os.str();
}

}  // namespace rift::test
