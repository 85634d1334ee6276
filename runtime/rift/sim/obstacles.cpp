#include "rift/sim/obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rift {

const char* to_string(Obstacle::Shape shape) {
  switch (shape) {
    case Obstacle::Shape::kPlane:
      return "plane";
    case Obstacle::Shape::kSphere:
      return "sphere";
    case Obstacle::Shape::kBox:
      return "box";
    case Obstacle::Shape::kCapsule:
      return "capsule";
  }
  return "?";
}

Real Obstacle::distance(const Vec3& p_world, Real t, Vec3& normal) const {
  const Vec3 p = p_world - offset(t);  // in the obstacle's rest frame
  switch (shape) {
    case Shape::kPlane: {
      normal = b.normalized();
      return (p - a).dot(normal);
    }
    case Shape::kSphere: {
      const Vec3 d = p - a;
      const Real r = d.norm();
      normal = r > 0 ? Vec3(d / r) : Vec3(0, 0, 1);
      return r - radius;
    }
    case Shape::kCapsule: {
      const Vec3 axis = b - a;
      const Real len2 = axis.squaredNorm();
      const Real s = len2 > 0 ? std::clamp((p - a).dot(axis) / len2, Real(0), Real(1)) : 0;
      const Vec3 d = p - (a + s * axis);
      const Real r = d.norm();
      normal = r > 0 ? Vec3(d / r) : Vec3(0, 0, 1);
      return r - radius;
    }
    case Shape::kBox: {
      const Vec3 centre = 0.5 * (a + b);
      const Vec3 half = 0.5 * (b - a);
      const Vec3 q = (p - centre).cwiseAbs() - half;
      if ((q.array() > 0).any()) {
        const Vec3 outside = q.cwiseMax(0);
        const Real r = outside.norm();
        normal = (p - centre).cwiseSign().cwiseProduct(outside) / r;
        return r;
      }
      // Inside: out through the nearest face.
      int axis = 0;
      q.maxCoeff(&axis);
      normal = Vec3::Zero();
      normal[axis] = p[axis] >= centre[axis] ? 1 : -1;
      return q[axis];
    }
  }
  normal = Vec3(0, 0, 1);
  return 1;
}

std::size_t Contact::project(const OrbitAttachment& alive, Real t,
                             const std::vector<Real>& inverse_mass, std::vector<Vec3>& x,
                             std::vector<Vec3>& v) const {
  std::size_t touching = 0;
  const std::size_t n = std::min(x.size(), inverse_mass.size());
  for (Slot s = 0; s < n; ++s) {
    if (!alive.slot_alive(s) || inverse_mass[s] == 0) continue;
    bool touched = false;
    for (const Obstacle& o : obstacles_) {
      Vec3 normal;
      const Real d = o.distance(x[s], t, normal);
      if (d >= 0) continue;
      touched = true;
      x[s] -= d * normal;
      const Vec3 obstacle_v = o.velocity_at(t);
      Vec3 relative = v[s] - obstacle_v;
      const Real vn = relative.dot(normal);
      if (vn < 0) {
        relative -= vn * normal;
        // Coulomb: the tangential speed drops by at most mu |dv_n|.
        const Real vt = relative.norm();
        const Real drop = o.friction * -vn;
        relative *= vt > drop ? (vt - drop) / vt : 0;
        v[s] = obstacle_v + relative;
      }
    }
    touching += touched ? 1 : 0;
  }
  return touching;
}

}  // namespace rift

namespace rift {

namespace {

// Two unit vectors orthogonal to n and to each other.
void basis(const Vec3& n, Vec3& u, Vec3& w) {
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  u = n.cross(helper).normalized();
  w = n.cross(u);
}

void add_sphere(const Vec3& c, Real r, std::vector<Vec3>& points,
                std::vector<std::array<std::uint32_t, 3>>& triangles) {
  const int rings = 12, segments = 24;
  const auto first = static_cast<std::uint32_t>(points.size());
  for (int i = 0; i <= rings; ++i) {
    const Real theta = std::numbers::pi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const Real phi = 2 * std::numbers::pi * j / segments;
      points.push_back(c + r * Vec3(std::sin(theta) * std::cos(phi),
                                    std::sin(theta) * std::sin(phi), std::cos(theta)));
    }
  }
  auto at = [&](int i, int j) {
    return first + static_cast<std::uint32_t>(i * segments + (j % segments));
  };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
}

}  // namespace

void tessellate(const Obstacle& o, Real t, const Vec3& lo, const Vec3& hi,
                std::vector<Vec3>& points, std::vector<std::array<std::uint32_t, 3>>& triangles) {
  const Vec3 shift = o.offset(t);
  const auto first = static_cast<std::uint32_t>(points.size());
  switch (o.shape) {
    case Obstacle::Shape::kPlane: {
      const Vec3 n = o.b.normalized();
      Vec3 u, w;
      basis(n, u, w);
      const Vec3 centre = 0.5 * (lo + hi);
      const Vec3 foot = centre - (centre - o.a - shift).dot(n) * n;
      const Real half = std::max((hi - lo).norm(), Real(1e-3));
      points.push_back(foot - half * u - half * w);
      points.push_back(foot + half * u - half * w);
      points.push_back(foot + half * u + half * w);
      points.push_back(foot - half * u + half * w);
      triangles.push_back({first, first + 1, first + 2});
      triangles.push_back({first, first + 2, first + 3});
      return;
    }
    case Obstacle::Shape::kSphere:
      add_sphere(o.a + shift, o.radius, points, triangles);
      return;
    case Obstacle::Shape::kBox: {
      const Vec3 a = o.a + shift, b = o.b + shift;
      for (int k = 0; k < 8; ++k)
        points.push_back(Vec3(k & 1 ? b.x() : a.x(), k & 2 ? b.y() : a.y(), k & 4 ? b.z() : a.z()));
      const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
      for (const auto& q : quads) {
        triangles.push_back({first + q[0], first + q[1], first + q[2]});
        triangles.push_back({first + q[0], first + q[2], first + q[3]});
      }
      return;
    }
    case Obstacle::Shape::kCapsule: {
      const Vec3 a = o.a + shift, b = o.b + shift;
      add_sphere(a, o.radius, points, triangles);
      add_sphere(b, o.radius, points, triangles);
      const Vec3 axis = b - a;
      if (axis.norm() == 0) return;
      Vec3 u, w;
      basis(axis.normalized(), u, w);
      const int segments = 24;
      const auto base = static_cast<std::uint32_t>(points.size());
      for (int j = 0; j < segments; ++j) {
        const Real phi = 2 * std::numbers::pi * j / segments;
        const Vec3 r = o.radius * (std::cos(phi) * u + std::sin(phi) * w);
        points.push_back(a + r);
        points.push_back(b + r);
      }
      for (int j = 0; j < segments; ++j) {
        const std::uint32_t k0 = base + 2 * static_cast<std::uint32_t>(j);
        const std::uint32_t k1 = base + 2 * static_cast<std::uint32_t>((j + 1) % segments);
        triangles.push_back({k0, k1, k1 + 1});
        triangles.push_back({k0, k1 + 1, k0 + 1});
      }
      return;
    }
  }
}

}  // namespace rift
