#include "rift/sim/bdf2.hpp"

namespace rift {

void Bdf2::step(ImplicitEuler& solver, const ImplicitEuler::ForceFn& force,
                const std::vector<Real>& mass, const std::vector<char>& is_free,
                const Vec3* target_v, std::vector<Vec3>& x, std::vector<Vec3>& v, Real h,
                const std::vector<Vec3>* f0) {
  const std::size_t n = x.size();
  if (!have_previous_ || x_previous_.size() != n || h != previous_h_) {
    // Start (again): one backward Euler step, remembering where it started.
    x_previous_.assign(x.begin(), x.end());
    v_previous_.assign(v.begin(), v.end());
    solver.step(force, mass, is_free, target_v, x, v, h, f0);
    have_previous_ = true;
    last_was_bdf2_ = false;
    previous_h_ = h;
    return;
  }
  const Real h_hat = 2 * h / 3;
  target_v_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 x_hat = (4 * x[i] - x_previous_[i]) / 3;
    const Vec3 v_hat = (4 * v[i] - v_previous_[i]) / 3;
    // A constrained slot lands where backward Euler would put it, x0 + h
    // target_v: from x̂ that takes the velocity (x0 + h target_v - x̂) / ĥ.
    const Vec3 land = x[i] + h * (target_v ? target_v[i] : Vec3::Zero());
    target_v_[i] = is_free[i] ? Vec3::Zero() : Vec3((land - x_hat) / h_hat);
    x_previous_[i] = x[i];
    v_previous_[i] = v[i];
    x[i] = x_hat;
    v[i] = v_hat;
  }
  // The forces at (x̂, v̂) are not those at (x0, v0): the solver evaluates them.
  solver.step(force, mass, is_free, target_v_.data(), x, v, h_hat, nullptr);
  last_was_bdf2_ = true;
}

}  // namespace rift
