#include "rift/output/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace rift {

Camera::Camera(const Vec3& eye, const Vec3& target, const Vec3& up, Real fov_y_degrees)
    : eye_(eye), target_(target) {
  forward_ = (target - eye).normalized();
  Vec3 side = forward_.cross(up);
  if (side.squaredNorm() < 1e-20) side = forward_.cross(Vec3::UnitX());
  if (side.squaredNorm() < 1e-20) side = forward_.cross(Vec3::UnitY());
  right_ = side.normalized();
  up_ = right_.cross(forward_);
  tan_half_fov_ = std::tan(0.5 * fov_y_degrees * std::numbers::pi / 180.0);
}

Camera Camera::framing(const Vec3& lo, const Vec3& hi, Real aspect, const CameraView& view) {
  Vec3 corners[8];
  for (int c = 0; c < 8; ++c) {
    corners[c] =
        Vec3((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z());
  }
  return framing(corners, aspect, view);
}

Camera Camera::framing(std::span<const Vec3> points, Real aspect, const CameraView& view) {
  // Non-finite points (a blown-up frame) are left out of the framing.
  std::vector<Vec3> finite;
  finite.reserve(points.size());
  for (const Vec3& p : points) {
    if (p.allFinite()) finite.push_back(p);
  }
  points = finite;
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  if (!points.empty()) lo = hi = points.front();
  for (const Vec3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Vec3 target = 0.5 * (lo + hi);
  const Real size = std::max(0.5 * view.expand * (hi - lo).norm(), Real(1e-9));
  const Real grow = view.expand;
  const Vec3 direction =
      view.direction.squaredNorm() > 0 ? view.direction.normalized() : Vec3::UnitZ();
  const Camera basis(target + direction, target, view.up, view.fov_y_degrees);
  const Real tan_v = basis.tan_half_fov_ * (1.0 - view.margin);
  const Real tan_h = tan_v * aspect;
  const Vec3 centre = target;
  // Smallest distance D at which every point projects inside the margins,
  // |x| <= tan_h (D + z) and |y| <= tan_v (D + z); then the target moves so
  // that the projected extents are centred, and D is found again.
  Real distance = size;
  for (int pass = 0; pass < 4; ++pass) {
    distance = 0;
    for (const Vec3& p : points) {
      const Vec3 q = centre + grow * (p - centre) - target;
      const Real x = std::abs(q.dot(basis.right_));
      const Real y = std::abs(q.dot(basis.up_));
      const Real z = q.dot(basis.forward_);
      distance = std::max({distance, x / tan_h - z, y / tan_v - z, 0.1 * size - z});
    }
    if (points.empty()) distance = size / tan_v;
    Real x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
    bool first = true;
    for (const Vec3& p : points) {
      const Vec3 q = centre + grow * (p - centre) - target;
      const Real depth = distance + q.dot(basis.forward_);
      const Real x = q.dot(basis.right_) / depth;
      const Real y = q.dot(basis.up_) / depth;
      x_lo = first ? x : std::min(x_lo, x);
      x_hi = first ? x : std::max(x_hi, x);
      y_lo = first ? y : std::min(y_lo, y);
      y_hi = first ? y : std::max(y_hi, y);
      first = false;
    }
    target += distance * (0.5 * (x_lo + x_hi) * basis.right_ + 0.5 * (y_lo + y_hi) * basis.up_);
  }
  return Camera(target - basis.forward_ * distance, target, view.up, view.fov_y_degrees);
}

}  // namespace rift
