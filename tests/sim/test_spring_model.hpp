// A hand-written stretch spring on every half-edge <0>, used to test the
// simulation loop before generated interactions exist. The real interactions
// live in rules/ and are compiled by riftc.
#pragma once

#include <vector>

#include "rift/sim/force_model.hpp"

namespace rift::test {

class HalfEdgeSprings final : public ForceModel {
 public:
  HalfEdgeSprings(Real stiffness, Real damping) : k_(stiffness), c_(damping) {}

  const std::string& name() const override { return name_; }

  void initialise(GMap& map) override {
    position_ = map.embedding<Vec3>("position");
    rematch(map, {});
    rest_.clear();
    for (const Spring& s : springs_)
      rest_.push_back((position_.values()[s.b] - position_.values()[s.a]).norm());
  }

  void rematch(const GMap& map, std::span<const Dart>) override {
    springs_.clear();
    map.for_each_cell(Orbit{0}, [&](Dart d) {
      springs_.push_back({position_.slot(d), position_.slot(map.alpha(d, 0))});
    });
  }

  void add_forces(const ForceInput& in, Vec3* f, bool) override {
    for (std::size_t i = 0; i < springs_.size(); ++i) {
      const Spring& s = springs_[i];
      const Vec3 d = in.x[s.b] - in.x[s.a];
      const Real len = d.norm();
      const Vec3 u = d / len;
      const Real tension = k_ * (len - rest_[i]) + c_ * (in.v[s.b] - in.v[s.a]).dot(u);
      f[s.a] += tension * u;
      f[s.b] -= tension * u;
    }
  }

  Real potential_energy(const ForceInput& in) const override {
    Real e = 0;
    for (std::size_t i = 0; i < springs_.size(); ++i) {
      const Real stretch = (in.x[springs_[i].b] - in.x[springs_[i].a]).norm() - rest_[i];
      e += 0.5 * k_ * stretch * stretch;
    }
    return e;
  }

  std::size_t active_matches() const override { return springs_.size(); }

 private:
  struct Spring {
    Slot a, b;
  };
  std::string name_ = "test_half_edge_springs";
  Real k_, c_;
  Embedding<Vec3> position_;
  std::vector<Spring> springs_;
  std::vector<Real> rest_;
};

}  // namespace rift::test
