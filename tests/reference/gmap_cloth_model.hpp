// The atomic springs of docs/physics.md matched on a 2D G-map, hand-written:
// stretch on every half-edge <0>, the diagonals of every quad face <0,1>, and a
// bending spring on every edge extremity <2> whose alpha_2 is linked. Plugged
// into the runtime's Simulation, it lets the tests compare the generic loop
// (mass model, pins, gravity, Integrator) against the flat ReferenceCloth,
// which builds the same springs from element lists instead of orbits.
#pragma once

#include <string>
#include <vector>

#include "reference_cloth.hpp"
#include "rift/sim/force_model.hpp"

namespace rift::reference {

class GMapClothModel final : public ForceModel {
 public:
  explicit GMapClothModel(const ClothParameters& params) : params_(params) {}

  const std::string& name() const override { return name_; }

  void initialise(GMap& map) override {
    position_ = map.embedding<Vec3>("position");
    springs_.clear();
    counts_ = {};
    // Stretch: the two darts of the half-edge.
    map.for_each_cell(Orbit{0}, [&](Dart d) {
      add(d, map.alpha(d, 0), params_.stretch_k, params_.stretch_c);
      ++counts_.stretch;
    });
    // Linear shear: a closed face of 8 darts, its corners c0..c3 along alpha_1 o alpha_0.
    map.for_each_cell(Orbit{0, 1}, [&](Dart d) {
      if (map.orbit_size(d, Orbit{0, 1}) != 8) return;
      Dart corner[4];
      Dart cur = d;
      for (Dart& c : corner) {
        c = cur;
        cur = map.alpha(map.alpha(cur, 0), 1);
      }
      if (cur != d) return;  // an open face is not a quad
      add(corner[0], corner[2], params_.shear_k, params_.shear_c);
      add(corner[1], corner[3], params_.shear_k, params_.shear_c);
      counts_.shear += 2;
    });
    // Linear bending: edge extremity {d, alpha_2 d} at A; L and R are the
    // far ends of A's other edges in the two faces.
    map.for_each_cell(Orbit{2}, [&](Dart d) {
      if (map.is_free(d, 2)) return;
      const Dart l = map.alpha(map.alpha(d, 1), 0);
      const Dart r = map.alpha(map.alpha(map.alpha(d, 2), 1), 0);
      add(l, r, params_.bend_k, params_.bend_c);
      ++counts_.bend;
    });
  }

  void rematch(const GMap& /*map*/, std::span<const Dart> /*region*/) override {}

  void add_forces(const ForceInput& in, Vec3* f, bool /*store*/) override {
    for (const Spring& s : springs_) {
      const Vec3 d = in.x[s.b] - in.x[s.a];
      const Real l = d.norm();
      if (!(l > 0)) continue;
      const Vec3 u = d / l;
      const Vec3 fa = (s.k * (l - s.rest) + s.c * (in.v[s.b] - in.v[s.a]).dot(u)) * u;
      f[s.a] += fa;
      f[s.b] -= fa;
    }
  }

  Real potential_energy(const ForceInput& in) const override {
    Real e = 0;
    for (const Spring& s : springs_) {
      const Real stretch = (in.x[s.b] - in.x[s.a]).norm() - s.rest;
      e += 0.5 * s.k * stretch * stretch;
    }
    return e;
  }

  std::size_t active_matches() const override { return springs_.size(); }
  const SpringCounts& counts() const { return counts_; }
  /// Spring ends are vertex slots of the position embedding.
  const std::vector<Spring>& springs() const { return springs_; }

 private:
  void add(Dart a, Dart b, Real k, Real c) {
    const Slot sa = position_.slot(a), sb = position_.slot(b);
    springs_.push_back({sa, sb, (position_.values()[sb] - position_.values()[sa]).norm(), k, c});
  }

  std::string name_ = "reference_gmap_cloth";
  ClothParameters params_;
  Embedding<Vec3> position_;
  std::vector<Spring> springs_;
  SpringCounts counts_;
};

}  // namespace rift::reference
