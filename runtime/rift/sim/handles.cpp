#include "rift/sim/handles.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <iterator>
#include <numbers>
#include <stdexcept>

#include "rift/core/state_embeddings.hpp"

namespace rift {

namespace {

Mat3 rotation_of(const Vec3& rotate_degrees) {
  const Real angle = rotate_degrees.norm() * std::numbers::pi / 180;
  if (angle == 0) return Mat3::Identity();
  return Eigen::AngleAxis<Real>(angle, rotate_degrees.normalized()).toRotationMatrix();
}

}  // namespace

Vec3 HandleMotion::place(const Vec3& rest, Real t) const {
  Vec3 translate = Vec3::Zero();
  Vec3 rotate = Vec3::Zero();
  if (!keyframes.empty()) {
    if (t <= keyframes.front().time) {
      translate = keyframes.front().translate;
      rotate = keyframes.front().rotate_degrees;
    } else if (t >= keyframes.back().time) {
      translate = keyframes.back().translate;
      rotate = keyframes.back().rotate_degrees;
    } else {
      const auto next = std::upper_bound(keyframes.begin(), keyframes.end(), t,
                                         [](Real u, const Keyframe& k) { return u < k.time; });
      const Keyframe& b = *next;
      const Keyframe& a = *(next - 1);
      const Real w = b.time > a.time ? (t - a.time) / (b.time - a.time) : 1;
      translate = (1 - w) * a.translate + w * b.translate;
      rotate = (1 - w) * a.rotate_degrees + w * b.rotate_degrees;
    }
  }
  return pivot + rotation_of(rotate) * (rest - pivot) + translate + velocity * t;
}

Handles::Handles(GMap& map) : map_(map) {
  const Orbit vertex = Orbit::cell(0, map.dimension());
  handle_ = map.embedding<std::int64_t>("handle");
  if (!handle_)
    handle_ = map.add_embedding<std::int64_t>("handle", vertex, MergePolicy::kKeepFirst, -1);
  position_ = map.embedding<Vec3>(state::kPosition);
  // A map that brings its rest positions (or has no positions to stand in
  // for them) keeps them.
  rest_ = map.embedding<Vec3>("handle_rest");
  if (!position_) keep_rest();
  if (handle_.orbit() != vertex || (rest_ && rest_.orbit() != vertex) ||
      (position_ && position_.orbit() != vertex)) {
    throw std::invalid_argument(
        "the embeddings 'handle', 'handle_rest' and 'position' must live on vertices");
  }
}

void Handles::keep_rest() {
  if (rest_) return;
  const Orbit vertex = Orbit::cell(0, map_.dimension());
  rest_ = map_.add_embedding<Vec3>("handle_rest", vertex, MergePolicy::kMean, Vec3::Zero());
  // Every vertex held so far stands where its fixed handle holds it.
  if (position_) {
    std::vector<Vec3>& rest = rest_.values();
    const std::vector<Vec3>& x = position_.values();
    std::copy(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(std::min(x.size(), rest.size())),
              rest.begin());
  }
}

int Handles::add(HandleMotion motion) {
  std::sort(motion.keyframes.begin(), motion.keyframes.end(),
            [](const auto& a, const auto& b) { return a.time < b.time; });
  if (!motion.fixed()) keep_rest();
  motions_.push_back(std::move(motion));
  return static_cast<int>(motions_.size() - 1);
}

bool Handles::hold(Dart d, int index, const Vec3& rest) {
  if (handle_[d] >= 0 && handle_[d] != index) return false;
  if (!rest_ && rest != position_[d]) keep_rest();
  handle_[d] = index;
  if (rest_) rest_[d] = rest;
  held_stale_ = true;
  return true;
}

bool Handles::releases_between(Real t0, Real t1) const {
  return std::any_of(motions_.begin(), motions_.end(),
                     [&](const HandleMotion& m) { return m.release > t0 && m.release <= t1; });
}

Vec3 Handles::target(Slot s, Real t) const {
  if (!rest_) return position_.values()[s];
  return motions_[static_cast<std::size_t>(handle_.values()[s])].place(rest_.values()[s], t);
}

Vec3 Handles::target_velocity(Slot s, Real t, Real dt) const {
  return (target(s, t + dt) - target(s, t)) / dt;
}

const std::vector<Slot>& Handles::held_slots(const OrbitAttachment& alive) const {
  if (held_stale_) {
    held_.clear();
    const std::vector<std::int64_t>& handle = handle_.values();
    for (Slot s = 0; s < handle.size(); ++s) {
      if (handle[s] >= 0 && alive.slot_alive(s)) held_.push_back(s);
    }
    held_stale_ = false;
    ++held_sweeps_;
  }
  return held_;
}

void Handles::topology_changed(const GMap& map, std::span<const Dart> region) {
  if (held_stale_) return;  // swept at the next use anyway
  const OrbitAttachment& att = handle_.attachment();
  const std::vector<std::int64_t>& handle = handle_.values();
  std::erase_if(held_,
                [&](Slot s) { return s >= handle.size() || !att.slot_alive(s) || handle[s] < 0; });
  const std::size_t kept = held_.size();
  for (const Dart d : region) {
    if (d >= map.capacity() || !map.is_alive(d)) continue;
    const Slot s = att.slot(d);
    if (s != kNoSlot && s < handle.size() && handle[s] >= 0) held_.push_back(s);
  }
  if (held_.size() == kept) return;
  // The region's held slots, sorted, merged into the kept ones (without
  // std::inplace_merge's buffer: a warm tear allocates nothing).
  const auto middle = held_.begin() + static_cast<std::ptrdiff_t>(kept);
  std::sort(middle, held_.end());
  merged_.clear();
  std::merge(held_.begin(), middle, middle, held_.end(), std::back_inserter(merged_));
  merged_.erase(std::unique(merged_.begin(), merged_.end()), merged_.end());
  held_.swap(merged_);
}

void Handles::impose(const OrbitAttachment& alive, Real t, Real dt, std::vector<Vec3>& x,
                     std::vector<Vec3>& v) const {
  for (Slot s : held_slots(alive)) {
    if (s >= x.size() || !holds(s, t)) continue;
    x[s] = target(s, t);
    v[s] = target_velocity(s, t, dt);
  }
}

void Handles::reactions(const OrbitAttachment& alive, Real t, const std::vector<Vec3>& forces,
                        const std::vector<Real>& mass, const Vec3& gravity,
                        std::vector<Vec3>& per_handle) const {
  // Summed per handle in slot order, as a sweep of every slot would.
  per_handle.assign(motions_.size(), Vec3::Zero());
  for (Slot s : held_slots(alive)) {
    if (s >= forces.size() || !holds(s, t)) continue;
    per_handle[static_cast<std::size_t>(handle_.values()[s])] -= forces[s] + mass[s] * gravity;
  }
}

}  // namespace rift
