// A plain, hand-written mass-spring cloth over flat arrays: the speed baseline
// of the physics issue and an independent check of the simulator generated from
// the rule packs. It implements exactly the model of docs/physics.md (atomic
// springs of Table 1 of the paper, corner masses, pins, gravity, RK4) without
// any G-map: springs are built once from the mesh's polygons and a step is a
// flat loop over them.
//
//   stretch  one spring per half-edge <0> (an interior edge carries two)
//   shear    the two diagonals of every quad face <0,1> (other polygons: none)
//   bending  one spring per edge extremity <2>: at the end A of an interior
//            edge shared by faces F1 and F2, between L and R, the vertices
//            reached from A along A's other edge in F1 and in F2
//
// Spring force on its end a (b gets the opposite), with u = (x_b - x_a) / l:
//   f_a = (k (l - l0) + c (v_b - v_a) . u) u
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "rift/core/types.hpp"
#include "rift/mesh/mesh_data.hpp"

namespace rift::reference {

/// The paper's cloth (Fig. 14): 100 g, 60 / 43 / 10 N/m, damping 0.1 N s/m.
struct ClothParameters {
  Real total_mass = 0.1;  ///< kg, spread over the faces by area
  Real stretch_k = 60;    ///< N/m, each atomic stretch spring
  Real shear_k = 43;      ///< N/m, each diagonal
  Real bend_k = 10;       ///< N/m, each linear bending spring
  Real stretch_c = 0.1;   ///< N s/m, damping along the spring
  Real shear_c = 0.1;
  Real bend_c = 0.1;
  Vec3 gravity = Vec3(0, 0, -9.81);
};

/// A damped spring between vertices a and b.
struct Spring {
  std::uint32_t a, b;
  Real rest;  ///< l0, m
  Real k;     ///< N/m
  Real c;     ///< N s/m
};

struct SpringCounts {
  std::size_t stretch = 0, shear = 0, bend = 0;
  std::size_t total() const { return stretch + shear + bend; }
};

/// Rotates a z = 0 grid by +90 degrees about the x axis, (x, y, 0) -> (x, 0, y),
/// so that it hangs in the x-z plane with its row y = 1 on top (gravity -z).
inline void hang_vertically(MeshData& mesh) {
  for (Vec3& p : mesh.points)
    p = Vec3(p.x(), -p.z(), p.y());
}

/// Index of grid point (i, j) of make_grid(kind, nx, ny).
inline std::uint32_t grid_point(int nx, int i, int j) {
  return static_cast<std::uint32_t>(j * (nx + 1) + i);
}

class ReferenceCloth {
 public:
  /// Builds masses and atomic springs from a polygon mesh; rest lengths from its points.
  ReferenceCloth(const MeshData& mesh, const ClothParameters& params) : gravity_(params.gravity) {
    if (mesh.dimension != 2)
      throw std::invalid_argument("reference cloth: a polygon mesh is needed");
    init_state(mesh.points);
    assign_masses(mesh, params.total_mass);
    build_springs(mesh, params);
  }

  /// Free particles joined by the given springs (rest lengths as given).
  ReferenceCloth(std::vector<Vec3> points, std::vector<Real> masses, std::vector<Spring> springs,
                 Vec3 gravity)
      : gravity_(gravity) {
    init_state(points);
    if (masses.size() != points.size()) throw std::invalid_argument("one mass per point");
    mass_ = std::move(masses);
    for (std::size_t i = 0; i < mass_.size(); ++i)
      inverse_mass_[i] = mass_[i] > 0 ? 1 / mass_[i] : 0;
    springs_ = std::move(springs);
    counts_.stretch = springs_.size();
  }

  std::size_t vertex_count() const { return x_.size(); }
  std::vector<Vec3>& positions() { return x_; }
  std::vector<Vec3>& velocities() { return v_; }
  const std::vector<Vec3>& positions() const { return x_; }
  const std::vector<Vec3>& velocities() const { return v_; }
  const std::vector<Real>& masses() const { return mass_; }
  const std::vector<Spring>& springs() const { return springs_; }
  const SpringCounts& counts() const { return counts_; }
  const Vec3& gravity() const { return gravity_; }
  Real time() const { return time_; }

  /// Merges the springs that join the same pair of vertices at the same rest
  /// length into one spring of summed stiffness and damping: the paper's two
  /// atomic stretch springs of an interior edge, and the bending springs that
  /// two edges of one vertex both place across it. The forces are the same up
  /// to rounding (k1 (l - l0) u + k2 (l - l0) u = (k1 + k2) (l - l0) u), with
  /// fewer evaluations: the fastest plain way to step this cloth, the second
  /// baseline of docs/performance.md. counts() keeps the atomic counts.
  void cumulate_springs() {
    std::unordered_map<std::uint64_t, std::size_t> first;  // vertex pair -> merged spring
    std::vector<Spring> merged;
    merged.reserve(springs_.size());
    for (const Spring& s : springs_) {
      const std::uint64_t key = (std::uint64_t{std::min(s.a, s.b)} << 32) | std::max(s.a, s.b);
      const auto [it, inserted] = first.try_emplace(key, merged.size());
      if (!inserted && merged[it->second].rest == s.rest) {
        merged[it->second].k += s.k;
        merged[it->second].c += s.c;
      } else {
        merged.push_back(s);
      }
    }
    springs_ = std::move(merged);
  }

  /// A pinned vertex keeps its position: zero velocity and acceleration.
  void pin(std::uint32_t vertex) {
    inverse_mass_.at(vertex) = 0;
    v_[vertex] = Vec3::Zero();
    pinned_[vertex] = 1;
  }
  bool pinned(std::uint32_t vertex) const { return pinned_[vertex] != 0; }

  /// f = the springs' forces on every vertex at state (x, v), gravity excluded.
  void internal_forces(const Vec3* x, const Vec3* v, Vec3* f) const {
    const std::size_t n = x_.size();
    for (std::size_t i = 0; i < n; ++i)
      f[i].setZero();
    for (const Spring& s : springs_) {
      const Vec3 d = x[s.b] - x[s.a];
      const Real l = d.norm();
      if (!(l > 0)) continue;  // direction undefined: no force
      // f_a = (k (l - l0) + c dv.u) u with u = d / l, using one division.
      const Real inv = 1 / l;
      const Real tension = s.k * (l - s.rest) + s.c * (v[s.b] - v[s.a]).dot(d) * inv;
      const Vec3 fa = (tension * inv) * d;
      f[s.a] += fa;
      f[s.b] -= fa;
    }
  }

  /// a = f / m + g for free vertices, 0 for pinned ones.
  void accelerations(const Vec3* x, const Vec3* v, Vec3* a) {
    internal_forces(x, v, force_.data());
    const std::size_t n = x_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Real w = inverse_mass_[i];
      a[i] = w > 0 ? Vec3(force_[i] * w + gravity_) : Vec3::Zero();
    }
  }

  /// One classical RK4 step of (x, v)' = (v, a(x, v)). Allocates nothing.
  void step_rk4(Real dt) {
    const std::size_t n = x_.size();
    const Real h = dt / 2;
    // Stage 1: k1 = (v, a1). sum_x, sum_v gather k1 + 2 k2 + 2 k3.
    accelerations(x_.data(), v_.data(), acc_.data());
    for (std::size_t i = 0; i < n; ++i) {
      sum_x_[i] = v_[i];
      sum_v_[i] = acc_[i];
      xs_[i] = x_[i] + h * v_[i];
      vs_[i] = v_[i] + h * acc_[i];
    }
    // Stage 2: k2 = (vs, a(xs, vs)).
    accelerations(xs_.data(), vs_.data(), acc_.data());
    for (std::size_t i = 0; i < n; ++i) {
      sum_x_[i] += 2 * vs_[i];
      sum_v_[i] += 2 * acc_[i];
      xs_[i] = x_[i] + h * vs_[i];
      vs_[i] = v_[i] + h * acc_[i];
    }
    // Stage 3.
    accelerations(xs_.data(), vs_.data(), acc_.data());
    for (std::size_t i = 0; i < n; ++i) {
      sum_x_[i] += 2 * vs_[i];
      sum_v_[i] += 2 * acc_[i];
      xs_[i] = x_[i] + dt * vs_[i];
      vs_[i] = v_[i] + dt * acc_[i];
    }
    // Stage 4 and the update.
    accelerations(xs_.data(), vs_.data(), acc_.data());
    const Real s = dt / 6;
    for (std::size_t i = 0; i < n; ++i) {
      x_[i] += s * (sum_x_[i] + vs_[i]);
      v_[i] += s * (sum_v_[i] + acc_[i]);
    }
    time_ += dt;
  }

  // ---- diagnostics ---------------------------------------------------------------

  Real total_mass() const {
    Real m = 0;
    for (Real mi : mass_)
      m += mi;
    return m;
  }
  Real kinetic_energy() const {
    Real e = 0;
    for (std::size_t i = 0; i < x_.size(); ++i)
      e += 0.5 * mass_[i] * v_[i].squaredNorm();
    return e;
  }
  /// Sum of 1/2 k (l - l0)^2 over the springs.
  Real elastic_energy() const {
    Real e = 0;
    for (const Spring& s : springs_) {
      const Real stretch = (x_[s.b] - x_[s.a]).norm() - s.rest;
      e += 0.5 * s.k * stretch * stretch;
    }
    return e;
  }
  /// -sum m g . x over all vertices (pinned ones add a constant).
  Real gravity_energy() const {
    Real e = 0;
    for (std::size_t i = 0; i < x_.size(); ++i)
      e -= mass_[i] * gravity_.dot(x_[i]);
    return e;
  }
  Real total_energy() const { return kinetic_energy() + elastic_energy() + gravity_energy(); }
  Vec3 momentum() const {
    Vec3 p = Vec3::Zero();
    for (std::size_t i = 0; i < x_.size(); ++i)
      p += mass_[i] * v_[i];
    return p;
  }
  Vec3 angular_momentum() const {
    Vec3 l = Vec3::Zero();
    for (std::size_t i = 0; i < x_.size(); ++i)
      l += mass_[i] * x_[i].cross(v_[i]);
    return l;
  }
  /// The springs' forces on every vertex at the current state.
  std::vector<Vec3> current_internal_forces() const {
    std::vector<Vec3> f(x_.size());
    internal_forces(x_.data(), v_.data(), f.data());
    return f;
  }

 private:
  void init_state(const std::vector<Vec3>& points) {
    const std::size_t n = points.size();
    x_ = points;
    v_.assign(n, Vec3::Zero());
    mass_.assign(n, 0);
    inverse_mass_.assign(n, 0);
    pinned_.assign(n, 0);
    for (auto* buffer : {&force_, &acc_, &xs_, &vs_, &sum_x_, &sum_v_})
      buffer->assign(n, Vec3::Zero());
  }

  // Vector area of a polygon: half the norm of sum p_i x p_{i+1}.
  static Real polygon_area(const MeshData& mesh, const MeshElement& e) {
    const std::uint32_t* w = mesh.vertices_of(e);
    Vec3 twice = Vec3::Zero();
    for (std::uint32_t i = 0; i < e.count; ++i)
      twice += mesh.points[w[i]].cross(mesh.points[w[(i + 1) % e.count]]);
    return 0.5 * twice.norm();
  }

  // Each face weighs total_mass * area / total_area, split equally among its corners.
  void assign_masses(const MeshData& mesh, Real total_mass) {
    Real total_area = 0;
    for (const MeshElement& e : mesh.elements)
      total_area += polygon_area(mesh, e);
    if (!(total_area > 0)) throw std::invalid_argument("reference cloth: zero area");
    for (const MeshElement& e : mesh.elements) {
      if (e.type != ElementType::Polygon || e.count < 3)
        throw std::invalid_argument("reference cloth: polygons only");
      const Real corner = total_mass * polygon_area(mesh, e) / total_area / e.count;
      const std::uint32_t* w = mesh.vertices_of(e);
      for (std::uint32_t i = 0; i < e.count; ++i)
        mass_[w[i]] += corner;
    }
    for (std::size_t i = 0; i < mass_.size(); ++i)
      inverse_mass_[i] = mass_[i] > 0 ? 1 / mass_[i] : 0;
  }

  void add_spring(std::uint32_t a, std::uint32_t b, Real k, Real c) {
    springs_.push_back({a, b, (x_[b] - x_[a]).norm(), k, c});
  }

  // One side of an edge: face `face`, whose vertex `local` starts the half-edge.
  struct EdgeSide {
    std::uint32_t lo, hi;  // the edge's vertices, sorted
    std::uint32_t face, local;
  };

  // The neighbour of `vertex` in the face other than across the side's edge.
  static std::uint32_t other_neighbour(const MeshData& mesh, const EdgeSide& side,
                                       std::uint32_t vertex) {
    const MeshElement& e = mesh.elements[side.face];
    const std::uint32_t* w = mesh.vertices_of(e);
    const std::uint32_t n = e.count;
    return w[side.local] == vertex ? w[(side.local + n - 1) % n] : w[(side.local + 2) % n];
  }

  void build_springs(const MeshData& mesh, const ClothParameters& p) {
    std::vector<EdgeSide> sides;
    for (std::uint32_t f = 0; f < mesh.elements.size(); ++f) {
      const MeshElement& e = mesh.elements[f];
      const std::uint32_t* w = mesh.vertices_of(e);
      for (std::uint32_t i = 0; i < e.count; ++i) {
        const std::uint32_t a = w[i], b = w[(i + 1) % e.count];
        add_spring(a, b, p.stretch_k, p.stretch_c);  // one per half-edge <0>
        sides.push_back({std::min(a, b), std::max(a, b), f, i});
      }
    }
    counts_.stretch = springs_.size();

    for (const MeshElement& e : mesh.elements) {
      if (e.count != 4) continue;  // the linear shear pattern is a quad
      const std::uint32_t* w = mesh.vertices_of(e);
      add_spring(w[0], w[2], p.shear_k, p.shear_c);
      add_spring(w[1], w[3], p.shear_k, p.shear_c);
    }
    counts_.shear = springs_.size() - counts_.stretch;

    // Faces sharing an edge: sort the sides by edge, then by face, so that an
    // edge of more than two faces joins its first two, as the G-map assembler does.
    std::sort(sides.begin(), sides.end(), [](const EdgeSide& s, const EdgeSide& t) {
      if (s.lo != t.lo) return s.lo < t.lo;
      if (s.hi != t.hi) return s.hi < t.hi;
      return s.face < t.face;
    });
    for (std::size_t i = 0; i + 1 < sides.size();) {
      std::size_t j = i + 1;
      while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi)
        ++j;
      if (j - i >= 2) {
        const EdgeSide& f1 = sides[i];
        const EdgeSide& f2 = sides[i + 1];
        for (std::uint32_t end : {f1.lo, f1.hi}) {  // one spring per edge extremity <2>
          add_spring(other_neighbour(mesh, f1, end), other_neighbour(mesh, f2, end), p.bend_k,
                     p.bend_c);
        }
      }
      i = j;
    }
    counts_.bend = springs_.size() - counts_.stretch - counts_.shear;
  }

  Vec3 gravity_;
  std::vector<Vec3> x_, v_;
  std::vector<Real> mass_, inverse_mass_;
  std::vector<std::uint8_t> pinned_;
  std::vector<Spring> springs_;
  SpringCounts counts_;
  Real time_ = 0;
  // Stage buffers of RK4, sized once.
  std::vector<Vec3> force_, acc_, xs_, vs_, sum_x_, sum_v_;
};

}  // namespace rift::reference
