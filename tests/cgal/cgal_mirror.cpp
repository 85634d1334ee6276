#include "cgal_mirror.hpp"

#include <deque>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace rift_cgal {

namespace {

constexpr std::uint32_t kNone = ~0u;
constexpr std::uint32_t kPad = ~0u;

/// Calls f(std::integral_constant<unsigned, i>) for a runtime i in [0, N].
template <unsigned N, class F>
decltype(auto) with_index(int i, F&& f) {
  switch (i) {
    case 0:
      return f(std::integral_constant<unsigned, 0>{});
    case 1:
      return f(std::integral_constant<unsigned, 1>{});
    case 2:
      return f(std::integral_constant<unsigned, 2>{});
    default:
      if constexpr (N >= 3) {
        if (i == 3) return f(std::integral_constant<unsigned, 3>{});
      }
      throw std::out_of_range("dimension " + std::to_string(i) + " outside the map");
  }
}

std::array<std::uint32_t, 4> sorted_key(const std::uint32_t* ids, int count) {
  std::array<std::uint32_t, 4> key{kPad, kPad, kPad, kPad};
  // Insertion sort: GCC 12 reports false array-bounds errors for std::sort here.
  for (int i = 0; i < count; ++i) {
    int j = i;
    for (; j > 0 && key[j - 1] > ids[i]; --j)
      key[j] = key[j - 1];
    key[j] = ids[i];
  }
  return key;
}

using RootKey = std::array<std::uint32_t, 4>;

}  // namespace

std::string to_string(const Counts& c) {
  return "darts=" + std::to_string(c.darts) + " vertices=" + std::to_string(c.vertices) +
         " edges=" + std::to_string(c.edges) + " faces=" + std::to_string(c.faces) +
         " volumes=" + std::to_string(c.volumes) + " components=" + std::to_string(c.components) +
         " boundary=" + std::to_string(c.boundary) + " valid=" + (c.valid ? "yes" : "no");
}

Counts rift_counts(const rift::GMap& map) {
  const int n = map.dimension();
  Counts c;
  c.darts = map.size();
  c.vertices = map.count_cells_of_dimension(0);
  c.edges = map.count_cells_of_dimension(1);
  c.faces = map.count_cells_of_dimension(2);
  c.volumes = n >= 3 ? map.count_cells_of_dimension(3) : 0;
  c.components = map.count_cells(rift::Orbit::all(n));
  map.for_each_cell(rift::Orbit::cell(n - 1, n), [&](rift::Dart d) {
    if (map.is_free(d, n)) ++c.boundary;
  });
  c.valid = map.is_valid();
  return c;
}

std::vector<SolidFace> solid_faces(rift::ElementType type) {
  using rift::ElementType;
  switch (type) {
    case ElementType::Tetra:
      return {{3, {0, 1, 2, 0}}, {3, {0, 1, 3, 0}}, {3, {1, 2, 3, 0}}, {3, {0, 2, 3, 0}}};
    case ElementType::Hexa:
      return {{4, {0, 1, 2, 3}}, {4, {4, 5, 6, 7}}, {4, {0, 1, 5, 4}},
              {4, {1, 2, 6, 5}}, {4, {2, 3, 7, 6}}, {4, {3, 0, 4, 7}}};
    case ElementType::Wedge:
      return {{3, {0, 1, 2, 0}},
              {3, {3, 4, 5, 0}},
              {4, {0, 1, 4, 3}},
              {4, {1, 2, 5, 4}},
              {4, {2, 0, 3, 5}}};
    case ElementType::Pyramid:
      return {{4, {0, 1, 2, 3}},
              {3, {0, 1, 4, 0}},
              {3, {1, 2, 4, 0}},
              {3, {2, 3, 4, 0}},
              {3, {3, 0, 4, 0}}};
    case ElementType::Polygon:
      break;
  }
  return {};
}

template <unsigned N>
CgalMirror<N>::CgalMirror(const rift::MeshData& mesh) {
  if (mesh.dimension != static_cast<int>(N)) {
    throw std::invalid_argument("mesh dimension does not match the CGAL map");
  }
  // Sides an element offers to its neighbours, in element order: edges in 2D,
  // faces in 3D, keyed by their sorted vertex ids.
  std::map<std::array<std::uint32_t, 4>, std::vector<Dart>> sides;
  for (const rift::MeshElement& e : mesh.elements) {
    const std::uint32_t* v = mesh.vertices_of(e);
    const int k = static_cast<int>(e.count);
    if constexpr (N == 2) {
      Dart d = new_polygon(v, k);
      for (int i = 0; i < k; ++i) {
        const std::uint32_t edge[2] = {v[i], v[(i + 1) % k]};
        sides[sorted_key(edge, 2)].push_back(d);
        d = map_.template alpha<1>(map_.template alpha<0>(d));
      }
    } else {
      std::vector<Dart> faces;
      for (const SolidFace& f : solid_faces(e.type)) {
        std::uint32_t ids[4];
        for (int i = 0; i < f.count; ++i)
          ids[i] = v[f.v[i]];
        faces.push_back(new_polygon(ids, f.count));
        sides[sorted_key(ids, f.count)].push_back(faces.back());
      }
      sew_inside_solid(faces);
    }
  }
  sew_neighbours(sides);
}

template <unsigned N>
typename CgalMirror<N>::Dart CgalMirror<N>::new_polygon(const std::uint32_t* ids, int count) {
  const Dart start = map_.make_combinatorial_polygon(static_cast<unsigned>(count));
  auto label = [&](Dart d, std::uint32_t vertex) {
    map_.info(d).vertex = vertex;
    map_.info(d).serial = static_cast<std::uint32_t>(by_serial_.size());
    by_serial_.push_back(d);
  };
  Dart d = start;
  for (int i = 0; i < count; ++i) {
    const Dart e = map_.template alpha<0>(d);
    label(d, ids[i]);
    label(e, ids[(i + 1) % count]);
    d = map_.template alpha<1>(e);
  }
  if (d != start) errors_.push_back("CGAL polygon of " + std::to_string(count) + " is not a cycle");
  return start;
}

template <unsigned N>
void CgalMirror<N>::sew_inside_solid(const std::vector<Dart>& face_darts) {
  // Each edge of the solid is shared by two of its faces: 2-sew them where
  // the darts sit on the same vertex and edge.
  for (std::size_t f = 0; f < face_darts.size(); ++f) {
    auto face = map_.template darts_of_orbit<0, 1>(face_darts[f]);
    for (auto it = face.begin(); it != face.end(); ++it) {
      const Dart x = it;
      if (!map_.template is_free<2>(x)) continue;
      const std::uint32_t a = map_.info(x).vertex;
      const std::uint32_t b = map_.info(map_.template alpha<0>(x)).vertex;
      bool sewn = false;
      for (std::size_t g = f + 1; g < face_darts.size() && !sewn; ++g) {
        if (auto y = find_in_side(face_darts[g], a, b)) {
          if (map_.template is_sewable<2>(x, *y)) {
            map_.template sew<2>(x, *y);
          } else {
            errors_.push_back("CGAL refuses to 2-sew two faces of one solid");
          }
          sewn = true;
        }
      }
    }
  }
}

template <unsigned N>
std::optional<typename CgalMirror<N>::Dart> CgalMirror<N>::find_in_side(Dart d,
                                                                        std::uint32_t vertex,
                                                                        std::uint32_t other) {
  auto fits = [&](Dart x) {
    return map_.info(x).vertex == vertex && map_.info(map_.template alpha<0>(x)).vertex == other;
  };
  if constexpr (N == 2) {
    if (fits(d)) return d;
    if (fits(map_.template alpha<0>(d))) return map_.template alpha<0>(d);
  } else {
    auto face = map_.template darts_of_orbit<0, 1>(d);
    for (auto it = face.begin(); it != face.end(); ++it) {
      if (fits(it)) return Dart(it);
    }
  }
  return std::nullopt;
}

template <unsigned N>
void CgalMirror<N>::sew_neighbours(
    const std::map<std::array<std::uint32_t, 4>, std::vector<Dart>>& sides) {
  for (const auto& [key, darts] : sides) {
    if (darts.size() < 2) continue;
    nonmanifold_ += darts.size() - 2;  // a third element keeps this side free
    const Dart x = darts[0];
    const std::uint32_t a = map_.info(x).vertex;
    const std::uint32_t b = map_.info(map_.template alpha<0>(x)).vertex;
    const auto y = find_in_side(darts[1], a, b);
    if (!y) {
      errors_.push_back("no matching dart on side starting at vertex " + std::to_string(a));
    } else if (!map_.template is_sewable<N>(x, *y)) {
      errors_.push_back("CGAL refuses to " + std::to_string(N) + "-sew the side at vertices " +
                        std::to_string(a) + "," + std::to_string(b));
    } else {
      map_.template sew<N>(x, *y);
    }
  }
}

template <unsigned N>
Counts CgalMirror<N>::counts() const {
  Counts c;
  const std::vector<unsigned int> cells = map_.count_all_cells();  // 0..N, then components
  c.darts = map_.number_of_darts();
  c.vertices = cells[0];
  c.edges = cells[1];
  c.faces = cells[2];
  c.volumes = N >= 3 ? cells[3] : 0;
  c.components = cells[N + 1];
  for (auto d = map_.template one_dart_per_cell<N - 1>().begin(),
            end = map_.template one_dart_per_cell<N - 1>().end();
       d != end; ++d) {
    if (map_.template is_free<N>(d)) ++c.boundary;
  }
  c.valid = map_.is_valid();
  return c;
}

template <unsigned N>
std::string CgalMirror<N>::match_darts(const rift::GMap& rift_map,
                                       std::vector<std::uint32_t>& rift_to_cgal) {
  const auto point = rift_map.template embedding<std::int64_t>("point_index");
  if (!point) return "the rift map has no point_index embedding";
  auto rift_vertex = [&](rift::Dart d) { return static_cast<std::uint32_t>(point[d]); };

  // A dart is identified, in a mesh without duplicated elements, by its
  // vertex, the other end of its edge, the other end of its 1-neighbour's
  // edge and (3D) that of its 2-neighbour's 1-neighbour.
  auto rift_key = [&](rift::Dart d) {
    RootKey k{rift_vertex(d), rift_vertex(rift_map.alpha(d, 0)),
              rift_vertex(rift_map.alpha(rift_map.alpha(d, 1), 0)), kPad};
    if (N == 3) k[3] = rift_vertex(rift_map.alpha(rift_map.alpha(rift_map.alpha(d, 2), 1), 0));
    return k;
  };
  auto cgal_key = [&](Dart d) {
    auto vertex = [&](Dart x) { return map_.info(x).vertex; };
    RootKey k{vertex(d), vertex(map_.alpha(d, 0)), vertex(map_.alpha(d, 1, 0)), kPad};
    if (N == 3) k[3] = vertex(map_.alpha(d, 2, 1, 0));
    return k;
  };
  std::map<RootKey, std::pair<rift::Dart, int>> roots;
  rift_map.for_each_dart([&](rift::Dart d) {
    auto& slot = roots.try_emplace(rift_key(d), d, 0).first->second;
    ++slot.second;
  });

  rift_to_cgal.assign(rift_map.capacity(), kNone);
  std::vector<rift::Dart> cgal_to_rift(by_serial_.size(), rift::kNoDart);
  std::deque<std::pair<rift::Dart, std::uint32_t>> queue;
  for (std::uint32_t s = 0; s < by_serial_.size(); ++s) {
    if (cgal_to_rift[s] != rift::kNoDart) continue;
    const auto root = roots.find(cgal_key(by_serial_[s]));
    if (root == roots.end()) return "CGAL dart " + std::to_string(s) + " has no rift counterpart";
    if (root->second.second != 1) return "ambiguous root for CGAL dart " + std::to_string(s);
    const rift::Dart r = root->second.first;
    if (rift_to_cgal[r] != kNone) return "rift dart " + std::to_string(r) + " matched twice";
    rift_to_cgal[r] = s;
    cgal_to_rift[s] = r;
    queue.emplace_back(r, s);
    while (!queue.empty()) {
      const auto [x, c] = queue.front();
      queue.pop_front();
      if (rift_vertex(x) != map_.info(by_serial_[c]).vertex) {
        return "rift dart " + std::to_string(x) + " sits on vertex " +
               std::to_string(rift_vertex(x)) + ", its CGAL twin on " +
               std::to_string(map_.info(by_serial_[c]).vertex);
      }
      for (int i = 0; i <= static_cast<int>(N); ++i) {
        const rift::Dart y = rift_map.alpha(x, i);
        const std::uint32_t cy = map_.info(map_.alpha(by_serial_[c], i)).serial;
        if (rift_to_cgal[y] == kNone && cgal_to_rift[cy] == rift::kNoDart) {
          rift_to_cgal[y] = cy;
          cgal_to_rift[cy] = y;
          queue.emplace_back(y, cy);
        } else if (rift_to_cgal[y] != cy || cgal_to_rift[cy] != y) {
          return "alpha_" + std::to_string(i) + " differs at rift dart " + std::to_string(x) +
                 " (CGAL dart " + std::to_string(c) + ")";
        }
      }
    }
  }
  std::size_t matched = 0;
  rift_map.for_each_dart([&](rift::Dart d) { matched += rift_to_cgal[d] != kNone; });
  if (matched != rift_map.size() || matched != by_serial_.size()) {
    return "matched " + std::to_string(matched) + " darts of " + std::to_string(rift_map.size()) +
           " (rift) and " + std::to_string(by_serial_.size()) + " (CGAL)";
  }
  return {};
}

template <unsigned N>
std::string CgalMirror<N>::compare_links(const rift::GMap& rift_map,
                                         const std::vector<std::uint32_t>& rift_to_cgal) const {
  std::string first;
  rift_map.for_each_dart([&](rift::Dart d) {
    for (int i = 0; i <= static_cast<int>(N) && first.empty(); ++i) {
      if (alpha(rift_to_cgal[d], i) != rift_to_cgal[rift_map.alpha(d, i)]) {
        first = "alpha_" + std::to_string(i) + " differs at rift dart " + std::to_string(d);
      }
    }
  });
  return first;
}

template <unsigned N>
bool CgalMirror<N>::is_free(std::uint32_t d, int i) const {
  return map_.is_free(by_serial_[d], static_cast<unsigned>(i));
}

template <unsigned N>
std::uint32_t CgalMirror<N>::alpha(std::uint32_t d, int i) const {
  return map_.info(map_.alpha(by_serial_[d], static_cast<unsigned>(i))).serial;
}

template <unsigned N>
bool CgalMirror<N>::is_sewable(std::uint32_t a, std::uint32_t b, int i) const {
  return with_index<N>(
      i, [&](auto c) { return map_.template is_sewable<c()>(by_serial_[a], by_serial_[b]); });
}

template <unsigned N>
void CgalMirror<N>::sew(std::uint32_t a, std::uint32_t b, int i) {
  with_index<N>(i, [&](auto c) { map_.template sew<c()>(by_serial_[a], by_serial_[b]); });
}

template <unsigned N>
void CgalMirror<N>::unsew(std::uint32_t d, int i) {
  with_index<N>(i, [&](auto c) { map_.template unsew<c()>(by_serial_[d]); });
}

template class CgalMirror<2>;
template class CgalMirror<3>;

}  // namespace rift_cgal
