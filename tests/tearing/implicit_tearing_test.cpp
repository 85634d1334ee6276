// implicit_euler through criteria and rewrites: the hanging cloth of
// topology_test torn by the global edge criterion gives, at a small step,
// the same tears as RK4 (each step's Jacobian pattern follows the map); so
// does a sheet pulled apart by two handles, which the implicit solve holds
// as Dirichlet degrees of freedom moving along their prescribed paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

std::string hanging_cloth(const std::string& integrator) {
  return "[mesh]\nsource = \"grid:quad:6x6\"\nrotate = [90, 0, 0]\n"
         "[simulation]\nintegrator = \"" +
         integrator +
         "\"\ndt = 0.0001\nsteps = 4000\n"
         "[mass]\ntotal = 0.1\n[pin]\ncorners = [\"top-left\", \"top-right\"]\n"
         "[[interaction]]\nname = \"stretch\"\nstiffness = 60.0\ndamping = 0.1\n"
         "[[interaction]]\nname = \"shear\"\nstiffness = 43.0\ndamping = 0.1\n"
         "[[interaction]]\nname = \"bend\"\nstiffness = 10.0\ndamping = 0.1\n"
         "[[criterion]]\nname = \"global_edge\"\nthreshold = 0.06\n" +
         (integrator == "implicit_euler" ? "[implicit]\ncg_tolerance = 1e-10\n" : "");
}

struct Tears {
  std::vector<std::size_t> step_of_tear;  // the step of each tear, in order
  std::vector<Vec3> splits;               // rounded to 1 mm, sorted
  std::size_t vertices = 0;
};

// A sheet held along its bottom side, its top side pulled up at 0.5 m/s by
// a handle, no gravity: the tears come from the handles' motion alone.
std::string pulled_sheet(const std::string& integrator) {
  return "[mesh]\nsource = \"grid:quad:6x6\"\n"
         "[simulation]\nintegrator = \"" +
         integrator +
         "\"\ndt = 0.0001\nsteps = 4000\ngravity = [0, 0, 0]\n"
         "[mass]\ntotal = 0.1\n"
         "[[handle]]\nname = \"floor\"\nselect = \"bottom\"\n"
         "[[handle]]\nname = \"puller\"\nselect = \"top\"\nvelocity = [0, 0.5, 0]\n"
         "[[interaction]]\nname = \"stretch\"\nstiffness = 60.0\ndamping = 0.1\n"
         "[[interaction]]\nname = \"shear\"\nstiffness = 43.0\ndamping = 0.1\n"
         "[[criterion]]\nname = \"global_edge\"\nthreshold = 0.06\n" +
         (integrator == "implicit_euler" ? "[implicit]\ncg_tolerance = 1e-10\n" : "");
}

Tears run(const std::string& integrator,
          const std::function<std::string(const std::string&)>& scene = hanging_cloth,
          int steps = 4000) {
  auto sim = simulate("cloth_" + integrator, scene(integrator));
  Tears t;
  for (int s = 0; s < steps; ++s) {
    sim->step();
    for (std::size_t k = 0; k < sim->tears_last_step(); ++k)
      t.step_of_tear.push_back(sim->steps_done());
  }
  EXPECT_TRUE(sim->map().check_validity().empty());
  for (Vec3 p : split_positions(*sim))
    t.splits.push_back((p * 1e3).array().round() / 1e3);
  std::sort(t.splits.begin(), t.splits.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  t.vertices = counts(sim->map()).vertices;
  return t;
}

// Where the torn vertices end up is compared only when the scene fixes it (a
// swinging cloth's split copies move apart differently with each integrator).
enum class Places { kCompared, kCounted };

// The same tears as RK4's at a small step: as many, each within 2 % of RK4's
// step plus 2 (first order in dt), the same vertex count, the same splits.
void expect_same_tears(const Tears& rk4, const Tears& other, Places places) {
  ASSERT_GE(rk4.step_of_tear.size(), 2u) << "RK4 never tore";
  ASSERT_EQ(other.step_of_tear.size(), rk4.step_of_tear.size());
  for (std::size_t k = 0; k < rk4.step_of_tear.size(); ++k) {
    EXPECT_NEAR(static_cast<double>(other.step_of_tear[k]),
                static_cast<double>(rk4.step_of_tear[k]), 0.02 * rk4.step_of_tear[k] + 2)
        << "tear " << k;
  }
  EXPECT_EQ(other.vertices, rk4.vertices);
  if (places == Places::kCompared) {
    EXPECT_EQ(other.splits, rk4.splits);
  } else {
    EXPECT_EQ(other.splits.size(), rk4.splits.size());
  }
}

TEST(ImplicitTearing, HangingClothTearsAsWithRk4AtASmallStep) {
  expect_same_tears(run("rk4"), run("implicit_euler"), Places::kCounted);
}

TEST(ImplicitTearing, SheetPulledByHandlesTearsAsWithRk4AtASmallStep) {
  expect_same_tears(run("rk4", pulled_sheet, 3000), run("implicit_euler", pulled_sheet, 3000),
                    Places::kCompared);
}

}  // namespace
}  // namespace rift::tearing_test
