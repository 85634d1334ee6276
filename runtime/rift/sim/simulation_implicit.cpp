// Simulation's step with integrator = implicit_euler: the glue between the
// loop's state (masses, pins, forces) and ImplicitEuler.
#include "rift/sim/simulation.hpp"

namespace rift {

void Simulation::implicit_step() {
  std::vector<Vec3>& x = position_.values();
  std::vector<Vec3>& v = velocity_.values();
  const std::vector<Real>& mass = vertex_mass_.values();
  const std::size_t n = x.size();
  // Constrained (pinned) and dead slots are Dirichlet vertices; their
  // target velocity is zero until moving handles exist.
  is_free_.resize(n);
  for (std::size_t s = 0; s < n; ++s)
    is_free_[s] = inverse_mass_[s] > 0;
  const Vec3 g = settings_.gravity;
  // Total force = interactions + gravity (external: no Jacobian).
  auto add_external = [&](std::vector<Vec3>& f) {
    for (std::size_t s = 0; s < n; ++s)
      if (is_free_[s]) f[s] += mass[s] * g;
  };
  a0_.assign(forces_.begin(), forces_.end());  // forces at (x, v), computed by step()
  add_external(a0_);
  implicit_->step(
      [&](const std::vector<Vec3>& xs, const std::vector<Vec3>& vs, std::vector<Vec3>& f) {
        accelerations(xs, vs, scratch_a_, false);
        f.assign(forces_.begin(), forces_.end());
        add_external(f);
      },
      mass, is_free_, nullptr, x, v, settings_.dt, &a0_);
}

}  // namespace rift
