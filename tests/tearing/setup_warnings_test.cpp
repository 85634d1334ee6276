// Scene set-up warns when an interaction cannot act on the mesh: its forces
// stay zero, and the criteria that read them can never fire (vertex_stress
// reads the co-rotational tetrahedron's forces, shear_force the hexahedron's
// volume shear springs).
#include <gtest/gtest.h>

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

TEST(SetupWarnings, InteractionsThatMatchNoElementAreNamedWithTheirCriteria) {
  const auto hex = setup_warnings("hex", "block:hex:2x2x2",
                                  "[[interaction]]\nname = \"corotational\"\n"
                                  "[[criterion]]\nname = \"vertex_stress\"\n");
  ASSERT_EQ(hex.size(), 1u);
  EXPECT_EQ(hex[0],
            "interaction 'corotational' matches no element of the mesh 'block:hex:2x2x2' (its "
            "pattern needs other elements): it exerts no force, and criteria that read its forces "
            "(of: vertex_stress) cannot fire");
  const auto tet = setup_warnings("tet", "block:tet:2x2x2",
                                  "[[interaction]]\nname = \"volume_shear\"\n"
                                  "[[criterion]]\nname = \"shear_force\"\n");
  ASSERT_EQ(tet.size(), 1u);
  EXPECT_NE(tet[0].find("interaction 'volume_shear' matches no element"), std::string::npos);
  EXPECT_NE(tet[0].find("(of: shear_force) cannot fire"), std::string::npos);
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

}  // namespace
}  // namespace rift::tearing_test
