// Property tests of tearing at scale: random tear events in 2D and 3D, with
// every criterion of criteria2d/criteria3d at random thresholds, on generated
// meshes and on the shared real meshes, after random deformations and random
// velocities. After every step: the G-map is valid (checked after every
// rewrite as rift run --check does), the mass is unchanged unless elements
// were removed (then it only decreases), and, the scenes having no gravity and
// no pins, the linear momentum is unchanged unless elements were removed.
//
// The number of tear events per dimension is RIFT_PROPERTY_EVENTS (default
// 3,000 in the normal suite; the 10^5 runs are the CTest tests labelled
// "property-scale", built with -DRIFT_PROPERTY_SCALE=ON, see docs/performance.md).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <random>

#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

struct CriterionCase {
  const char* name;
  double threshold;          // a value that tears under the deformations below
  const char* interactions;  // the interactions that produce the forces it reads
};

const char* kSprings2d =
    "[[interaction]]\nname = \"stretch\"\nstiffness = 60.0\ndamping = 0.1\n"
    "[[interaction]]\nname = \"shear\"\nstiffness = 43.0\ndamping = 0.1\n"
    "[[interaction]]\nname = \"bend\"\nstiffness = 10.0\ndamping = 0.1\n";
const char* kMembrane = "[[interaction]]\nname = \"membrane\"\nyoung = 1000.0\npoisson = 0.3\n";
const char* kStretch3d = "[[interaction]]\nname = \"stretch\"\nstiffness = 60.0\ndamping = 0.1\n";
const char* kShear3d = "[[interaction]]\nname = \"volume_shear\"\nstiffness = 43.0\n";
const char* kFem3d = "[[interaction]]\nname = \"corotational\"\nyoung = 1.0e5\npoisson = 0.3\n";

const std::vector<CriterionCase> kCriteria2d = {
    {"stretch_strain", 0.2, kSprings2d},    {"stretch_force", 2.0, kSprings2d},
    {"spring_split", 2.0, kSprings2d},      {"shear_force", 1.0, kSprings2d},
    {"bend_force", 0.5, kSprings2d},        {"element_stress", 100.0, kMembrane},
    {"interaction_force", 2.0, kSprings2d}, {"vertex_stress", 100.0, kMembrane},
    {"vertex_sum", 2.0, kSprings2d},        {"atomic_edge", 5.0, kSprings2d},
    {"global_edge", 5.0, kSprings2d}};

const std::vector<CriterionCase> kCriteria3d = {
    {"stretch_force", 2.0, kStretch3d},  {"spring_split", 2.0, kStretch3d},
    {"shear_force", 1.0, kShear3d},      {"element_stress", 1.0e4, kFem3d},
    {"interaction_force", 20.0, kFem3d}, {"vertex_stress", 5.0e3, kFem3d},
    {"vertex_sum", 5.0, kStretch3d},     {"global_face", 20.0, kStretch3d},
    {"atomic_face", 40.0, kStretch3d}};

std::string shared(const char* file) {
  const std::string path = std::string(RIFT_SHARED_MESHES) + "/" + file;
  EXPECT_TRUE(std::filesystem::exists(path)) << "missing shared mesh " << path;
  return path;
}

std::size_t target_events() {
  if (const char* s = std::getenv("RIFT_PROPERTY_EVENTS")) return std::strtoull(s, nullptr, 10);
  return 3000;
}

struct Tally {
  std::size_t events = 0, steps = 0, cases = 0;
};

/// One random case: mesh, criterion, threshold; rounds of deformation and
/// velocities, one step each, every property checked after every step.
void run_case(const std::string& mesh, const CriterionCase& c, std::mt19937& rng, Tally& tally) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double threshold = c.threshold * std::pow(10.0, -1.5 + 2.0 * unit(rng));
  const std::string toml =
      "[mesh]\nsource = \"" + mesh +
      "\"\n[simulation]\nintegrator = \"rk4\"\ndt = 1e-7\nsteps = 1\ngravity = [0, 0, 0]\n"
      "[mass]\ntotal = 1.0\n" +
      c.interactions + "[[criterion]]\nname = \"" + c.name +
      "\"\nthreshold = " + std::to_string(threshold) + "\n";
  const std::string what = mesh + " " + c.name + " threshold " + std::to_string(threshold);
  std::unique_ptr<Simulation> sim = simulate("property_" + std::to_string(tally.cases), toml);
  ++tally.cases;
  Vec3 lo = Vec3::Constant(1e300), hi = -lo;
  for (const Vec3& x : sim->position().values())
    lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double size = (hi - lo).norm();
  const int dim = sim->map().dimension();
  std::normal_distribution<double> normal(0, 1);
  for (int round = 0; round < 12; ++round) {
    const double amplitude = size * (0.005 + 0.05 * unit(rng));
    const Vec3 drift(normal(rng), normal(rng), normal(rng));
    sim->map().for_each_cell(Orbit::cell(0, dim), [&](Dart d) {
      sim->position()[d] += amplitude * Vec3(normal(rng), normal(rng), dim == 3 ? normal(rng) : 0);
      sim->velocity()[d] = drift + 0.3 * Vec3(normal(rng), normal(rng), normal(rng));
    });
    const double mass = sim->total_mass();
    const Vec3 momentum = sim->momentum();
    const std::size_t elements = sim->map().count_cells(Orbit::all(dim - 1));
    double momentum_scale = 0;
    sim->map().for_each_cell(Orbit::cell(0, dim), [&](Dart d) {
      momentum_scale += sim->vertex_mass()[d] * sim->velocity()[d].norm();
    });
    const std::size_t tears_before = sim->tears();
    ASSERT_NO_THROW(sim->step()) << what << " round " << round;
    ++tally.steps;
    tally.events += sim->tears() - tears_before;
    ASSERT_TRUE(sim->map().is_valid()) << what;
    const std::size_t elements_after = sim->map().count_cells(Orbit::all(dim - 1));
    ASSERT_LE(elements_after, elements) << what;
    if (elements_after == elements) {
      ASSERT_NEAR(sim->total_mass(), mass, 1e-12 * mass) << what << " round " << round;
      ASSERT_LE((sim->momentum() - momentum).norm(), 1e-9 * momentum_scale)
          << what << " round " << round;
    } else {
      ASSERT_LT(sim->total_mass(), mass) << what;
    }
    if (elements_after == 0) break;
  }
}

void run_until(const std::vector<std::string>& meshes, const std::vector<CriterionCase>& criteria,
               unsigned seed, Tally& tally) {
  std::mt19937 rng(seed);
  const std::size_t target = target_events();
  // Every mesh with every criterion once, then random pairs until enough events.
  for (const std::string& mesh : meshes) {
    for (const CriterionCase& c : criteria) {
      run_case(mesh, c, rng, tally);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  std::uniform_int_distribution<std::size_t> pick_mesh(0, meshes.size() - 1);
  std::uniform_int_distribution<std::size_t> pick_criterion(0, criteria.size() - 1);
  while (tally.events < target && tally.cases < 100000) {
    run_case(meshes[pick_mesh(rng)], criteria[pick_criterion(rng)], rng, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(TearingProperties, RandomTearsIn2dKeepValidityMassAndMomentum) {
  Tally tally;
  run_until({"grid:quad:12x12", "grid:tri:12x12", "grid:mix:12x12",
             shared("triangleGrid_10_10.obj"), shared("square3.msh"), shared("liver.obj")},
            kCriteria2d, 2024, tally);
  std::cout << "2D: " << tally.events << " tear events in " << tally.steps << " steps of "
            << tally.cases << " random scenes\n";
  EXPECT_GE(tally.events, target_events());
}

TEST(TearingProperties, RandomTearsIn3dKeepValidityMassAndMomentum) {
  Tally tally;
  run_until({"block:tet:3x3x3", "block:hex:3x3x3", shared("cube_low_res.msh"),
             shared("msh4_cube.msh"), shared("cube.mesh"), shared("liver.msh")},
            kCriteria3d, 3033, tally);
  std::cout << "3D: " << tally.events << " tear events in " << tally.steps << " steps of "
            << tally.cases << " random scenes\n";
  EXPECT_GE(tally.events, target_events());
}

}  // namespace
}  // namespace rift::tearing_test
