// Simulation's step with integrator = implicit_euler or bdf2: the glue
// between the loop's state (masses, pins, forces) and ImplicitEuler.
#include "rift/sim/handles.hpp"
#include "rift/sim/simulation.hpp"

namespace rift {

void Simulation::implicit_step() {
  std::vector<Vec3>& x = position_.values();
  std::vector<Vec3>& v = velocity_.values();
  const std::vector<Real>& mass = vertex_mass_.values();
  const std::size_t n = x.size();
  // Constrained slots (pins, held by a handle, dead) are Dirichlet degrees
  // of freedom of the linear system: their end-of-step velocity is
  // prescribed, and the solve sees them move. A held vertex gets the
  // velocity that lands it on its handle's target at t + h exactly
  // (x1 = x0 + h v1), so the free vertices around it respond to that motion
  // within the same step (never a post-step overwrite the solve did not
  // know of); pins and dead slots stay where they are.
  is_free_.resize(n);
  target_v_.resize(n);
  const OrbitAttachment& att = position_.attachment();
  const Real h = settings_.dt;
  for (std::size_t s = 0; s < n; ++s) {
    is_free_[s] = inverse_mass_[s] > 0;
    const bool held = !is_free_[s] && handles_ && att.slot_alive(static_cast<Slot>(s)) &&
                      handles_->holds(static_cast<Slot>(s), time_);
    target_v_[s] =
        held ? Vec3((handles_->target(static_cast<Slot>(s), time_ + h) - x[s]) / h) : Vec3::Zero();
  }
  const Vec3 g = settings_.gravity;
  // Total force = interactions + gravity (external: no Jacobian).
  auto add_external = [&](std::vector<Vec3>& f) {
    for (std::size_t s = 0; s < n; ++s)
      if (is_free_[s]) f[s] += mass[s] * g;
  };
  // The forces at (x, v) with gravity, in forces_ (free between the step's
  // swap and the next step's start_forces()).
  std::vector<Vec3>& f0 = forces_;
  f0.assign(start_forces_.begin(), start_forces_.end());
  forces_zero_ = false;
  add_external(f0);
  // Two captures (16 bytes) stay in std::function's own buffer: a warm step
  // allocates nothing.
  const ImplicitEuler::ForceFn force = [this, &add_external](const std::vector<Vec3>& xs,
                                                             const std::vector<Vec3>& vs,
                                                             std::vector<Vec3>& f) {
    f.assign(xs.size(), Vec3::Zero());
    add_stage_forces(xs, vs, f);
    add_external(f);
  };
  if (settings_.integrator == IntegratorKind::kBdf2) {
    bdf2_.step(*implicit_, force, mass, is_free_, target_v_.data(), x, v, h, &f0);
  } else {
    implicit_->step(force, mass, is_free_, target_v_.data(), x, v, h, &f0);
  }
}

}  // namespace rift
