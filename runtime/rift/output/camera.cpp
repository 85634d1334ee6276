#include "rift/output/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

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
  const Vec3 centre = 0.5 * (lo + hi);
  Vec3 half = 0.5 * view.expand * (hi - lo);
  const Real size = std::max(half.norm(), Real(1e-9));
  // A flat box (a cloth) still needs some depth for a sensible distance.
  half = half.cwiseMax(Vec3::Constant(1e-6 * size));
  Vec3 direction = view.direction.squaredNorm() > 0 ? view.direction.normalized() : Vec3::UnitZ();
  Camera basis(centre + direction, centre, view.up, view.fov_y_degrees);
  const Real tan_v = basis.tan_half_fov_ * (1.0 - view.margin);
  const Real tan_h = tan_v * aspect;
  // Smallest distance at which every corner of the box projects inside the
  // margins: |x| <= tan_h * (D + z) and |y| <= tan_v * (D + z).
  Real distance = 0;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner((c & 1) ? half.x() : -half.x(), (c & 2) ? half.y() : -half.y(),
                      (c & 4) ? half.z() : -half.z());
    const Real x = std::abs(corner.dot(basis.right_));
    const Real y = std::abs(corner.dot(basis.up_));
    const Real z = corner.dot(basis.forward_);
    distance = std::max({distance, x / tan_h - z, y / tan_v - z, 0.1 * size - z});
  }
  return Camera(centre - basis.forward_ * distance, centre, view.up, view.fov_y_degrees);
}

}  // namespace rift
