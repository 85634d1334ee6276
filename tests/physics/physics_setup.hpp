// Simulations of the GENERATED standard packs (rules/*.rules compiled by
// riftc), set up as a scene would set them up: the packs' embeddings declared
// and initialised, masses from the runtime's mass model, pins, then the
// interactions made by the packs' factories from scene parameters.
#pragma once

#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "criteria2d.hpp"
#include "fem2d.hpp"
#include "fem3d.hpp"
#include "mass_spring2d.hpp"
#include "mass_spring3d.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/pack/pack.hpp"
#include "rift/scene/scene_setup.hpp"
#include "rift/sim/simulation.hpp"

namespace rift::physics_test {

/// The physics packs (and the 2D tearing pack), registered as `rift` does.
inline const PackRegistry& packs() {
  static const PackRegistry registry = [] {
    PackRegistry r;
    rift_register_pack_mass_spring2d(r);
    rift_register_pack_fem2d(r);
    rift_register_pack_mass_spring3d(r);
    rift_register_pack_fem3d(r);
    rift_register_pack_criteria2d(r);
    return r;
  }();
  return registry;
}

/// An interaction or criterion as a scene names it: {"stretch", {{"stiffness", 60.0}}}.
struct Use {
  std::string name;
  std::vector<std::pair<std::string, Real>> params;

  ComponentUse component() const {
    ComponentUse u;
    u.name = name;
    for (const auto& [key, value] : params)
      u.params[key] = SceneParam{Value(value), 0};
    return u;
  }
};

struct SimSetup {
  SimulationSettings settings;
  std::vector<Use> interactions;
  std::vector<Use> criteria;
  /// Masses (default: total 1 kg by area/volume) and pins, before initialise().
  std::function<void(Simulation&)> prepare;
  /// Where the components are looked up (null: the standard packs, packs()).
  const PackRegistry* registry = nullptr;
  /// Interactions store only the forces the criteria read, as a scene's
  /// set-up makes them (rift/scene/scene_setup.hpp); false: all store.
  bool lean_forces = false;
};

/// Declares and initialises the packs the setup uses, then builds the simulation.
inline std::unique_ptr<Simulation> simulate(GMap map, const SimSetup& setup) {
  const int n = map.dimension();
  const PackRegistry& registry = setup.registry ? *setup.registry : packs();
  std::vector<const Pack*> used;
  auto use = [&](const Pack* p) {
    if (!p) throw std::invalid_argument("no pack offers a component of this setup");
    for (const Pack* q : used) {
      if (q == p) return;
    }
    used.push_back(p);
  };
  for (const Use& u : setup.interactions)
    use(registry.pack_of_interaction(u.name, n));
  for (const Use& u : setup.criteria)
    use(registry.pack_of_criterion(u.name, n));
  for (const Pack* p : used) {
    declare_embeddings(map, p->embeddings());
    p->initialise(map);
  }
  std::vector<std::string> interaction_names, criterion_names, read;
  for (const Use& u : setup.interactions)
    interaction_names.push_back(u.name);
  for (const Use& u : setup.criteria)
    criterion_names.push_back(u.name);
  const Catalog catalog = registry.catalog(n);
  if (setup.lean_forces) {
    read = stored_forces_read(catalog, criterion_names, {});
    withhold_unstored_forces(map, catalog, interaction_names, read);
  }
  auto sim = std::make_unique<Simulation>(std::move(map), setup.settings);
  if (setup.prepare) {
    setup.prepare(*sim);
  } else {
    sim->set_total_mass(1.0);
  }
  for (const Use& u : setup.interactions) {
    auto model = registry.pack_of_interaction(u.name, n)->make_interaction(u.component());
    if (setup.lean_forces)
      model->set_store_forces(interaction_stores_forces(catalog, u.name, read));
    sim->add_force_model(std::move(model));
  }
  for (const Use& u : setup.criteria)
    sim->add_criterion(registry.pack_of_criterion(u.name, n)->make_criterion(u.component()));
  sim->initialise();
  return sim;
}

/// The paper's cloth interactions (docs/physics.md §5), optionally undamped.
inline std::vector<Use> paper_cloth_springs(Real damping = 0.1) {
  return {{"stretch", {{"stiffness", 60.0}, {"damping", damping}}},
          {"shear", {{"stiffness", 43.0}, {"damping", damping}}},
          {"bend", {{"stiffness", 10.0}, {"damping", damping}}}};
}

/// Internal forces of every interaction at the simulation's current state, by vertex slot.
inline std::vector<Vec3> internal_forces(Simulation& sim) {
  const auto& x = sim.position().values();
  const auto& v = sim.velocity().values();
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  for (const auto& m : sim.force_models())
    m->add_forces({x.data(), v.data()}, f.data(), false);
  return f;
}

/// Elastic energy of every interaction at the simulation's current state.
inline Real elastic_energy(const Simulation& sim) {
  const ForceInput in{sim.position().values().data(), sim.velocity().values().data()};
  Real e = 0;
  for (const auto& m : sim.force_models())
    e += m->potential_energy(in);
  return e;
}

/// Applies p -> f(p) to every vertex (rest values are computed before: this deforms).
template <class F>
void move_vertices(Simulation& sim, F&& f) {
  const OrbitAttachment& att = sim.position().attachment();
  auto& x = sim.position().values();
  for (Slot s = 0; s < x.size(); ++s) {
    if (att.slot_alive(s)) x[s] = f(x[s]);
  }
}

/// A random deformation (each coordinate moved by at most `amplitude`) and
/// velocity, the same for any simulation of the same mesh (slots are
/// assigned in the same order): two simulations compared on one state.
inline void deform(Simulation& sim, unsigned seed, Real amplitude) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  auto& x = sim.position().values();
  auto& v = sim.velocity().values();
  for (std::size_t s = 0; s < x.size(); ++s) {
    x[s] += amplitude * Vec3(u(rng), u(rng), u(rng));
    v[s] = Vec3(u(rng), u(rng), u(rng));
  }
}

/// Sum over vertices of m v, and of the vertex masses.
/// Tears at candidate c as the loop does: the first criterion's rewrite, then
/// Simulation::on_topology_changed with the darts it touched (into
/// `touched`, cleared first). False when c's dart is gone or nothing applied.
inline bool tear_at(Simulation& sim, const TearCandidate& c, std::vector<Dart>& touched) {
  if (!sim.map().is_alive(c.at)) return false;
  touched.clear();
  if (!sim.criteria()[0]->apply(sim.map(), c, touched)) return false;
  sim.on_topology_changed(touched);
  return true;
}

inline Real sum_of_vertex_masses(const Simulation& sim) {
  Real m = 0;
  sim.map().for_each_cell(Orbit::cell(0, sim.map().dimension()),
                          [&](Dart d) { m += sim.vertex_mass()[d]; });
  return m;
}

}  // namespace rift::physics_test
