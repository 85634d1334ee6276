// The simulation loop of §3.3 over a G-map: interactions store their forces
// in their orbits and add them per vertex, accelerations a = f / m + g are
// integrated, and (later in the loop) criteria trigger rewrites after which
// only the touched vertices' masses and the touched matches are updated.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "rift/gmap/gmap.hpp"
#include "rift/sim/force_model.hpp"
#include "rift/sim/integrator.hpp"

namespace rift {

struct SimulationSettings {
  IntegratorKind integrator = IntegratorKind::kRK4;
  Real dt = 1e-3;
  Vec3 gravity = Vec3(0, 0, -9.81);
};

/// Names of the embeddings the loop itself uses. `position` comes from the
/// mesh; the others are declared by the simulation when the map lacks them.
namespace embedding_names {
inline constexpr const char* kPosition = "position";
inline constexpr const char* kVelocity = "velocity";
inline constexpr const char* kVertexMass = "vertex_mass";
inline constexpr const char* kCornerMass = "corner_mass";
inline constexpr const char* kPinned = "pinned";
}  // namespace embedding_names

class Simulation {
 public:
  Simulation(GMap map, SimulationSettings settings);

  GMap& map() { return map_; }
  const GMap& map() const { return map_; }
  const SimulationSettings& settings() const { return settings_; }

  void add_force_model(std::unique_ptr<ForceModel> model);
  const std::vector<std::unique_ptr<ForceModel>>& force_models() const { return models_; }

  /// Corner masses from a total mass (spread by area or volume) or a density.
  void set_total_mass(Real total_mass);
  void set_density(Real density);
  /// Fixes every vertex for which pred(position) holds; returns how many.
  template <class Pred>
  std::size_t pin_where(Pred&& pred);

  /// Computes vertex masses and initialises every interaction. Call once,
  /// after masses and pins are set and models added.
  void initialise();

  /// One step: forces at the current state (stored in their orbits), then
  /// the integrator advances positions and velocities by dt.
  void step();

  /// After rewrites: recompute the masses of the vertices of `touched`
  /// darts and re-match the interactions around them.
  void on_topology_changed(std::span<const Dart> touched);

  Real time() const { return time_; }
  std::size_t steps_done() const { return steps_; }

  Embedding<Vec3>& position() { return position_; }
  Embedding<Vec3>& velocity() { return velocity_; }
  Embedding<Real>& vertex_mass() { return vertex_mass_; }
  Embedding<Real>& corner_mass() { return corner_mass_; }
  const Embedding<Vec3>& position() const { return position_; }
  const Embedding<Vec3>& velocity() const { return velocity_; }
  const Embedding<Real>& vertex_mass() const { return vertex_mass_; }
  /// Total internal force on each vertex slot at the start of the last step.
  const std::vector<Vec3>& internal_forces() const { return start_forces_; }

  Real kinetic_energy() const;
  /// Gravity plus every interaction's elastic energy.
  Real potential_energy() const;
  Vec3 momentum() const;
  Real total_mass() const;

 private:
  void accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& a,
                     bool store);
  void refresh_inverse_masses();

  GMap map_;
  SimulationSettings settings_;
  Integrator integrator_;
  std::vector<std::unique_ptr<ForceModel>> models_;
  Embedding<Vec3> position_, velocity_;
  Embedding<Real> vertex_mass_, corner_mass_;
  Embedding<Bool> pinned_;
  std::vector<Vec3> forces_, start_forces_, a0_;
  std::vector<Real> inverse_mass_;  // 0 for pinned vertices and free slots
  std::vector<Dart> region_;
  Real time_ = 0;
  std::size_t steps_ = 0;
  bool initialised_ = false;
};

template <class Pred>
std::size_t Simulation::pin_where(Pred&& pred) {
  std::size_t count = 0;
  map_.for_each_cell(Orbit::cell(0, map_.dimension()), [&](Dart v) {
    if (pred(position_[v])) {
      pinned_[v] = true;
      ++count;
    }
  });
  return count;
}

}  // namespace rift
