#include "rift/sim/loads.hpp"

#include <algorithm>

namespace rift {

Real GroupLoad::factor(Real t) const {
  if (t < spec_.start) return 0;
  if (spec_.ramp <= 0) return 1;
  return std::min<Real>(1, (t - spec_.start) / spec_.ramp);
}

void GroupLoad::add_forces(const GMap& map, const ExternalInput& in, Vec3* f) {
  const Real k = factor(in.time);
  if (k == 0) return;
  const OrbitAttachment& att = *map.attachment_of("position");
  auto member = [&](Slot s) {
    return att.slot_alive(s) && (spec_.group < 0 || groups_->contains(s, spec_.group));
  };
  if (!spec_.acceleration.isZero()) {
    for (Slot s = 0; s < in.slots; ++s)
      if (member(s)) f[s] += k * in.mass[s] * spec_.acceleration;
  }
  if (spec_.force.isZero()) return;
  if (spec_.per_vertex) {
    for (Slot s = 0; s < in.slots; ++s)
      if (member(s)) f[s] += k * spec_.force;
    return;
  }
  // A total force spread by mass: each vertex gets m_i / M of it, so that the
  // group accelerates uniformly when free.
  Real total = 0;
  for (Slot s = 0; s < in.slots; ++s)
    if (member(s)) total += in.mass[s];
  if (total <= 0) return;
  const Vec3 per_kg = k * spec_.force / total;
  for (Slot s = 0; s < in.slots; ++s)
    if (member(s)) f[s] += in.mass[s] * per_kg;
}

void SurfaceDrag::add_forces(const GMap& map, const ExternalInput& in, Vec3* f) {
  if (map.dimension() != 2) return;
  const OrbitAttachment& att = *map.attachment_of("position");
  map.for_each_cell(Orbit{0, 1}, [&](Dart face) {
    corners_.clear();
    // The corners of the face, once each: every other dart of the <0,1> orbit.
    Dart d = face;
    do {
      corners_.push_back(att.slot(d));
      d = map.alpha(map.alpha(d, 0), 1);
    } while (d != face && corners_.size() < 64);
    const std::size_t k = corners_.size();
    if (k < 3) return;
    // Newell's normal times the area, and the mean velocity.
    Vec3 area_normal = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    for (std::size_t i = 0; i < k; ++i) {
      area_normal += 0.5 * in.x[corners_[i]].cross(in.x[corners_[(i + 1) % k]]);
      velocity += in.v[corners_[i]];
    }
    velocity /= static_cast<Real>(k);
    const Real area = area_normal.norm();
    if (area <= 0) return;
    const Vec3 n = area_normal / area;
    const Vec3 force = -coefficient_ * area * (velocity - wind_).dot(n) * n;
    for (Slot s : corners_)
      f[s] += force / static_cast<Real>(k);
  });
}

}  // namespace rift
