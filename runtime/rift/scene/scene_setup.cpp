#include "rift/scene/scene_setup.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <set>

#include "rift/core/input_error.hpp"
#include "rift/io/read_mesh.hpp"
#include "rift/mesh/generators.hpp"

namespace rift {

namespace {

// Vertices at the named corners of the mesh seen from the front: "top" is
// against gravity, "left"/"right" along the widest horizontal axis.
std::vector<Dart> corner_vertices(const GMap& map, const Embedding<Vec3>& position, Vec3 gravity,
                                  const std::string& corner) {
  Vec3 up = gravity.norm() > 0 ? Vec3(-gravity.normalized()) : Vec3(0, 0, 1);
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  const Orbit vertex = Orbit::cell(0, map.dimension());
  map.for_each_cell(vertex, [&](Dart d) {
    lo = lo.cwiseMin(position[d]);
    hi = hi.cwiseMax(position[d]);
  });
  // The horizontal axis: the coordinate axis least aligned with `up` among
  // those with the largest extent.
  int axis = 0;
  Real best = -1;
  for (int a = 0; a < 3; ++a) {
    const Real extent = (hi[a] - lo[a]) * (1 - std::abs(up[a]));
    if (extent > best) {
      best = extent;
      axis = a;
    }
  }
  Vec3 right = Vec3::Unit(axis);
  right = (right - right.dot(up) * up).normalized();
  const Real sr = corner.ends_with("left") ? -1 : 1;
  const Real su = corner.starts_with("top") ? 1 : -1;
  const Real scale = std::max((hi - lo).norm(), Real(1e-300));
  Real best_score = -INFINITY;
  Vec3 best_point = Vec3::Zero();
  map.for_each_cell(vertex, [&](Dart d) {
    const Real score = (sr * position[d].dot(right) + su * position[d].dot(up)) / scale;
    if (score > best_score + 1e-12) {
      best_score = score;
      best_point = position[d];
    }
  });
  std::vector<Dart> found;
  map.for_each_cell(vertex, [&](Dart d) {
    if ((position[d] - best_point).norm() <= 1e-9 * scale) found.push_back(d);
  });
  return found;
}

}  // namespace

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
  MeshData mesh = is_generator_spec(scene.mesh.source) ? make_generated_mesh(scene.mesh.source)
                                                       : read_mesh_file(scene.mesh.source);
  place_mesh(mesh, scene.mesh);
  GMap map = assemble_gmap(mesh, &rep.assembly);
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
  auto sim = std::make_unique<Simulation>(std::move(map), settings);
  GMap& m = sim->map();
  for (const Pack* p : used) {
    declare_embeddings(m, p->embeddings());
    p->initialise(m);
  }
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

  // Pins.
  std::size_t pinned = 0;
  Embedding<Bool> pin = m.embedding<Bool>(embedding_names::kPinned);
  const Embedding<Vec3>& position = sim->position();
  for (const std::string& corner : scene.pins.corners) {
    for (Dart d : corner_vertices(m, position, scene.gravity, corner)) {
      if (!pin[d]) ++pinned;
      pin[d] = true;
    }
  }
  if (!scene.pins.vertices.empty()) {
    const Embedding<std::int64_t> point = m.embedding<std::int64_t>("point_index");
    std::set<std::int64_t> wanted(scene.pins.vertices.begin(), scene.pins.vertices.end());
    std::set<std::int64_t> found;
    m.for_each_cell(Orbit::cell(0, n), [&](Dart d) {
      if (wanted.count(point[d])) {
        found.insert(point[d]);
        if (!pin[d]) ++pinned;
        pin[d] = true;
      }
    });
    for (std::int64_t w : wanted) {
      if (!found.count(w)) {
        throw InputError(scene.path, scene.pins.line,
                         "pinned vertex " + std::to_string(w) + " is not a point of the mesh (" +
                             std::to_string(mesh.points.size()) + " points, numbered from 0)");
      }
    }
  }
  for (const auto& box : scene.pins.boxes) {
    // Named rather than structured bindings: C++20 lets a lambda capture
    // those, clang 14 does not yet.
    const Vec3& lo = box.first;
    const Vec3& hi = box.second;
    std::size_t in_box = 0;
    m.for_each_cell(Orbit::cell(0, n), [&](Dart d) {
      const Vec3& p = position[d];
      if ((p.array() >= lo.array()).all() && (p.array() <= hi.array()).all()) {
        ++in_box;
        if (!pin[d]) ++pinned;
        pin[d] = true;
      }
    });
    if (in_box == 0) throw InputError(scene.path, scene.pins.line, "a pin box holds no vertex");
  }
  rep.pinned_vertices = pinned;

  for (const ComponentUse& u : scene.interactions) {
    auto model = packs.pack_of_interaction(u.name, n)->make_interaction(u);
    if (scene.integrator == IntegratorKind::kImplicitEuler && model->jacobian_vertices() <= 0) {
      throw InputError(scene.path, u.line,
                       "integrator = \"implicit_euler\" needs the Jacobians of interaction '" +
                           u.name + "', which has none: " + model->jacobian_unavailable_reason());
    }
    sim->add_force_model(std::move(model));
  }
  for (const ComponentUse& u : scene.criteria) {
    sim->add_criterion(packs.pack_of_criterion(u.name, n)->make_criterion(u));
  }
  sim->initialise();
  rep.total_mass = sim->total_mass();
  for (const auto& model : sim->force_models()) {
    if (model->active_matches() > 0) continue;
    std::string criteria;
    for (const ComponentUse& u : scene.criteria)
      criteria += (criteria.empty() ? "" : ", ") + u.name;
    rep.warnings.push_back(
        "interaction '" + model->name() + "' matches no element of the mesh '" + scene.mesh.source +
        "' (its pattern needs other elements): it exerts no force" +
        (criteria.empty()
             ? std::string()
             : ", and criteria that read its forces (of: " + criteria + ") cannot fire"));
  }
  return sim;
}

}  // namespace rift
