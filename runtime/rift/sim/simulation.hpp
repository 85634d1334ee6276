// The simulation loop of §3.3 over a G-map: interactions store their forces
// in their orbits and add them per vertex, accelerations a = f / m + g are
// integrated, and (later in the loop) criteria trigger rewrites after which
// only the touched vertices' masses and the touched matches are updated.
#pragma once

#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "rift/core/memory_report.hpp"
#include "rift/gmap/gmap.hpp"
#include "rift/sim/bdf2.hpp"
#include "rift/sim/criterion.hpp"
#include "rift/sim/divergence.hpp"
#include "rift/sim/external_force.hpp"
#include "rift/sim/force_model.hpp"
#include "rift/sim/handles.hpp"
#include "rift/sim/implicit_euler.hpp"
#include "rift/sim/integrator.hpp"
#include "rift/sim/mass_model.hpp"
#include "rift/sim/obstacles.hpp"
#include "rift/sim/setup_phases.hpp"

namespace rift {

struct SimulationSettings {
  IntegratorKind integrator = IntegratorKind::kRK4;
  Real dt = 1e-3;
  Vec3 gravity = Vec3(0, 0, -9.81);
  /// At most this many rewrites per step (0: no cap).
  int max_tears_per_step = 0;
  /// Check the G-map's validity after every rewrite (rift run --check).
  bool check_each_rewrite = false;
  /// Safety factor S of the divergence check (divergence.hpp): the run stops
  /// when the kinetic energy exceeds S times the scene's energy scale or a
  /// vertex crosses the whole body in one step. 0 keeps only the finite check.
  Real divergence_factor = 100;
  /// Solver settings of integrator = implicit_euler (the scene's [implicit]).
  ImplicitSettings implicit = {};
  /// Evaluate identical matches of an interaction once (same forces to
  /// rounding, rift/sim/match_groups.hpp); false evaluates each match.
  bool group_interactions = true;
  /// Evaluate rift::lanes::kWidth matches at once where riftc gave an
  /// interaction a lanes form (the same forces to the bit,
  /// rift/core/lanes.hpp); false runs the scalar body on each match, to compare.
  bool lanes = true;
  /// The map may be rewritten after initialise (criteria, or a caller's own
  /// rewrites announced by on_topology_changed). false, for a scene without
  /// criteria: the interactions keep none of what only re-matching reads
  /// (ForceModel::set_rewrites), and on_topology_changed throws.
  bool rewrites = true;
  /// false, for a map never rewritten (rewrites = false) whose corner
  /// masses nothing reads but the vertex masses (no pack of the scene reads
  /// `corner_mass`): the vertex masses are summed from the elements' masses
  /// at initialise, the same bits, and no corner mass is kept (no column,
  /// and no corner slots unless another column needs them: 80 MB of a
  /// 10^6-vertex cloth). An interaction that asks for corner_mass anyway
  /// makes initialise throw. Ignored (kept) when the map is rewritten.
  bool keep_corner_masses = true;
};

/// A simulation that cannot go on: exploded state or an invalid map.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Simulation {
 public:
  Simulation(GMap map, const SimulationSettings& settings);

  GMap& map() { return map_; }
  const GMap& map() const { return map_; }
  const SimulationSettings& settings() const { return settings_; }

  void add_force_model(std::unique_ptr<ForceModel> model);
  void add_criterion(std::unique_ptr<Criterion> criterion);
  const std::vector<std::unique_ptr<Criterion>>& criteria() const { return criteria_; }
  const std::vector<std::unique_ptr<ForceModel>>& force_models() const { return models_; }

  /// Corner masses from a total mass (spread by area or volume) or a density
  /// (without corner masses: the elements' masses, for initialise).
  void set_total_mass(Real total_mass);
  void set_density(Real density);
  /// Fixes every vertex for which pred(position) holds; returns how many.
  template <class Pred>
  std::size_t pin_where(Pred&& pred);

  /// Scene drivers (docs/scenes.md): prescribed motions, external forces and
  /// obstacles. Handles and external forces are set before initialise().
  void set_handles(std::unique_ptr<Handles> handles);
  void add_external_force(std::unique_ptr<ExternalForce> force);
  void set_contact(std::unique_ptr<Contact> contact);
  const Handles* handles() const { return handles_.get(); }
  const Contact* contact() const { return contact_.get(); }
  /// The force each handle exerts on the body at the start of the last step.
  const std::vector<Vec3>& handle_reactions() const { return reactions_; }
  /// Work done on the body by external forces and handles since the start
  /// (gravity excluded: it is in the potential energy).
  Real external_work() const { return external_work_; }

  /// Computes vertex masses and initialises every interaction. Call once,
  /// after masses and pins are set and models added.
  /// With `phases`, ends a phase after the vertex masses, after each
  /// interaction ("interaction NAME") and after the criteria.
  void initialise(SetupPhases* phases = nullptr);

  /// One step (§3.3, Fig. 3, starting from the forces):
  ///  1. every interaction computes its forces at the current state and
  ///     stores them in its orbits; they are gathered per vertex;
  ///  2. every criterion is evaluated on those forces; the candidates are
  ///     applied in a deterministic order (criterion order, then most
  ///     critical first, then smaller dart), each matched again just before it
  ///     applies, up to max_tears_per_step;
  ///  3. if the map changed: masses of touched vertices and matches around
  ///     them are updated, and forces recomputed;
  ///  4. the integrator advances positions and velocities by dt, and a
  ///     diverged state (divergence.hpp) stops the simulation with a
  ///     SimulationError.
  /// Throws Interrupted (rift/core/interrupt.hpp) part-way when an interrupt
  /// was requested; the state is then not that of a finished step.
  void step();

  /// After rewrites: recompute the masses of the vertices of `touched`
  /// darts and re-match the interactions around them.
  void on_topology_changed(std::span<const Dart> touched);

  Real time() const { return time_; }
  /// Rewrites applied since the start, and in the last step.
  std::size_t tears() const { return tears_; }
  std::size_t tears_last_step() const { return tears_last_step_; }
  std::size_t steps_done() const { return steps_; }

  Embedding<Vec3>& position() { return position_; }
  Embedding<Vec3>& velocity() { return velocity_; }
  Embedding<Real>& vertex_mass() { return vertex_mass_; }
  /// Empty when the corner masses are not kept (keeps_corner_masses).
  Embedding<Real>& corner_mass() { return corner_mass_; }
  bool keeps_corner_masses() const { return settings_.keep_corner_masses || settings_.rewrites; }
  const Embedding<Vec3>& position() const { return position_; }
  const Embedding<Vec3>& velocity() const { return velocity_; }
  const Embedding<Real>& vertex_mass() const { return vertex_mass_; }
  /// Total internal force on each vertex slot at the start of the last step.
  const std::vector<Vec3>& internal_forces() const { return start_forces_; }
  /// The divergence check (its scales are set at the first step).
  const DivergenceMonitor& divergence() const { return divergence_; }
  /// 1 / mass by vertex slot; 0 for pinned (prescribed) vertices and free slots.
  const std::vector<Real>& inverse_masses() const { return inverse_mass_; }
  /// Why the implicit Newton line search cannot be on the incremental
  /// potential ("" when it can): an interaction without an energy, or
  /// external forces besides gravity. (Damping is found while stepping.)
  std::string implicit_potential_missing() const;
  /// Bytes of the loop's per-vertex arrays (capacities), the integrator's
  /// included: forces, start forces, inverse masses, the integrator's stage
  /// state, and what loads, handles and implicit integrators add. Neither
  /// the map's columns (positions, velocities, masses) nor the implicit
  /// solver's own.
  std::size_t per_vertex_bytes() const;
  /// Where its memory goes: the map's links and columns, the per-vertex
  /// arrays, each interaction's and criterion's arrays (MemoryReport).
  void report_memory(MemoryReport& report) const;
  /// The implicit integrator, when settings().integrator is implicit_euler.
  const ImplicitEuler* implicit() const { return implicit_.get(); }
  ImplicitEuler* implicit() { return implicit_.get(); }

  Real kinetic_energy() const;
  /// Gravity plus every interaction's elastic energy.
  Real potential_energy() const;
  Vec3 momentum() const;
  Real total_mass() const;

 private:
  /// The forces at the start of the step (x, v) into forces_, stored in the
  /// interactions' orbits for criteria and outputs: interactions, then
  /// external forces (also kept apart in external_forces_).
  void start_forces(const std::vector<Vec3>& x, const std::vector<Vec3>& v);
  /// Adds the interactions' and external forces at a stage (x, v) into f,
  /// storing none (the integrator's stages after the first).
  void add_stage_forces(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                        std::vector<Vec3>& f);
  /// True when the step accounts the work of external forces and handles
  /// (then it keeps the positions before the step).
  bool tracks_external_work() const { return !external_.empty() || handles_ != nullptr; }
  void refresh_inverse_masses();
  /// The inverse masses of the vertices on_topology_changed walked (its
  /// vertex_runs_) and of the free slots.
  void refresh_touched_inverse_masses();
  void refresh_inverse_mass(Slot s);
  void implicit_step();  // simulation_implicit.cpp
  std::size_t apply_criteria();
  /// Before the integrator, what account_external_work needs: every
  /// position with loads, the held vertices' with handles only.
  void keep_positions_before(const std::vector<Vec3>& x);
  void account_external_work(const std::vector<Vec3>& x);

  GMap map_;
  SimulationSettings settings_;
  Integrator integrator_;
  std::unique_ptr<ImplicitEuler> implicit_;  // integrator = implicit_euler or bdf2
  Bdf2 bdf2_;                                // integrator = bdf2: the step before
  std::vector<char> is_free_;                // implicit: inverse mass > 0
  std::vector<Vec3> target_v_;               // implicit: end-of-step velocity of the others
  std::vector<std::unique_ptr<ForceModel>> models_;
  Embedding<Vec3> position_, velocity_;
  Embedding<Real> vertex_mass_, corner_mass_;
  ElementMasses element_masses_;  // without corner masses: from set_total_mass to initialise
  Embedding<Bool> pinned_;
  Embedding<Vec3> vertex_force_;  // optional: only when a pack reads state::kVertexForce
  // The loop's per-vertex forces (docs/architecture.md, "The step's arrays"):
  // forces_ is filled at the start of a step, then swapped into
  // start_forces_ (kept for readers until the next step), after which it
  // is the integrator's stage buffer (zero on return: forces_zero_).
  std::vector<Vec3> forces_, start_forces_;
  bool forces_zero_ = false;
  std::vector<Real> inverse_mass_;  // 0 for pinned and held vertices and free slots
  std::unique_ptr<Handles> handles_;
  std::vector<std::unique_ptr<ExternalForce>> external_;
  std::unique_ptr<Contact> contact_;
  std::vector<Vec3> external_forces_, x_before_, reactions_;
  std::vector<Vec3> held_x_before_;  // handles without loads: by Handles::held_slots()
  Real external_work_ = 0;
  std::vector<Dart> region_;
  // on_topology_changed: each touched vertex's darts, [first, end) in region_.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> vertex_runs_;
  std::vector<std::unique_ptr<Criterion>> criteria_;
  // The map's topology version when on_topology_changed (or initialise) last
  // brought everything derived from the links up to date: the rewrites the
  // next call reports started there (Criterion::topology_changed).
  std::uint64_t synced_version_ = 0;
  std::vector<TearCandidate> candidates_;
  std::vector<Dart> touched_;
  std::size_t tears_ = 0, tears_last_step_ = 0;
  Real time_ = 0;
  std::size_t steps_ = 0;
  bool initialised_ = false;
  DivergenceMonitor divergence_;
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
