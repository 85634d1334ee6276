#include "rift/sim/divergence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rift/core/parallel.hpp"
#include "rift/core/state_embeddings.hpp"
#include "rift/sim/simulation.hpp"

namespace rift {

namespace {

/// "vertex 12 of element 7" from the mesh's own numbering when the map kept
/// it (point_index, element_index), else the slot and a dart.
std::string describe_vertex(const Simulation& sim, Slot s) {
  const GMap& map = sim.map();
  const Embedding<std::int64_t> element = map.embedding<std::int64_t>(state::kElementIndex);
  const Embedding<std::int64_t> point = map.embedding<std::int64_t>(state::kPointIndex);
  const std::size_t n = map.capacity();
  for (std::size_t k = 0; k < n; ++k) {
    const Dart d = static_cast<Dart>(k);
    if (!map.is_alive(d) || sim.position().slot(d) != s) continue;
    std::string where =
        point ? fmt::format("vertex {}", point[d]) : fmt::format("vertex slot {}", s);
    if (element) where += fmt::format(" of element {}", element[d]);
    return where;
  }
  return fmt::format("vertex slot {}", s);
}

/// What to change in the scene: a smaller step, or an implicit integrator
/// when this build has one and the scene does not use it yet.
std::string suggested_fix(const Simulation& sim) {
  const SimulationSettings& s = sim.settings();
  std::string fix = fmt::format(
      "try a smaller time step ([simulation] dt = {:.3g}, a quarter of {:.3g})", s.dt / 4, s.dt);
  const auto implicit = parse_integrator("implicit_euler");
  if (implicit && !is_implicit(s.integrator)) {
    fix +=
        " or the unconditionally stable integrator ([simulation] integrator = \"implicit_euler\")";
  } else if (implicit) {
    fix += "; " + std::string(to_string(s.integrator)) +
           " diverged: more [implicit] newton_iterations or a tighter cg_tolerance";
  }
  return fix;
}

}  // namespace

void DivergenceMonitor::start(const Simulation& sim) {
  started_ = true;
  const OrbitAttachment& att = sim.position().attachment();
  const auto& x = sim.position().values();
  const auto& v = sim.velocity().values();
  const auto& m = sim.vertex_mass().values();
  const std::vector<Real>& w = sim.inverse_masses();
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity()), hi = -lo;
  Real kinetic = 0;
  free_mass_ = initial_speed_ = 0;
  for (Slot s = 0; s < x.size(); ++s) {
    if (!att.slot_alive(s)) continue;
    lo = lo.cwiseMin(x[s]);
    hi = hi.cwiseMax(x[s]);
    if (s < w.size() && w[s] > 0) {
      free_mass_ += m[s];
      kinetic += 0.5 * m[s] * v[s].squaredNorm();
      initial_speed_ = std::max(initial_speed_, v[s].norm());
    }
  }
  length_ = lo.allFinite() && hi.allFinite() ? (hi - lo).norm() : 0;
  Real elastic = 0;
  const ForceInput in{x.data(), v.data()};
  for (const auto& model : sim.force_models())
    elastic += model->potential_energy(in);
  initial_energy_ = kinetic + std::max<Real>(elastic, 0);
  if (!std::isfinite(initial_energy_)) initial_energy_ = 0;
  constrained_work_ = constrained_speed_ = 0;
}

namespace {

/// The largest speed of an obstacle at time t (0 without obstacles).
Real fastest_obstacle(const Simulation& sim, Real t) {
  Real speed = 0;
  if (const Contact* contact = sim.contact()) {
    for (const Obstacle& o : contact->obstacles())
      speed = std::max(speed, o.velocity_at(t).norm());
  }
  return speed;
}

}  // namespace

Real DivergenceMonitor::energy_bound(const Simulation& sim) const {
  const Real factor = sim.settings().divergence_factor;
  if (!(factor > 0)) return 0;
  const Real t = sim.time();
  const Real g = sim.settings().gravity.norm();
  const Real fall = length_ + initial_speed_ * t + 0.5 * g * t * t;
  // Moving obstacles and loads put energy in too: the work the external
  // forces and handles did so far, and the free mass at the fastest
  // obstacle's speed (a vertex it pushes takes its velocity).
  const Real pushed = std::max(constrained_speed_, fastest_obstacle(sim, t));
  const Real scale = initial_energy_ + free_mass_ * g * fall + constrained_work_ +
                     std::abs(sim.external_work()) + 0.5 * free_mass_ * pushed * pushed;
  return factor * scale;
}

void DivergenceMonitor::check(const Simulation& sim) {
  const OrbitAttachment& att = sim.position().attachment();
  const auto& x = sim.position().values();
  const auto& v = sim.velocity().values();
  const auto& m = sim.vertex_mass().values();
  const std::vector<Real>& w = sim.inverse_masses();
  const std::vector<Vec3>& f = sim.internal_forces();
  const Real dt = sim.settings().dt;
  // One flat pass over the vertices, in parallel blocks: the kinetic energy,
  // the fastest and the most energetic free vertex, and the work of
  // prescribed vertices (inverse mass 0, moving). Each block keeps its own
  // partial results; they are combined in block order below, so the outcome
  // does not depend on the thread count. On one thread this pass was 4 % of
  // an RK4 step of the 10⁶-vertex cloth, the step's last serial part.
  const std::size_t n = x.size();
  const std::size_t blocks = (n + kParallelBlock - 1) / kParallelBlock;
  if (partials_.size() < blocks) partials_.resize(blocks);
  // Non-finite values are caught by a probe, x - x + v - v summed over the
  // block (NaN as soon as one component is infinite or NaN, else 0), and
  // looked for vertex by vertex only then: testing each vertex with
  // branches was half the pass's instructions.
  auto scan = [&](std::size_t first, std::size_t last) {
    Partial p;
    Vec3 probe = Vec3::Zero();
    for (std::size_t k = first; k < last; ++k) {
      const Slot s = static_cast<Slot>(k);
      if (!att.slot_alive(s)) continue;
      probe += (x[s] - x[s]) + (v[s] - v[s]);
      const Real speed2 = v[s].squaredNorm();
      if (s < w.size() && w[s] > 0) {
        const Real e = 0.5 * m[s] * speed2;
        p.kinetic += e;
        if (e > p.top_energy) p.top_energy = e, p.most_energetic = s;
        if (speed2 > p.top_speed2) p.top_speed2 = speed2, p.fastest = s;
      } else if (speed2 > 0) {
        if (s < f.size()) p.work += std::abs(f[s].dot(v[s])) * dt;
        p.constrained_speed = std::max(p.constrained_speed, std::sqrt(speed2));
      }
    }
    if (!probe.allFinite()) {
      for (std::size_t k = first; k < last; ++k) {
        const Slot s = static_cast<Slot>(k);
        if (att.slot_alive(s) && (!x[s].allFinite() || !v[s].allFinite())) {
          p.bad = s;
          break;
        }
      }
    }
    partials_[first / kParallelBlock] = p;
  };
  parallel_blocks(n, kParallelBlock, scan);
  // In block order, with the serial pass's ties: the first slot wins.
  Real kinetic = 0, top_speed = 0, top_energy = -1;
  Slot fastest = kNoSlot, most_energetic = kNoSlot, bad = kNoSlot;
  for (std::size_t b = 0; b < blocks && bad == kNoSlot; ++b) {
    const Partial& p = partials_[b];
    if (p.bad != kNoSlot) {
      bad = p.bad;
      break;
    }
    kinetic += p.kinetic;
    if (p.top_energy > top_energy) top_energy = p.top_energy, most_energetic = p.most_energetic;
    if (p.top_speed2 > top_speed) top_speed = p.top_speed2, fastest = p.fastest;
    constrained_work_ += p.work;
    constrained_speed_ = std::max(constrained_speed_, p.constrained_speed);
  }
  top_speed = std::sqrt(top_speed);
  // Formatted only on failure: a passing check allocates nothing.
  auto when = [&] {
    return fmt::format("at step {} (t = {:.6g} s)", sim.steps_done(), sim.time());
  };
  if (bad != kNoSlot) {
    throw SimulationError(
        fmt::format("the simulation exploded {}: non-finite position or velocity at {}; {}", when(),
                    describe_vertex(sim, bad), suggested_fix(sim)));
  }
  if (!(sim.settings().divergence_factor > 0)) return;
  const Real bound = energy_bound(sim);
  if (bound > 0 && kinetic > bound) {
    throw SimulationError(fmt::format(
        "the simulation diverged {}: kinetic energy {:.3g} J exceeds {:.3g} J, {:g} times the "
        "scene's energy scale (initial energy {:.3g} J, {:.3g} kg free to fall under gravity, "
        "work of prescribed vertices {:.3g} J); the most energetic is {} "
        "({:.3g} J, {:.3g} m/s); {}",
        when(), kinetic, bound, sim.settings().divergence_factor, initial_energy_, free_mass_,
        constrained_work_, describe_vertex(sim, most_energetic), top_energy,
        v[most_energetic].norm(), suggested_fix(sim)));
  }
  const Real g = sim.settings().gravity.norm();
  const Real reach = length_ + (initial_speed_ + g * sim.time() +
                                std::max(constrained_speed_, fastest_obstacle(sim, sim.time()))) *
                                   dt;
  if (fastest != kNoSlot && length_ > 0 && top_speed * dt > reach) {
    throw SimulationError(fmt::format(
        "the simulation diverged {}: {} moves at {:.3g} m/s, {:.3g} m in one step, farther than "
        "the whole body ({:.3g} m across); {}",
        when(), describe_vertex(sim, fastest), top_speed, top_speed * dt, length_,
        suggested_fix(sim)));
  }
}

}  // namespace rift
