// Scene set-up warns when a component cannot act on the mesh
// (rift/scene/inert_components.hpp): an interaction whose pattern matches no
// element exerts no force, and a criterion whose measure reads only forces
// that no interaction of the scene stores there can never fire
// (vertex_stress reads the co-rotational tetrahedron's f_fem, shear_force the
// hexahedron's volume shear springs' f_volume_shear).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "rift/scene/scene.hpp"
#include "rift/scene/scene_setup.hpp"
#include "tearing_support.hpp"

namespace rift::tearing_test {
namespace {

std::vector<std::string> setup_warnings(const std::string& name, const std::string& mesh,
                                        const std::string& components) {
  const std::string path = ::testing::TempDir() + "rift_setup_" + name + ".toml";
  std::ofstream(path) << static_scene(mesh, "1.0", 1.0, components);
  const Scene scene = read_scene(path, standard_packs().catalog());
  SetupReport report;
  build_simulation(scene, standard_packs(), {}, &report);
  return report.warnings;
}

TEST(SetupWarnings, InteractionsThatMatchNoElementAndTheCriteriaTheyStarveAreNamed) {
  // The examples: vertex_stress on hexahedra, shear_force on tetrahedra.
  const auto hex = setup_warnings("hex", "block:hex:2x2x2",
                                  "[[interaction]]\nname = \"corotational\"\n"
                                  "[[criterion]]\nname = \"vertex_stress\"\n");
  EXPECT_EQ(hex, (std::vector<std::string>{
                     "interaction 'corotational' matches no element of the mesh "
                     "'block:hex:2x2x2' (its pattern needs other elements): it exerts no force",
                     "criterion 'vertex_stress' cannot fire on the mesh 'block:hex:2x2x2': its "
                     "measure reads only the stored stress_mass, stress_weighted, which no "
                     "interaction of the scene "
                     "stores here ('corotational' matches no element of this mesh)"}));
  const auto tet = setup_warnings("tet", "block:tet:2x2x2",
                                  "[[interaction]]\nname = \"volume_shear\"\n"
                                  "[[criterion]]\nname = \"shear_force\"\n");
  ASSERT_EQ(tet.size(), 2u);
  EXPECT_NE(tet[0].find("interaction 'volume_shear' matches no element"), std::string::npos);
  EXPECT_EQ(tet[1],
            "criterion 'shear_force' cannot fire on the mesh 'block:tet:2x2x2': its measure "
            "reads only the stored f_volume_shear, which no interaction of the scene stores here "
            "('volume_shear' matches no element of this mesh)");
  // The right pairings give no warning.
  EXPECT_TRUE(setup_warnings("tet_ok", "block:tet:2x2x2",
                             "[[interaction]]\nname = \"corotational\"\n"
                             "[[criterion]]\nname = \"vertex_stress\"\n")
                  .empty());
  EXPECT_TRUE(setup_warnings("hex_ok", "block:hex:2x2x2",
                             "[[interaction]]\nname = \"volume_shear\"\n"
                             "[[criterion]]\nname = \"shear_force\"\n")
                  .empty());
}

TEST(SetupWarnings, CriteriaReadingForcesNoInteractionOfTheSceneStoresAreNamed) {
  // Every interaction acts, but none stores what the criterion reads.
  const auto hex = setup_warnings("hex_springs", "block:hex:2x2x2",
                                  "[[interaction]]\nname = \"volume_shear\"\n"
                                  "[[criterion]]\nname = \"vertex_stress\"\n");
  EXPECT_EQ(hex, (std::vector<std::string>{
                     "criterion 'vertex_stress' cannot fire on the mesh 'block:hex:2x2x2': its "
                     "measure reads only the stored stress_mass, stress_weighted, which no "
                     "interaction of the scene "
                     "stores here ('corotational' is not in the scene)"}));
  // 2D: the co-rotational triangle's stress read on quadrangles with springs.
  const auto quads = setup_warnings("quads", "grid:quad:3x3",
                                    "[[interaction]]\nname = \"stretch\"\n"
                                    "[[criterion]]\nname = \"element_stress\"\n");
  ASSERT_EQ(quads.size(), 1u);
  EXPECT_NE(quads[0].find("criterion 'element_stress' cannot fire on the mesh 'grid:quad:3x3': "
                          "its measure reads only the stored f_membrane"),
            std::string::npos)
      << quads[0];
  // A criterion reading several stored forces fires when one is there.
  EXPECT_TRUE(setup_warnings("any_force", "grid:quad:3x3",
                             "[[interaction]]\nname = \"stretch\"\n"
                             "[[criterion]]\nname = \"interaction_force\"\n")
                  .empty());
  // The sum of all forces (vertex_force) with no interaction acting.
  const auto sum = setup_warnings("sum", "block:hex:1x1x1",
                                  "[[interaction]]\nname = \"corotational\"\n"
                                  "[[criterion]]\nname = \"vertex_sum\"\n");
  ASSERT_EQ(sum.size(), 2u);
  EXPECT_EQ(sum[1],
            "criterion 'vertex_sum' cannot fire on the mesh 'block:hex:1x1x1': it reads "
            "vertex_force, the sum of the interactions' forces, and no interaction of the scene "
            "acts on this mesh");
  // Criteria of geometry and rest values alone always can.
  EXPECT_TRUE(setup_warnings("strain", "grid:quad:3x3",
                             "[[interaction]]\nname = \"stretch\"\n"
                             "[[criterion]]\nname = \"stretch_strain\"\n")
                  .empty());
}

// implicit_euler with Newton iterations searches along the incremental
// potential (docs/physics.md) only when every force has one; a load besides
// gravity has none, and set-up says the search falls back to the residual.
TEST(SetupWarnings, NewtonLineSearchFallingBackToTheResidualIsNamed) {
  auto implicit_warnings = [](const std::string& name, const std::string& extra,
                              const std::string& line_search) {
    const std::string path =
        ::testing::TempDir() + "rift_setup_" + name + "_" + std::to_string(::getpid()) + ".toml";
    std::string toml = static_scene("grid:quad:3x3", "1.0", 1.0,
                                    "[[interaction]]\nname = \"stretch\"\n"
                                    "[implicit]\nnewton_iterations = 4\n" +
                                        line_search + extra);
    toml.replace(toml.find("\"rk4\""), 5, "\"implicit_euler\"");
    std::ofstream(path) << toml;
    const Scene scene = read_scene(path, standard_packs().catalog());
    SetupReport report;
    build_simulation(scene, standard_packs(), {}, &report);
    std::remove(path.c_str());
    return report.warnings;
  };
  const std::string load = "[[load]]\nacceleration = [0, 3, 0]\n";
  EXPECT_EQ(implicit_warnings("implicit_load", load, ""),
            (std::vector<std::string>{
                "[implicit]: the Newton line search is on the residual |g|, not on the "
                "incremental potential: the scene has loads or drag besides gravity"}));
  // Springs and gravity alone have a potential: no note; nor when the scene
  // asks for the residual search itself.
  EXPECT_TRUE(implicit_warnings("implicit_springs", "", "").empty());
  EXPECT_TRUE(implicit_warnings("implicit_residual", load, "line_search = \"residual\"\n").empty());
}

}  // namespace
}  // namespace rift::tearing_test
