#include "rift/scene/inert_components.hpp"

#include <algorithm>
#include <set>

#include "rift/core/state_embeddings.hpp"

namespace rift {

namespace {

bool contains(const std::vector<std::string>& list, std::string_view name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names)
    out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

std::vector<std::string> inert_component_warnings(const Scene& scene, const PackRegistry& packs,
                                                  const Simulation& sim) {
  const Catalog catalog = packs.catalog(sim.map().dimension());
  const std::string mesh = "the mesh '" + scene.mesh.source + "'";
  std::vector<std::string> warnings;

  // What the scene's interactions store on this mesh, and which ones match nothing.
  std::set<std::string> stored;
  std::vector<std::string> unmatched;
  bool any_force = false;
  for (const auto& model : sim.force_models()) {
    if (model->active_matches() == 0) {
      unmatched.push_back(model->name());
      warnings.push_back("interaction '" + model->name() + "' matches no element of " + mesh +
                         " (its pattern needs other elements): it exerts no force");
      continue;
    }
    any_force = true;
    if (const ComponentSpec* spec = Catalog::find(catalog.interactions, model->name()))
      stored.insert(spec->stores.begin(), spec->stores.end());
  }

  for (const ComponentUse& use : scene.criteria) {
    const ComponentSpec* spec = Catalog::find(catalog.criteria, use.name);
    if (!spec) continue;
    // The interactions' stored forces the measure reads (rest values and
    // positions are always there); the criterion can fire when one is stored.
    std::vector<std::string> forces;
    for (const std::string& read : spec->reads) {
      for (const ComponentSpec& i : catalog.interactions) {
        if (contains(i.stores, read) && !contains(forces, read)) forces.push_back(read);
      }
    }
    const bool reads_vertex_force = contains(spec->reads, state::kVertexForce);
    if (reads_vertex_force && !any_force) {
      warnings.push_back("criterion '" + use.name + "' cannot fire on " + mesh + ": it reads " +
                         std::string(state::kVertexForce) +
                         ", the sum of the interactions' forces, and no interaction of the "
                         "scene acts on this mesh");
      continue;
    }
    if (forces.empty() || reads_vertex_force) continue;
    if (std::any_of(forces.begin(), forces.end(),
                    [&](const std::string& f) { return stored.count(f) > 0; })) {
      continue;
    }
    // Who would store them, and why they do not here.
    std::vector<std::string> writers;
    for (const ComponentSpec& i : catalog.interactions) {
      if (!std::any_of(forces.begin(), forces.end(),
                       [&](const std::string& f) { return contains(i.stores, f); })) {
        continue;
      }
      writers.push_back("'" + i.name + "' " +
                        (contains(unmatched, i.name) ? "matches no element of this mesh"
                                                     : "is not in the scene"));
    }
    warnings.push_back("criterion '" + use.name + "' cannot fire on " + mesh +
                       ": its measure reads only the stored " + joined(forces) +
                       ", which no interaction of the scene stores here (" + joined(writers) + ")");
  }
  return warnings;
}

}  // namespace rift
