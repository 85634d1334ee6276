#include "rift/scene/scene_setup.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "rift/core/input_error.hpp"
#include "rift/core/state_embeddings.hpp"
#include "rift/io/read_mesh.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/scene/inert_components.hpp"
#include "rift/scene/notch.hpp"

namespace rift {

namespace {

Vec3 up_of(const Scene& scene) {
  return scene.gravity.norm() > 0 ? Vec3(-scene.gravity.normalized()) : Vec3::Zero();
}

std::string where_is(const Vec3& p) {
  // Round-off of a rotated mesh (2e-16 for 0) would only confuse.
  const Vec3 q =
      p.unaryExpr([&](Real v) { return std::abs(v) < 1e-12 * (1 + p.norm()) ? 0.0 : v; });
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", q.x(), q.y(), q.z());
  return text;
}

// The selected vertices, or an InputError naming the scene line when the
// selection holds none.
std::vector<Dart> selected(const Scene& scene, const GMap& map, VertexSelector& selector,
                           const Selection& sel, const std::string& what) {
  std::vector<Dart> found;
  try {
    found = selector.select(sel);
  } catch (const std::invalid_argument& e) {
    throw InputError(scene.path, sel.line, what + ": " + e.what());
  }
  if (found.empty()) {
    std::string hint;
    if (sel.kind == Selection::Kind::kGroup) {
      hint = map.has_embedding("element_tag")
                 ? " (no element of the mesh has that tag)"
                 : " (the mesh has no physical groups: Gmsh physical tags, Medit references "
                   "or VTU cell data)";
    }
    throw InputError(scene.path, sel.line,
                     what + ": the selection (" + sel.describe() + ") holds no vertex" + hint);
  }
  return found;
}

const Pack* pack_with_rule(const PackRegistry& packs, const std::string& rule, int dimension) {
  for (const auto& p : packs.packs()) {
    if (p->dimension() != dimension) continue;
    const auto names = p->rule_names();
    if (std::find(names.begin(), names.end(), rule) != names.end()) return p.get();
  }
  return nullptr;
}

void add_handles(const Scene& scene, Simulation& sim, VertexSelector& selector, SetupReport& rep) {
  if (scene.handles.empty() && scene.pins.corners.empty() && scene.pins.vertices.empty() &&
      scene.pins.boxes.empty()) {
    return;
  }
  GMap& m = sim.map();
  const Embedding<Vec3>& position = sim.position();
  auto handles = std::make_unique<Handles>(m);
  std::vector<std::string> owner;  // per handle, how messages name it

  // [pin]: one fixed handle for every pinned vertex.
  if (!scene.pins.corners.empty() || !scene.pins.vertices.empty() || !scene.pins.boxes.empty()) {
    HandleMotion fixed;
    fixed.name = "pin";
    const int h = handles->add(fixed);
    owner.push_back("[pin]");
    std::vector<Selection> pins;
    for (const std::string& c : scene.pins.corners) {
      Selection s;
      s.kind = Selection::Kind::kCorner;
      s.name = c;
      s.line = scene.pins.line;
      pins.push_back(s);
    }
    if (!scene.pins.vertices.empty()) {
      Selection s;
      s.kind = Selection::Kind::kVertices;
      s.vertices = scene.pins.vertices;
      s.line = scene.pins.line;
      pins.push_back(s);
    }
    for (const auto& [lo, hi] : scene.pins.boxes) {
      Selection s;
      s.kind = Selection::Kind::kBox;
      s.lo = lo;
      s.hi = hi;
      s.line = scene.pins.line;
      pins.push_back(s);
    }
    for (const Selection& s : pins) {
      for (Dart d : selected(scene, m, selector, s, "[pin]")) {
        if (handles->handle_of(d) < 0) ++rep.pinned_vertices;
        handles->hold(d, h, position[d]);
      }
    }
  }
  for (const SceneHandle& sh : scene.handles) {
    const std::string what = "[[handle]] '" + sh.motion.name + "'";
    const std::vector<Dart> vertices = selected(scene, m, selector, sh.select, what);
    HandleMotion motion = sh.motion;
    if (!sh.pivot_given) {
      motion.pivot = Vec3::Zero();
      for (Dart d : vertices)
        motion.pivot += position[d];
      motion.pivot /= static_cast<Real>(vertices.size());
    }
    const int h = handles->add(motion);
    owner.push_back(what);
    for (Dart d : vertices) {
      const int other = handles->handle_of(d);
      if (other >= 0 && other != h) {
        throw InputError(scene.path, sh.line,
                         "the vertex at " + where_is(position[d]) + " is held by both " +
                             owner[static_cast<std::size_t>(other)] + " and " + what +
                             ": a vertex can follow one prescribed motion only");
      }
      handles->hold(d, h, position[d]);
      ++rep.held_vertices;
    }
  }
  sim.set_handles(std::move(handles));
}

void add_loads(const Scene& scene, Simulation& sim, VertexSelector& selector) {
  GMap& m = sim.map();
  std::shared_ptr<VertexGroups> groups;
  for (const SceneLoad& l : scene.loads) {
    LoadSpec spec = l.spec;
    if (l.select.kind != Selection::Kind::kAll) {
      if (!groups) groups = std::make_shared<VertexGroups>(m);
      const std::vector<Dart> vertices =
          selected(scene, m, selector, l.select, "[[load]] '" + l.spec.name + "'");
      try {
        spec.group = groups->add_group();
      } catch (const std::invalid_argument& e) {
        throw InputError(scene.path, l.line, e.what());
      }
      for (Dart d : vertices)
        groups->add(d, spec.group);
    }
    sim.add_external_force(std::make_unique<GroupLoad>(spec, groups));
  }
  if (scene.drag.coefficient > 0) {
    if (m.dimension() != 2) {
      throw InputError(scene.path, scene.drag.line,
                       "[drag] acts on the faces of 2D surfaces, and this mesh is 3D");
    }
    sim.add_external_force(std::make_unique<SurfaceDrag>(scene.drag.coefficient, scene.drag.wind));
  }
  Embedding<Vec3>& velocity = sim.velocity();
  for (const SceneInitialVelocity& iv : scene.initial_velocities) {
    for (Dart d : selected(scene, m, selector, iv.select, "[[initial_velocity]]"))
      velocity[d] = iv.velocity;
  }
  if (!scene.obstacles.empty()) {
    std::vector<Obstacle> obstacles;
    obstacles.reserve(scene.obstacles.size());
    for (const SceneObstacle& o : scene.obstacles)
      obstacles.push_back(o.obstacle);
    sim.set_contact(std::make_unique<Contact>(std::move(obstacles)));
  }
}

void cut_notches(const Scene& scene, const PackRegistry& packs, std::vector<const Pack*>& used,
                 Simulation& sim, SetupReport& rep) {
  if (scene.notches.empty()) return;
  GMap& m = sim.map();
  const int n = m.dimension();
  const std::string rule_name = n == 2 ? "separate_faces" : "separate_volumes";
  const Pack* pack = pack_with_rule(packs, rule_name, n);
  if (!pack) {
    throw InputError(scene.path, scene.notches.front().line,
                     "a notch needs the rule '" + rule_name + "' of the standard " +
                         (n == 2 ? "topology2d" : "topology3d") +
                         " pack, and this simulator has no such pack");
  }
  if (std::find(used.begin(), used.end(), pack) == used.end()) {
    declare_embeddings(m, pack->embeddings());
    pack->initialise(m);
    used.push_back(pack);
  }
  std::unique_ptr<Rule> separate = pack->make_rule(rule_name);
  std::vector<Dart> touched;
  for (const SceneNotch& notch : scene.notches) {
    if (n == 3 && notch.depth.cross(notch.to - notch.from).norm() == 0) {
      throw InputError(scene.path, notch.line,
                       "a notch in a 3D mesh needs 'depth', a vector not parallel to to - from: "
                       "the cut is the parallelogram from, to, to + depth, from + depth");
    }
    const std::size_t cut = cut_notch(m, notch, *separate, touched);
    if (cut == 0) {
      throw InputError(scene.path, notch.line,
                       "the notch crosses no inner " + std::string(n == 2 ? "edge" : "face") +
                           " of the mesh: check 'from' and 'to' against the mesh's extent");
    }
    rep.notch_cuts += cut;
  }
  if (!m.is_valid()) {
    throw InputError(scene.path, scene.notches.front().line,
                     "internal error: the G-map is invalid after cutting the notch");
  }
}

}  // namespace

std::vector<std::string> stored_forces_read(const Catalog& catalog,
                                            const std::vector<std::string>& criteria,
                                            const std::vector<std::string>& output_arrays) {
  std::vector<std::string> read = output_arrays;
  for (const std::string& name : criteria) {
    if (const ComponentSpec* spec = Catalog::find(catalog.criteria, name))
      read.insert(read.end(), spec->reads.begin(), spec->reads.end());
  }
  return read;
}

bool interaction_stores_forces(const Catalog& catalog, const std::string& name,
                               const std::vector<std::string>& read) {
  const ComponentSpec* spec = Catalog::find(catalog.interactions, name);
  // Unknown to the catalog: store, as a simulation built by hand does.
  if (!spec) return true;
  return std::any_of(spec->stores.begin(), spec->stores.end(), [&](const std::string& s) {
    return std::find(read.begin(), read.end(), s) != read.end();
  });
}

void withhold_unstored_forces(GMap& map, const Catalog& catalog,
                              const std::vector<std::string>& interactions,
                              const std::vector<std::string>& read) {
  std::vector<std::string> written;
  for (const std::string& name : interactions) {
    const ComponentSpec* spec = Catalog::find(catalog.interactions, name);
    if (!spec || !interaction_stores_forces(catalog, name, read)) continue;
    written.insert(written.end(), spec->stores.begin(), spec->stores.end());
  }
  // Written by none, a column reads as its default, zero, and holds nothing.
  for (const ComponentSpec& spec : catalog.interactions) {
    for (const std::string& column : spec.stores) {
      if (std::find(written.begin(), written.end(), column) == written.end())
        map.withhold_storage(column);
    }
  }
}

void place_mesh(MeshData& mesh, const SceneMesh& placement) {
  const Real deg = std::numbers::pi / 180;
  const Mat3 rotation = (Eigen::AngleAxis<Real>(placement.rotate_degrees.z() * deg, Vec3::UnitZ()) *
                         Eigen::AngleAxis<Real>(placement.rotate_degrees.y() * deg, Vec3::UnitY()) *
                         Eigen::AngleAxis<Real>(placement.rotate_degrees.x() * deg, Vec3::UnitX()))
                            .toRotationMatrix();
  for (Vec3& p : mesh.points) {
    p = rotation * placement.scale.cwiseProduct(p) + placement.translate;
  }
}

std::unique_ptr<Simulation> build_simulation(const Scene& scene, const PackRegistry& packs,
                                             const SetupOptions& options, SetupReport* report) {
  SetupReport local;
  SetupReport& rep = report ? *report : local;
  rep.phases = SetupPhases{};
  // The mesh's points and elements are given back once assembled (tens of
  // MB at 10^6 vertices, which would otherwise stay through the set-up).
  GMap map = [&] {
    MeshData mesh = is_generator_spec(scene.mesh.source) ? make_generated_mesh(scene.mesh.source)
                                                         : read_mesh_file(scene.mesh.source);
    place_mesh(mesh, scene.mesh);
    rep.phases.end("mesh");
    GMap assembled = assemble_gmap(mesh, &rep.assembly);
    rep.phases.end("assembly");
    return assembled;
  }();
  const int n = map.dimension();

  // Every component must exist for this dimension; collect the packs used.
  std::vector<const Pack*> used;
  auto use = [&](const Pack* p) {
    if (std::find(used.begin(), used.end(), p) == used.end()) used.push_back(p);
  };
  for (const ComponentUse& u : scene.interactions) {
    const Pack* p = packs.pack_of_interaction(u.name, n);
    if (!p) {
      throw InputError(scene.path, u.line,
                       "interaction '" + u.name + "' is not available for " + std::to_string(n) +
                           "D meshes, and the mesh '" + scene.mesh.source + "' is " +
                           std::to_string(n) + "D");
    }
    use(p);
  }
  for (const ComponentUse& u : scene.criteria) {
    const Pack* p = packs.pack_of_criterion(u.name, n);
    if (!p) {
      throw InputError(scene.path, u.line,
                       "criterion '" + u.name + "' is not available for " + std::to_string(n) +
                           "D meshes, and the mesh '" + scene.mesh.source + "' is " +
                           std::to_string(n) + "D");
    }
    use(p);
  }

  SimulationSettings settings;
  settings.integrator = scene.integrator;
  settings.dt = scene.dt;
  settings.implicit = scene.implicit;
  settings.gravity = scene.gravity;
  settings.divergence_factor = scene.divergence_factor;
  settings.max_tears_per_step = scene.tearing.max_per_step;
  settings.check_each_rewrite = options.check_each_rewrite;
  settings.rewrites = !scene.criteria.empty() || options.rewrites_by_hand;
  // A pack lists corner_mass among its embeddings when one of its components
  // reads it (the FEM packs, criteria); notches are cut by rules before the
  // masses are summed: the corner masses are kept for them.
  settings.keep_corner_masses =
      settings.rewrites || !scene.notches.empty() ||
      std::any_of(used.begin(), used.end(), [](const Pack* p) {
        return std::any_of(p->embeddings().begin(), p->embeddings().end(),
                           [](const EmbeddingDecl& e) { return e.name == state::kCornerMass; });
      });
  auto sim = std::make_unique<Simulation>(std::move(map), settings);
  GMap& m = sim->map();
  for (const Pack* p : used) {
    declare_embeddings(m, p->embeddings());
    p->initialise(m);
  }
  rep.phases.end("pack inits");
  const Catalog catalog = packs.catalog(n);
  std::vector<std::string> interaction_names, criterion_names;
  for (const ComponentUse& u : scene.interactions)
    interaction_names.push_back(u.name);
  for (const ComponentUse& u : scene.criteria)
    criterion_names.push_back(u.name);
  const std::vector<std::string> read =
      stored_forces_read(catalog, criterion_names, options.output_arrays);
  withhold_unstored_forces(m, catalog, interaction_names, read);
  try {
    if (scene.density) {
      rep.total_mass = 0;
      sim->set_density(*scene.density);
    } else {
      sim->set_total_mass(scene.total_mass.value_or(1.0));
    }
  } catch (const std::invalid_argument& e) {
    throw InputError(scene.path, 0, std::string("cannot set the masses: ") + e.what());
  }

  rep.phases.end("masses");
  // Notches first: handles and loads select among the cut mesh's vertices.
  cut_notches(scene, packs, used, *sim, rep);
  // After the notches: the selections' vertices do not change from here on.
  VertexSelector selector(sim->map(), up_of(scene));
  add_handles(scene, *sim, selector, rep);
  add_loads(scene, *sim, selector);

  for (const ComponentUse& u : scene.interactions) {
    auto model = packs.pack_of_interaction(u.name, n)->make_interaction(u);
    if (is_implicit(scene.integrator) && model->jacobian_vertices() <= 0) {
      throw InputError(scene.path, u.line,
                       "integrator = \"" + std::string(to_string(scene.integrator)) +
                           "\" needs the Jacobians of interaction '" + u.name +
                           "', which has none: " + model->jacobian_unavailable_reason());
    }
    model->set_store_forces(interaction_stores_forces(catalog, u.name, read));
    sim->add_force_model(std::move(model));
  }
  for (const ComponentUse& u : scene.criteria) {
    sim->add_criterion(packs.pack_of_criterion(u.name, n)->make_criterion(u));
  }
  rep.phases.end("notches, handles, loads");
  sim->initialise(&rep.phases);
  rep.total_mass = sim->total_mass();
  rep.warnings = inert_component_warnings(scene, packs, *sim);
  if (is_implicit(scene.integrator) && scene.implicit.newton_iterations > 1 &&
      scene.implicit.line_search == LineSearch::kEnergy) {
    const std::string why = sim->implicit_potential_missing();
    if (!why.empty()) {
      rep.warnings.push_back(
          "[implicit]: the Newton line search is on the residual |g|, not on "
          "the incremental potential: " +
          why);
    }
  }
  rep.phases.end("checks");
  return sim;
}

}  // namespace rift
