// A perspective camera chosen once, from the first frame's bounding box, and
// kept across frames so that the view does not jump as the body moves.
#pragma once

#include <span>

#include "rift/core/types.hpp"

namespace rift {

/// How a camera looks at a box: from `direction` (target toward eye), with
/// `up` pointing up on screen, leaving `margin` of the image free on each side.
struct CameraView {
  Vec3 direction{0.45, 0.35, 1.0};
  Vec3 up{0.0, 1.0, 0.0};
  Real fov_y_degrees = 30.0;
  Real margin = 0.1;  ///< fraction of the half-width left free at each side
  Real expand = 1.0;  ///< grows the box around its centre (room for motion)
};

struct ScreenPoint {
  Real x;      ///< pixels from the left
  Real y;      ///< pixels from the top
  Real depth;  ///< distance along the view axis; <= near means behind
};

class Camera {
 public:
  Camera() = default;
  Camera(const Vec3& eye, const Vec3& target, const Vec3& up, Real fov_y_degrees);

  /// A camera that shows all of [lo, hi] in an image of aspect width/height.
  static Camera framing(const Vec3& lo, const Vec3& hi, Real aspect, const CameraView& view = {});
  /// A camera that shows every point, centred on their projection: a tighter
  /// fit than the bounding box's for curved or thin bodies.
  static Camera framing(std::span<const Vec3> points, Real aspect, const CameraView& view = {});

  /// Projects a world point onto an image of the given size.
  ScreenPoint project(const Vec3& p, int width, int height) const {
    const Vec3 q = p - eye_;
    const Real z = q.dot(forward_);
    const Real f = 0.5 * height / tan_half_fov_;
    const Real inv = z > 0 ? 1.0 / z : 0.0;
    return {0.5 * width + q.dot(right_) * inv * f, 0.5 * height - q.dot(up_) * inv * f, z};
  }

  const Vec3& eye() const { return eye_; }
  const Vec3& target() const { return target_; }
  const Vec3& forward() const { return forward_; }
  const Vec3& right() const { return right_; }
  const Vec3& up() const { return up_; }
  bool valid() const { return tan_half_fov_ > 0; }

 private:
  Vec3 eye_ = Vec3(0, 0, 1);
  Vec3 target_ = Vec3::Zero();
  Vec3 forward_ = Vec3(0, 0, -1);
  Vec3 right_ = Vec3(1, 0, 0);
  Vec3 up_ = Vec3(0, 1, 0);
  Real tan_half_fov_ = 0;
};

}  // namespace rift
