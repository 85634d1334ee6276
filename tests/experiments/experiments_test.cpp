// Small versions of the experiments of examples/experiments/ (docs/
// experiments.md): each checks what the experiment is about, where the
// tear starts and which way it runs, not a number copied from a run.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "experiment_support.hpp"

namespace rift::experiment_test {
namespace {

// A 10 cm membrane sheet, n x n triangles' grid, bottom clamped, top pulled
// up at `speed`; a notch from the left edge to x = notch_end at mid-height;
// a stress criterion (vertex_stress, N/m) or a force one.
std::string notched_sheet(int n, double notch_end, double speed, const std::string& criterion) {
  const double h = 0.1 / n;
  const double dt = 0.3 * h / 31.6;  // 31.6 m/s: the membrane's wave speed
  return "[mesh]\nsource = \"grid:tri:" + std::to_string(n) + "x" + std::to_string(n) +
         "\"\nscale = 0.1\n"
         "[simulation]\nintegrator = \"rk4\"\ndt = " +
         std::to_string(dt) +
         "\ngravity = [0, 0, 0]\n"
         "[mass]\ntotal = 0.01\n"
         "[[notch]]\nfrom = [-0.001, 0.05, 0]\nto = [" +
         std::to_string(notch_end) +
         ", 0.05, 0]\n"
         "[[handle]]\nname = \"clamp\"\nselect = \"bottom\"\n"
         "[[handle]]\nname = \"grip\"\nselect = \"top\"\nvelocity = [0, " +
         std::to_string(speed) +
         ", 0]\n"
         "[[interaction]]\nname = \"membrane\"\nyoung = 1000.0\npoisson = 0.3\ndamping = 1e-5\n" +
         criterion;
}

const std::string kStress = "[[criterion]]\nname = \"vertex_stress\"\nthreshold = 120.0\n";

// Mode I: the crack starts at the notch tip and runs along the notch's axis
// (perpendicular to the pull).
TEST(NotchedSheet, TearStartsAtTheTipAndRunsAcrossThePull) {
  const int n = 20;
  const double h = 0.1 / n;
  const double notch_end = 0.033;  // cuts the edges whose middle is left of it
  SetupReport report;
  auto sim = simulate(scene_of("mode1", notched_sheet(n, notch_end, 0.1, kStress)), &report);
  EXPECT_EQ(report.notch_cuts, 7u);  // edges of length h from x = 0 to 0.035
  const auto rest = rest_points(*sim);
  const auto before = free_sides(*sim);
  const Vec3 tip(7 * h, 0.05, 0);
  ASSERT_LT(steps_to_first_tear(*sim, 4000), 4000) << "the sheet never tore";
  const auto first = torn_centres(*sim, before, rest);
  ASSERT_FALSE(first.empty());
  Vec3 mean = Vec3::Zero();
  for (const Vec3& c : first)
    mean += c;
  mean /= static_cast<Real>(first.size());
  EXPECT_LT((mean - tip).norm(), 1.5 * h) << "first tear at " << mean.transpose();

  // Let the crack run, then compare the torn edges' direction with the
  // notch axis (x): the principal axis of their directions.
  for (int k = 0; k < 400 && sim->tears() < 12; ++k)
    sim->step();
  const auto edges = torn_edges(*sim, before, rest);
  ASSERT_GE(edges.size(), 6u);
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  for (const auto& [a, b] : edges) {
    const Eigen::Vector2d d = (b - a).head<2>().normalized();
    m += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(m);
  const Eigen::Vector2d axis = eig.eigenvectors().col(1);
  const double angle = std::acos(std::min(1.0, std::abs(axis.x()))) * 180 / std::numbers::pi;
  EXPECT_LT(angle, 20.0) << edges.size() << " torn edges";
  // The crack grew away from the notch: torn edges right of the tip.
  int ahead = 0;
  for (const auto& [a, b] : edges)
    ahead += 0.5 * (a.x() + b.x()) > tip.x() ? 1 : 0;
  EXPECT_GE(ahead, 3);
}

// Resolution independence: the notched sheet at 20 x 20 and 40 x 40 starts
// tearing at the same pull with Griffith's criterion at the mesh scale
// (vertex_energy: the strain energy of a vertex's share of its triangles per
// unit of its size, which tends to K^2 / E at a crack tip whatever the element
// size). A stress criterion would not: the tip elements' stress grows like
// 1 / sqrt(h), so vertex_stress starts the crack at 0.70 of the pull on the
// finer mesh (docs/experiments.md, with the force criteria's 1.3 the other way;
// 40 x 40 against 80 x 80 is measured there too, 0.99; the 80 x 80 sheet is
// kept out of the suite for its run time).
TEST(ResolutionIndependence, GriffithCriterionStartsTheCrackAtTheSamePull) {
  auto pull_at_first_tear = [](int n) {
    const std::string criterion = "[[criterion]]\nname = \"vertex_energy\"\ntoughness = 0.02\n";
    auto sim = simulate(scene_of("resolution", notched_sheet(n, 0.033, 0.1, criterion)));
    const auto rest = rest_points(*sim);
    const auto before = free_sides(*sim);
    EXPECT_LT(steps_to_first_tear(*sim, 20000), 20000);
    // At the notch's tip (x = 0.035 at 20 x 20, 0.0325 at 40 x 40).
    for (const Vec3& c : torn_centres(*sim, before, rest))
      EXPECT_LT((c - Vec3(0.034, 0.05, 0)).norm(), 2.5 * 0.1 / n)
          << "first tear at " << c.transpose();
    return 0.1 * sim->time();
  };
  const double coarse = pull_at_first_tear(20), fine = pull_at_first_tear(40);
  EXPECT_NEAR(fine / coarse, 1.0, 0.15) << "20 x 20: " << coarse << ", 40 x 40: " << fine;
}

// A longer notch tears at a smaller pull, as fracture mechanics says
// (K = sigma sqrt(pi a) F(a / W)) -- when the specimen is tall enough for the
// notch to be short beside the grips' distance. In the square sheet above
// (grips 5 cm from the notch) a notch as long as that distance no longer
// matters: with fixed grips, a crack longer than the half-height H releases
// G = E' eps^2 H whatever its length (the "pure shear" specimen of Rivlin and
// Thomas), and the first tear came at 6.6 mm of pull for both 1.8 and 5.3 cm
// notches. Hence a strip 3 times as tall as wide (single-edge-notched
// tension), notches of 1/5 and 1/2 of the width.
TEST(NotchedSheet, LongerNotchTearsAtSmallerPull) {
  const int n = 20;
  const double h = 0.1 / n, speed = 0.2;
  auto pull_at_first_tear = [&](double notch_end, double tip_x) {
    const std::string toml =
        "[mesh]\nsource = \"grid:tri:20x60\"\nscale = [0.1, 0.3, 1]\n"
        "[simulation]\nintegrator = \"rk4\"\ndt = 4.7e-5\ngravity = [0, 0, 0]\n"
        "[mass]\ntotal = 0.03\n"
        "[[notch]]\nfrom = [-0.001, 0.15, 0]\nto = [" +
        std::to_string(notch_end) +
        ", 0.15, 0]\n"
        "[[handle]]\nselect = \"bottom\"\n"
        "[[handle]]\nselect = \"top\"\nvelocity = [0, " +
        std::to_string(speed) +
        ", 0]\n"
        "[[interaction]]\nname = \"membrane\"\nyoung = 1000.0\npoisson = 0.3\n"
        "damping = 1e-5\n"
        "[[criterion]]\nname = \"vertex_stress\"\nthreshold = 60.0\n";
    auto sim = simulate(scene_of("notch_length", toml));
    const auto rest = rest_points(*sim);
    const auto before = free_sides(*sim);
    EXPECT_LT(steps_to_first_tear(*sim, 3000), 3000);
    // At the notch's tip, not at the grips.
    for (const Vec3& c : torn_centres(*sim, before, rest))
      EXPECT_LT((c - Vec3(tip_x, 0.15, 0)).norm(), 1.5 * h) << "first tear at " << c.transpose();
    return speed * sim->time();
  };
  const double short_pull = pull_at_first_tear(0.018, 0.02);
  const double long_pull = pull_at_first_tear(0.048, 0.05);
  // Measured 9.0 and 5.7 mm (0.64); linear fracture mechanics, with pinned
  // ends, would give about 0.3: the tip of a 4-element notch is not yet in the
  // 1 / sqrt(r) field.
  EXPECT_LT(long_pull, 0.8 * short_pull) << "short " << short_pull << " long " << long_pull;
}

// Trouser tear, set up as the standard test: the legs of a cloth cut
// half-way are gripped over their ends and pulled apart perpendicular to the
// sheet, the body free. The legs carry plain tension, which goes through the
// material straddling the cut just past its end: the tear starts there and
// runs on along the cut. (Pulling the legs apart sideways in the sheet's
// plane tears at the grips or kinks the crack: docs/experiments.md.)
TEST(TrouserTear, TheTearFollowsTheCut) {
  const std::string toml = R"(
[mesh]
source = "grid:quad:16x16"
[simulation]
integrator = "rk4"
dt = 0.0002
gravity = [0, 0, 0]
[mass]
total = 0.1
[[notch]]
from = [0.5, -0.001, 0]
to = [0.5, 0.5, 0]
[[handle]]
select = { box = { min = [-1, -1, -1], max = [0.49, 0.07, 1] } }
velocity = [0, 0, -2.0]
[[handle]]
select = { box = { min = [0.51, -1, -1], max = [2, 0.07, 1] } }
velocity = [0, 0, 2.0]
[[interaction]]
name = "stretch"
stiffness = 200.0
damping = 0.05
[[interaction]]
name = "shear"
stiffness = 100.0
damping = 0.05
[[interaction]]
name = "bend"
stiffness = 5.0
damping = 0.02
[[criterion]]
name = "stretch_strain"
threshold = 0.2
)";
  auto sim = simulate(scene_of("trouser", toml));
  const auto rest = rest_points(*sim);
  const auto before = free_sides(*sim);
  ASSERT_LT(steps_to_first_tear(*sim, 3000), 3000) << "the legs never tore apart";
  for (int k = 0; k < 600; ++k)
    sim->step();
  ASSERT_TRUE(bounded(*sim, 5.0));
  const auto torn = torn_centres(*sim, before, rest);
  ASSERT_GE(torn.size(), 6u);
  const double h = 1.0 / 16;
  double highest = 0;
  for (const Vec3& c : torn) {
    EXPECT_LT(std::abs(c.x() - 0.5), 1.5 * h) << "torn away from the cut at " << c.transpose();
    EXPECT_GT(c.y(), 0.5 - 1.5 * h) << "torn below the cut's end at " << c.transpose();
    highest = std::max(highest, c.y());
  }
  // The tear ran on: at least three elements past the cut's end.
  EXPECT_GT(highest, 0.5 + 3 * h);
}

// A ball shot through a hanging cloth punches a hole and nothing blows up.
TEST(BallThroughCloth, PunchesAHoleWithoutExploding) {
  const std::string toml = R"(
[mesh]
source = "grid:quad:16x16"
rotate = [90, 0, 0]
[simulation]
integrator = "rk4"
dt = 0.0002
gravity = [0, 0, -9.81]
[mass]
total = 0.1
[[handle]]
select = "top"
[[obstacle]]
shape = "sphere"
center = [0.5, -0.2, 0.45]
radius = 0.12
velocity = [0, 15, 0]
[[interaction]]
name = "stretch"
stiffness = 200.0
damping = 0.05
[[interaction]]
name = "shear"
stiffness = 100.0
damping = 0.05
[[criterion]]
name = "stretch_strain"
threshold = 0.2
)";
  auto sim = simulate(scene_of("ball", toml));
  const auto rest = rest_points(*sim);
  const auto before = free_sides(*sim);
  const std::size_t faces = sim->map().count_cells_of_dimension(2);
  for (int k = 0; k < 400; ++k)
    sim->step();  // 0.08 s: the ball is 1 m past the cloth
  ASSERT_TRUE(bounded(*sim, 3.0)) << "the cloth blew up";
  EXPECT_GT(sim->tears(), 0u);
  EXPECT_LT(sim->map().count_cells_of_dimension(2), faces);  // elements went with the hole
  // The hole is where the ball went through.
  const auto torn = torn_centres(*sim, before, rest);
  ASSERT_FALSE(torn.empty());
  Real nearest = INFINITY;
  for (const Vec3& c : torn)
    nearest = std::min(nearest, (c - Vec3(0.5, 0, 0.45)).norm());
  EXPECT_LT(nearest, 0.2);
  // The cloth still hangs from its rail: its highest point did not fall.
  Real top = -INFINITY;
  sim->map().for_each_cell(Orbit::cell(0, 2),
                           [&](Dart d) { top = std::max(top, sim->position()[d].z()); });
  EXPECT_NEAR(top, 1.0, 1e-9);
}

// Three-point bending: two fixed rollers under a tetrahedral beam, a third
// pressing its middle: it breaks near the indenter.
TEST(ThreePointBending, BreaksNearTheIndenter) {
  const std::string toml = R"(
[mesh]
source = "block:tet:10x2x2"
scale = [0.2, 0.02, 0.02]
[simulation]
integrator = "rk4"
dt = 4e-5
gravity = [0, 0, 0]
[mass]
density = 1000.0
[[obstacle]]
shape = "capsule"
from = [0.02, -0.05, -0.005]
to = [0.02, 0.07, -0.005]
radius = 0.005
friction = 0.5
[[obstacle]]
shape = "capsule"
from = [0.18, -0.05, -0.005]
to = [0.18, 0.07, -0.005]
radius = 0.005
friction = 0.5
[[obstacle]]
shape = "capsule"
from = [0.1, -0.05, 0.025]
to = [0.1, 0.07, 0.025]
radius = 0.005
velocity = [0, 0, -0.3]
friction = 0.5
[[interaction]]
name = "corotational"
young = 1.0e7
damping = 1e-5
[[criterion]]
name = "vertex_stress"
threshold = 2.0e5
)";
  auto sim = simulate(scene_of("bending", toml));
  const auto rest = rest_points(*sim);
  const auto before = free_sides(*sim);
  ASSERT_LT(steps_to_first_tear(*sim, 2500), 2500) << "the beam never broke";
  ASSERT_TRUE(bounded(*sim, 1.0));
  const auto torn = torn_centres(*sim, before, rest);
  ASSERT_FALSE(torn.empty());
  for (const Vec3& c : torn)
    EXPECT_LT(std::abs(c.x() - 0.1), 0.04) << "broke far from the indenter at " << c.transpose();
}

// Fig. 13's liver, grasped on its lower part by a handle and pulled away
// while its top hangs fixed: it tears near the grasp.
TEST(Liver, TearsNearTheGrasp) {
  const std::string mesh = std::string(RIFT_SHARED_MESHES) + "/liver.msh";
  if (!std::filesystem::exists(mesh)) GTEST_SKIP() << mesh << " is not on this machine";
  const std::string toml = "[mesh]\nsource = \"" + mesh + R"("
scale = 0.035
[simulation]
integrator = "implicit_euler"
dt = 2e-3
gravity = [0, 0, 0]
[mass]
density = 1060.0
[pin]
box = { min = [-0.2, 0.0, 0.0805], max = [0.07, 0.21, 0.2] }
[[handle]]
name = "grasp"
select = { sphere = { center = [-0.105, 0.09, -0.06], radius = 0.03 } }
velocity = [0, 0, -0.1]
[[interaction]]
name = "corotational"
young = 1.0e4
poisson = 0.3
[[criterion]]
name = "vertex_stress"
threshold = 3500.0
)";
  auto sim = simulate(scene_of("liver", toml));
  const auto rest = rest_points(*sim);
  const auto before = free_sides(*sim);
  // Backward Euler at 10 times rk4's step (the example's integrator): the
  // first tear comes after about 175 steps (0.35 s, as with rk4 at 0.2 ms).
  ASSERT_LT(steps_to_first_tear(*sim, 300), 300) << "the liver never tore";
  ASSERT_TRUE(bounded(*sim, 2.0));
  const auto torn = torn_centres(*sim, before, rest);
  ASSERT_FALSE(torn.empty());
  Vec3 mean = Vec3::Zero();
  for (const Vec3& c : torn)
    mean += c;
  mean /= static_cast<Real>(torn.size());
  const Vec3 grasp(-0.105, 0.09, -0.06);
  const Vec3 pins(-0.05, 0.1, 0.09);
  EXPECT_LT((mean - grasp).norm(), (mean - pins).norm())
      << "torn at " << mean.transpose() << ", nearer the fixed top than the grasp";
}

}  // namespace
}  // namespace rift::experiment_test
