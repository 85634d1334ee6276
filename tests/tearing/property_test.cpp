// Property tests at scale (issue 13): random tear events on random scenes of
// the standard packs, with the G-map, the mass and the momentum checked after
// every single event.
//
// A scene: a random mesh (generated grids and blocks of random kinds, sizes
// and proportions, the same with jittered vertices, and the shared real
// meshes), a random scale and mass, a random subset of the dimension's
// interactions (with one that stores the forces the criterion reads), one
// criterion of the standard packs (each in turn) with a random threshold
// (its default times 10^[-2, 2]). Scenes that set-up reports cannot tear
// (inert_components.hpp) are skipped, after checking under large random
// strains that their criterion indeed finds no candidate.
//
// Each round imposes a random state: a random strain of the rest shape plus
// noise per vertex (split copies of a vertex move apart), random velocities.
// Then either (1 in 5) the simulation's own step applies the most critical
// candidate (max_per_step = 1, a tiny dt), or the round's candidates are
// applied in random order, 1 to 8 of them, each matched again first and
// followed by the simulation's update (masses, matches), as a step does.
// When nothing passes the threshold the strain grows; a scene ends when its
// mesh is used up or its budget of events is.
//
// After every event:
//   - validity: GMap::check_validity, the full check (no allocation when the
//     map is valid);
//   - mass: the rewrites of topology2d/3d only unsew and delete whole
//     elements, so every surviving dart keeps its share of its corner's mass
//     (corner_mass / corner size); the corner masses must sum to the shares
//     of the darts that survived, and the vertex masses to the corner masses
//     (1e-12 relative);
//   - momentum: sum of vertex mass x velocity equals the sum over surviving
//     darts of share x velocity before the event (a split copy moves with its
//     vertex; a step adds dt x the sum of the internal forces, zero up to
//     rounding as every interaction's forces balance) (1e-10 relative).
// The test fails on the first violated property, naming the scene (its TOML
// is printed) and the event, and also when some criterion tore fewer than
// 1% of the events: every criterion must be exercised. Checked by mutation:
// vertex masses off by 1e-9 relative after a tear, or velocities by 1e-6,
// fail at the first event.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "rift/mesh/generators.hpp"
#include "rift/sim/mass_model.hpp"
#include "shared_test_data.hpp"
#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int uniform_int(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}
double log_uniform(Rng& rng, double lo, double hi) {
  return std::exp(uniform(rng, std::log(lo), std::log(hi)));
}

std::string num(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

// ---- random meshes ------------------------------------------------------------------

/// A generated mesh with every vertex moved by up to `jitter` cell sizes,
/// written as a legacy VTK file (VTK vertex order, as MeshData's).
std::string jittered_mesh_file(const MeshData& mesh, double jitter, double cell, Rng& rng,
                               const std::string& name) {
  const std::string path = ::testing::TempDir() + "rift_property_" + name + ".vtk";
  std::ofstream out(path);
  out.precision(17);
  out << "# vtk DataFile Version 3.0\njittered\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS "
      << mesh.points.size() << " double\n";
  for (const Vec3& p : mesh.points) {
    Vec3 q = p;
    for (int c = 0; c < mesh.dimension; ++c)
      q[c] += uniform(rng, -jitter, jitter) * cell;
    out << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
  }
  out << "CELLS " << mesh.elements.size() << ' '
      << mesh.elements.size() + mesh.element_vertices.size() << '\n';
  for (const MeshElement& e : mesh.elements) {
    out << e.count;
    for (std::uint32_t k = 0; k < e.count; ++k)
      out << ' ' << mesh.element_vertices[e.first + k];
    out << '\n';
  }
  out << "CELL_TYPES " << mesh.elements.size() << '\n';
  for (const MeshElement& e : mesh.elements) {
    const int type = e.type == ElementType::Tetra  ? 10
                     : e.type == ElementType::Hexa ? 12
                     : e.count == 3                ? 5
                     : e.count == 4                ? 9
                                                   : 7;
    out << type << '\n';
  }
  return path;
}

struct MeshChoice {
  std::string source;  // a generator spelling or a file
  int max_events = 0;  // budget: big meshes get fewer events, for variety
};

MeshChoice random_mesh(int dim, Rng& rng, const std::string& name) {
  const std::string shared = RIFT_SHARED_MESHES;
  const int pick = uniform_int(rng, 0, 9);
  if (dim == 2) {
    if (pick == 0) {
      static const char* kFiles[] = {"triangleGrid_10_10.obj", "square3.msh", "liver.obj"};
      const std::string file = kFiles[uniform_int(rng, 0, 2)];
      return {shared + "/" + file, file == "triangleGrid_10_10.obj" ? 150 : 60};
    }
    static const char* kKinds[] = {"quad", "tri", "mix"};
    const int k = uniform_int(rng, 0, 2), nx = uniform_int(rng, 1, 7), ny = uniform_int(rng, 1, 7);
    if (pick <= 3) {
      const MeshData m = make_grid(static_cast<GridKind>(k), nx, ny);
      return {jittered_mesh_file(m, 0.2, 1.0 / std::max(nx, ny), rng, name), 400};
    }
    return {std::string("grid:") + kKinds[k] + ":" + std::to_string(nx) + "x" + std::to_string(ny),
            400};
  }
  if (pick == 0) {
    static const char* kFiles[] = {"cube_low_res.msh", "msh4_cube.msh", "cube.mesh", "liver.msh"};
    const std::string file = kFiles[uniform_int(rng, 0, 3)];
    const bool big = file == "cube.mesh" || file == "liver.msh";
    return {shared + "/" + file, big ? 15 : 150};
  }
  const bool tet = uniform_int(rng, 0, 1) == 1;
  const int nx = uniform_int(rng, 1, tet ? 3 : 4), ny = uniform_int(rng, 1, tet ? 2 : 3),
            nz = uniform_int(rng, 1, 2);
  if (pick <= 3) {
    const MeshData m = make_block(tet ? BlockKind::Tet : BlockKind::Hex, nx, ny, nz);
    return {jittered_mesh_file(m, 0.12, 1.0 / std::max({nx, ny, nz}), rng, name), 300};
  }
  return {std::string("block:") + (tet ? "tet" : "hex") + ":" + std::to_string(nx) + "x" +
              std::to_string(ny) + "x" + std::to_string(nz),
          300};
}

// ---- random scenes ------------------------------------------------------------------

/// The scene's TOML: one criterion with a random threshold (its default
/// times 10^[-2, 2]), a random non-empty subset of the interactions.
std::string random_scene(int dim, const MeshChoice& mesh, const ComponentSpec& criterion,
                         Rng& rng) {
  std::string toml = "[mesh]\nsource = \"" + mesh.source + "\"\nscale = [" +
                     num(uniform(rng, 0.5, 2.0)) + ", " + num(uniform(rng, 0.5, 2.0)) + ", " +
                     num(uniform(rng, 0.5, 2.0)) + "]\n";
  toml +=
      "[simulation]\nintegrator = \"euler\"\ndt = 1e-9\nsteps = 1\ngravity = [0, 0, 0]\n"
      "divergence_factor = 0\n[mass]\ntotal = " +
      num(log_uniform(rng, 0.1, 10.0)) + "\n[tearing]\nmax_per_step = 1\n";
  const Catalog catalog = standard_packs().catalog(dim);
  std::vector<const ComponentSpec*> chosen;
  for (const ComponentSpec& i : catalog.interactions) {
    if (uniform(rng, 0, 1) < 0.6) chosen.push_back(&i);
  }
  // One of the interactions that store the forces the criterion reads, if
  // it reads any, so that it can fire (on a mesh that the interaction fits).
  std::vector<const ComponentSpec*> feeding;
  for (const ComponentSpec& i : catalog.interactions) {
    for (const std::string& f : criterion.reads) {
      if (std::find(i.stores.begin(), i.stores.end(), f) != i.stores.end()) {
        feeding.push_back(&i);
        break;
      }
    }
  }
  const auto is_chosen = [&](const ComponentSpec* i) {
    return std::find(chosen.begin(), chosen.end(), i) != chosen.end();
  };
  if (!feeding.empty() && std::none_of(feeding.begin(), feeding.end(), is_chosen))
    chosen.push_back(feeding[uniform_int(rng, 0, static_cast<int>(feeding.size()) - 1)]);
  if (chosen.empty())
    chosen.push_back(&catalog.interactions[uniform_int(
        rng, 0, static_cast<int>(catalog.interactions.size()) - 1)]);
  for (const ComponentSpec* i : chosen)
    toml += "[[interaction]]\nname = \"" + i->name + "\"\n";
  toml += "[[criterion]]\nname = \"" + criterion.name + "\"\n";
  for (const ParamSpec& p : criterion.params) {
    if (p.type == ValueType::kReal && p.default_value) {
      toml += p.name + " = " + num(std::get<Real>(*p.default_value) * log_uniform(rng, 1e-2, 1e2)) +
              "\n";
    } else if (p.type == ValueType::kBool) {
      toml += p.name + " = " + (uniform_int(rng, 0, 1) ? "true" : "false") + "\n";
    }
  }
  return toml;
}

// ---- the properties -----------------------------------------------------------------

/// What each dart carried before an event: alive, its share of its corner's
/// mass (corner_mass over the corner's darts), its vertex slot; and the
/// velocity by vertex slot. Refreshed by each check for the next event, so
/// that the checks stay flat loops and cost no more than the events.
struct DartLedger {
  std::vector<std::uint8_t> alive;
  std::vector<Real> share;
  std::vector<Slot> vertex;
  std::vector<Vec3> velocity;  // by vertex slot

  /// The velocities changed (a new random state, a step).
  void record_velocities(const Simulation& sim) { velocity = sim.velocity().values(); }
};

/// Checks the event that turned the ledger's state into the simulation's,
/// and records the new state in the ledger. Returns the first property
/// violated, or "".
std::string check_event(const Simulation& sim, DartLedger& ledger) {
  const GMap& g = sim.map();
  // The full check (every involution, orbit and embedding), allocation-free
  // when the map is valid; a valid map also has consistent slot counts,
  // which the sums below rely on.
  const std::vector<std::string> problems = g.check_validity(3);
  if (!problems.empty()) return "invalid G-map: " + problems.front();

  const Embedding<Real> corner_mass = g.embedding<Real>("corner_mass");
  const OrbitAttachment& corners = corner_mass.attachment();
  const OrbitAttachment& vertices = sim.velocity().attachment();
  Real expected_mass = 0, corner_total = 0, scale = 0;
  Vec3 expected_momentum = Vec3::Zero();
  Dart created = kNoDart;
  const std::size_t known = ledger.alive.size();
  g.for_each_dart([&](Dart d) {
    if (d >= known || !ledger.alive[d]) {
      created = d;
      return;
    }
    const Real share = ledger.share[d];
    const Vec3& v = ledger.velocity[ledger.vertex[d]];
    expected_mass += share;
    expected_momentum += share * v;
    scale += share * v.norm();
    const Slot c = corners.slot(d);
    ledger.share[d] = corner_mass.values()[c] / static_cast<Real>(corners.darts_in_slot(c));
    corner_total += ledger.share[d];
    ledger.vertex[d] = vertices.slot(d);
  });
  // The ledger assumes rewrites that unsew and delete whole elements (all of
  // topology2d/3d); a rule creating darts needs it extended.
  if (created != kNoDart) {
    return "dart " + std::to_string(created) + " was created: the mass ledger does not cover it";
  }
  for (Dart d = 0; d < known; ++d)
    ledger.alive[d] = g.is_alive(d) ? 1 : 0;

  const std::vector<Real>& mass = sim.vertex_mass().values();
  const std::vector<Vec3>& velocity = sim.velocity().values();
  const std::vector<Real>& inverse_mass = sim.inverse_masses();
  Real vertex_total = 0;
  Vec3 momentum = Vec3::Zero();
  for (Slot v = 0; v < mass.size(); ++v) {
    if (!vertices.slot_alive(v)) continue;
    vertex_total += mass[v];
    momentum += mass[v] * velocity[v];
    // The scenes pin nothing and hold nothing: every vertex moves by 1 / m,
    // its new copies and the vertices whose corners a rewrite took included.
    const Real expected_inverse = mass[v] > 0 ? 1 / mass[v] : 0;
    if (v >= inverse_mass.size() || inverse_mass[v] != expected_inverse) {
      return "vertex slot " + std::to_string(v) + " of mass " + num(mass[v]) +
             " has inverse mass " + (v < inverse_mass.size() ? num(inverse_mass[v]) : "none");
    }
  }
  ledger.record_velocities(sim);

  const Real tol = 1e-12 * std::max<Real>(expected_mass, 1e-300);
  if (std::abs(corner_total - expected_mass) > tol) {
    return "the corner masses sum to " + num(corner_total) + " but the surviving elements weigh " +
           num(expected_mass);
  }
  if (std::abs(vertex_total - corner_total) > tol) {
    return "the vertex masses sum to " + num(vertex_total) + " but the corner masses to " +
           num(corner_total);
  }
  if ((momentum - expected_momentum).norm() > 1e-10 * scale + 1e-300) {
    std::ostringstream s;
    s.precision(17);
    s << "momentum (" << momentum.transpose() << ") but the surviving darts carried ("
      << expected_momentum.transpose() << ")";
    return s.str();
  }
  return "";
}

/// The ledger of a fresh scene (every dart alive, nothing to check yet).
void start_ledger(const Simulation& sim, DartLedger& ledger) {
  const GMap& g = sim.map();
  ledger.alive.assign(g.capacity(), 0);
  ledger.share.assign(g.capacity(), 0);
  ledger.vertex.assign(g.capacity(), 0);
  g.for_each_dart([&](Dart d) { ledger.alive[d] = 1; });
  ledger.record_velocities(sim);
  check_event(sim, ledger);  // fills share and vertex
}

/// Rest positions by dart (rewrites never create darts: checked above).
std::vector<Vec3> rest_by_dart(const Simulation& sim) {
  std::vector<Vec3> rest(sim.map().capacity(), Vec3::Zero());
  sim.map().for_each_dart([&](Dart d) { rest[d] = sim.position()[d]; });
  return rest;
}

/// x = c + (I + amp S)(X - c) + noise, S a random matrix of norm ~1 and the
/// noise independent per vertex (split copies of a vertex move apart);
/// random velocities of up to 1 m/s. `rest_of_slot` is scratch.
void randomise_state(Simulation& sim, const std::vector<Vec3>& rest, const Vec3& centre, Real size,
                     Real amp, Rng& rng, std::vector<Vec3>& rest_of_slot) {
  Mat3 s;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      s(r, c) = uniform(rng, -1, 1);
  }
  const Mat3 f = Mat3::Identity() + amp * s;
  const OrbitAttachment& vertices = sim.position().attachment();
  std::vector<Vec3>& x = sim.position().values();
  std::vector<Vec3>& v = sim.velocity().values();
  rest_of_slot.resize(x.size());
  sim.map().for_each_dart([&](Dart d) { rest_of_slot[vertices.slot(d)] = rest[d]; });
  const bool flat = sim.map().dimension() == 2 && size > 0;
  for (Slot k = 0; k < x.size(); ++k) {
    if (!vertices.slot_alive(k)) continue;
    Vec3 noise(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    if (flat && rest_of_slot[k].z() == centre.z()) noise.z() = 0;  // flat sheets stay flat
    x[k] = centre + f * (rest_of_slot[k] - centre) + (0.2 * amp * size) * noise;
    v[k] = Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  }
}

struct Tally {
  long events = 0, scenes = 0, inert_scenes = 0, rounds = 0;
  double setup_seconds = 0;  // building the scenes, the rest is stepping and checking
  std::map<std::string, long> by_criterion;
};

/// Runs random scenes of dimension `dim` until `target` events, checking
/// every event; returns the tally. Stops at the first violation (test failure).
Tally run_random_events(int dim, long target, std::uint64_t seed) {
  Rng rng(seed);
  Tally tally;
  const std::vector<ComponentSpec> criteria = standard_packs().catalog(dim).criteria;
  DartLedger ledger;
  std::vector<Vec3> rest_of_slot;
  std::vector<TearCandidate> candidates;
  std::vector<Dart> touched;
  while (tally.events < target) {
    const ComponentSpec& criterion = criteria[tally.scenes % criteria.size()];
    const std::string name =
        std::to_string(dim) + "d_" + std::to_string(seed) + "_" + std::to_string(tally.scenes);
    const MeshChoice mesh = random_mesh(dim, rng, name);
    const std::string toml = random_scene(dim, mesh, criterion, rng);
    ++tally.scenes;
    std::unique_ptr<Simulation> sim;
    SetupReport report;
    const auto setup_start = std::chrono::steady_clock::now();
    try {
      sim = simulate(name, toml, false, &report);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "scene " << name << " could not be built: " << e.what() << "\n" << toml;
      return tally;
    }
    // A jittered mesh file is read once the simulation is built; it stays
    // behind only for a scene that failed, which the message above names.
    if (mesh.source.rfind(::testing::TempDir(), 0) == 0) std::remove(mesh.source.c_str());
    tally.setup_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_start).count();
    const std::vector<Vec3> rest = rest_by_dart(*sim);
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    sim->map().for_each_dart([&](Dart d) {
      lo = lo.cwiseMin(rest[d]);
      hi = hi.cwiseMax(rest[d]);
    });
    const Vec3 centre = 0.5 * (lo + hi);
    const Real size = (hi - lo).maxCoeff();
    // Set-up said the criterion cannot fire on this mesh (say shear_force on
    // tetrahedra): the claim is checked under large random strains (no
    // candidate may appear), then the next scene.
    if (std::any_of(report.warnings.begin(), report.warnings.end(), [](const std::string& w) {
          return w.find("cannot fire") != std::string::npos;
        })) {
      ++tally.inert_scenes;
      Criterion& inert = *sim->criteria().front();
      for (const Real amp : {0.3, 1.0, 2.0}) {
        randomise_state(*sim, rest, centre, size, amp, rng, rest_of_slot);
        store_forces(*sim);
        candidates.clear();
        inert.collect(sim->map(), candidates);
        if (!candidates.empty()) {
          ADD_FAILURE() << "scene " << name << ": set-up warned that criterion '" << criterion.name
                        << "' cannot fire, yet it has " << candidates.size()
                        << " candidates at a strain of " << amp << "\n"
                        << toml;
          return tally;
        }
      }
      continue;
    }
    Real amp = log_uniform(rng, 0.01, 0.3);
    long events = 0;
    Criterion& tear = *sim->criteria().front();
    start_ledger(*sim, ledger);
    // One event: checked at once; false (test failed) on a violation.
    const auto checked = [&](const char* how) {
      ++events;
      ++tally.events;
      ++tally.by_criterion[criterion.name];
      const std::string problem = check_event(*sim, ledger);
      if (problem.empty()) return true;
      ADD_FAILURE() << "scene " << name << ", event " << events << " (criterion '" << criterion.name
                    << "', " << how << "): " << problem << "\n"
                    << toml;
      return false;
    };
    while (events < mesh.max_events && tally.events < target && amp < 3.0) {
      randomise_state(*sim, rest, centre, size, amp, rng, rest_of_slot);
      ledger.record_velocities(*sim);
      ++tally.rounds;
      try {
        if (uniform(rng, 0, 1) < 0.2) {
          // The simulation's own step: forces, criteria, the most critical
          // candidate applied (max_per_step = 1), a tiny time step.
          sim->step();
          if (sim->tears_last_step() == 0) {
            amp *= 1.5;  // nothing passed the threshold: deform more
          } else if (!checked("in a step")) {
            return tally;
          }
          continue;
        }
        // Several events at once, in random order, as a step applies them
        // (forces of the round's state, each candidate matched again first).
        store_forces(*sim);
        candidates.clear();
        tear.collect(sim->map(), candidates);
        if (candidates.empty()) {
          amp *= 1.5;
          continue;
        }
        std::shuffle(candidates.begin(), candidates.end(), rng);
        const auto wanted = static_cast<std::size_t>(uniform_int(rng, 1, 8));
        std::size_t done = 0;
        for (const TearCandidate& c : candidates) {
          if (done == wanted || events >= mesh.max_events || tally.events >= target) break;
          if (!sim->map().is_alive(c.at)) continue;  // removed by an earlier event
          touched.clear();
          if (!tear.apply(sim->map(), c, touched)) continue;
          sim->on_topology_changed(touched);
          ++done;
          if (!checked("a candidate in random order")) return tally;
        }
      } catch (const std::exception& e) {
        ADD_FAILURE() << "scene " << name << ", after " << events << " events, threw: " << e.what()
                      << "\n"
                      << toml;
        return tally;
      }
    }
  }
  return tally;
}

void run_and_report(int dim, long target, std::uint64_t seed) {
  const auto start = std::chrono::steady_clock::now();
  Tally tally = run_random_events(dim, target, seed);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << dim << "D, seed " << seed << ": " << tally.events << " tear events in "
            << tally.scenes << " scenes (" << tally.inert_scenes << " that cannot tear skipped, "
            << tally.rounds << " random states), " << seconds << " s of which "
            << tally.setup_seconds << " s building scenes\n";
  if (::testing::Test::HasFailure()) return;
  EXPECT_GE(tally.events, target);
  // Every criterion of the dimension tore, and not just once.
  for (const ComponentSpec& c : standard_packs().catalog(dim).criteria) {
    std::cout << "  " << c.name << ": " << tally.by_criterion[c.name] << "\n";
    EXPECT_GE(tally.by_criterion[c.name], target / 100) << "criterion '" << c.name << "'";
  }
}

// 2 x 50,000 events per dimension, in four tests so that ctest can run them
// side by side. RIFT_PROPERTY_EVENTS=N runs N per test instead (a quick local
// run, or a long one).
long events_per_test() {
  const char* n = std::getenv("RIFT_PROPERTY_EVENTS");
  return n ? std::atol(n) : 50'000;
}

TEST(TearProperties, RandomEvents2DFirstHalf) {
  RIFT_EXPECT_SHARED_MESHES(std::ifstream(std::string(RIFT_SHARED_MESHES) + "/square3.msh"));
  run_and_report(2, events_per_test(), 1);
}
TEST(TearProperties, RandomEvents2DSecondHalf) {
  RIFT_EXPECT_SHARED_MESHES(std::ifstream(std::string(RIFT_SHARED_MESHES) + "/square3.msh"));
  run_and_report(2, events_per_test(), 2);
}
TEST(TearProperties, RandomEvents3DFirstHalf) {
  RIFT_EXPECT_SHARED_MESHES(std::ifstream(std::string(RIFT_SHARED_MESHES) + "/liver.msh"));
  run_and_report(3, events_per_test(), 3);
}
TEST(TearProperties, RandomEvents3DSecondHalf) {
  RIFT_EXPECT_SHARED_MESHES(std::ifstream(std::string(RIFT_SHARED_MESHES) + "/liver.msh"));
  run_and_report(3, events_per_test(), 4);
}

}  // namespace
}  // namespace rift::tearing_test
