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

  // Analytic Jacobians (hand-derived, to test the implicit integrator apart
  // from riftc's derivatives). With d = x_b - x_a, l = |d|, u = d / l,
  // P = I - u uᵀ, w = v_b - v_a and t = k (l - L) + c w·u, f_a = t u = -f_b:
  //   ∂f_a/∂x_b = u (k u + c P w / l)ᵀ + t P / l = K,   ∂f_a/∂x_a = -K,
  //   ∂f_a/∂v_b = c u uᵀ,                              ∂f_a/∂v_a = -c u uᵀ,
  // and f_b = -f_a gives the other row.
  int jacobian_vertices() const override { return 2; }

  void jacobians(const ForceInput& in, Slot* slots, Mat3* dfdx, Mat3* dfdv) override {
    for (std::size_t i = 0; i < springs_.size(); ++i) {
      Mat3 kx, kv;
      blocks(in, i, kx, kv);
      slots[2 * i] = springs_[i].a;
      slots[2 * i + 1] = springs_[i].b;
      Mat3* jx = dfdx + 4 * i;
      Mat3* jv = dfdv + 4 * i;
      jx[0] = -kx, jx[1] = kx, jx[2] = kx, jx[3] = -kx;  // (a,a) (a,b) (b,a) (b,b)
      jv[0] = -kv, jv[1] = kv, jv[2] = kv, jv[3] = -kv;
    }
  }

  void add_jacobian_product(const ForceInput& in, const Vec3* px, const Vec3* pv,
                            Vec3* out) override {
    for (std::size_t i = 0; i < springs_.size(); ++i) {
      Mat3 kx, kv;
      blocks(in, i, kx, kv);
      const Slot a = springs_[i].a, b = springs_[i].b;
      const Vec3 df = kx * (px[b] - px[a]) + kv * (pv[b] - pv[a]);
      out[a] += df;
      out[b] -= df;
    }
  }

 private:
  struct Spring {
    Slot a, b;
  };
  void blocks(const ForceInput& in, std::size_t i, Mat3& kx, Mat3& kv) const {
    const Spring& s = springs_[i];
    const Vec3 d = in.x[s.b] - in.x[s.a];
    const Real len = d.norm();
    const Vec3 u = d / len;
    const Vec3 w = in.v[s.b] - in.v[s.a];
    const Mat3 p = Mat3::Identity() - u * u.transpose();
    const Real tension = k_ * (len - rest_[i]) + c_ * w.dot(u);
    kx = u * (k_ * u + c_ * p * w / len).transpose() + tension * p / len;
    kv = c_ * u * u.transpose();
  }
  std::string name_ = "test_half_edge_springs";
  Real k_, c_;
  Embedding<Vec3> position_;
  std::vector<Spring> springs_;
  std::vector<Real> rest_;
};

}  // namespace rift::test
