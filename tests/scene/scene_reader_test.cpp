#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "rift/core/input_error.hpp"
#include "rift/scene/scene.hpp"

namespace rift {
namespace {

namespace fs = std::filesystem;

Catalog test_catalog() {
  Catalog c;
  c.interactions.push_back({"stretch",
                            "stretch spring",
                            {{"stiffness", ValueType::kReal, std::nullopt, "N/m", true, false},
                             {"damping", ValueType::kReal, Value(0.0), "", false, true}}});
  c.criteria.push_back(
      {"global_edge", "", {{"threshold", ValueType::kReal, std::nullopt, "N", true, false}}});
  return c;
}

class SceneFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("rift_scene_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& text, const std::string& name = "scene.toml") {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

  // The message of the InputError read_scene throws, or "no error".
  std::string error(const std::string& text) {
    const std::string path = write(text);
    try {
      read_scene(path, test_catalog());
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path);
      return std::string(e.what()).substr(path.size());
    }
    return "no error";
  }

  fs::path dir_;
};

const char* kGood = R"(
[mesh]
source = "grid:quad:10x10"
rotate = [90, 0, 0]

[simulation]
integrator = "rk4"
dt = 0.002
steps = 500
gravity = [0, 0, -9.81]

[mass]
total = 0.1

[pin]
corners = ["top-left", "top-right"]

[[interaction]]
name = "stretch"
stiffness = 60

[[criterion]]
name = "global_edge"
threshold = 0.5

[output]
every = 5
formats = ["vtu", "png", "csv"]
)";

TEST_F(SceneFiles, ReadsEveryValue) {
  const Scene s = read_scene(write(kGood), test_catalog());
  EXPECT_EQ(s.name, "scene");
  EXPECT_EQ(s.mesh.source, "grid:quad:10x10");
  EXPECT_EQ(s.mesh.rotate_degrees, Vec3(90, 0, 0));
  EXPECT_EQ(s.integrator, IntegratorKind::kRK4);
  EXPECT_EQ(s.dt, 0.002);
  EXPECT_EQ(s.steps, 500);
  EXPECT_EQ(*s.total_mass, 0.1);
  EXPECT_EQ(s.pins.corners.size(), 2u);
  ASSERT_EQ(s.interactions.size(), 1u);
  EXPECT_EQ(s.interactions[0].real("stiffness"), 60.0);  // an integer read as a real
  EXPECT_EQ(s.interactions[0].real("damping"), 0.0);     // the default
  EXPECT_EQ(s.criteria[0].real("threshold"), 0.5);
  EXPECT_EQ(s.output.every, 5);
  EXPECT_EQ(s.output.dir, "out/scene");
}

TEST_F(SceneFiles, UnknownKeysNameTheLineAndTheClosestKey) {
  std::string text = kGood;
  text.replace(text.find("steps = 500"), 11, "stpes = 500");
  EXPECT_EQ(error(text), ":9: error: unknown key 'stpes' in [simulation] (did you mean 'steps'?)");
}

TEST_F(SceneFiles, WrongValuesAreRejectedWithWhatIsExpected) {
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = kGood;
    text.replace(text.find(from), from.size(), to);
    return error(text);
  };
  EXPECT_EQ(with("dt = 0.002", "dt = -0.002"), ":8: error: 'dt' must be positive, not -0.002");
  EXPECT_EQ(with("total = 0.1", "total = 0"), ":13: error: 'total' must be positive, not 0");
  EXPECT_EQ(with("threshold = 0.5", "threshold = \"high\""),
            ":24: error: 'threshold' must be a number, not a string");
  EXPECT_EQ(with("rk4", "rk5"),
            ":7: error: unknown integrator 'rk5': expected euler, symplectic_euler, rk4, "
            "implicit_euler or bdf2 (did you mean 'rk4'?)");
  EXPECT_EQ(with("\"grid:quad:10x10\"", "\"missing.obj\""),
            ":3: error: mesh file '" + (dir_ / "missing.obj").string() + "' does not exist");
  EXPECT_EQ(with("\"grid:quad:10x10\"", "\"grid:quad:0x10\""),
            ":3: error: cell counts must be at least 1");
  EXPECT_EQ(with("name = \"stretch\"", "name = \"strech\""),
            ":19: error: unknown interaction 'strech' (did you mean 'stretch'?); this simulator "
            "has: stretch");
  EXPECT_EQ(with("stiffness = 60", "stiffness = -60"),
            ":20: error: 'stiffness' of 'stretch' must be positive, not -60");
  EXPECT_EQ(with("stiffness = 60", "stifness = 60"),
            ":20: error: unknown key 'stifness' in [[interaction]] 'stretch' (did you mean "
            "'stiffness'?)");
  EXPECT_EQ(with("gravity = [0, 0, -9.81]", "gravity = [0, -9.81]"),
            ":10: error: 'gravity' must be an array of 3 numbers, like [0, 0, -9.81]");
  EXPECT_EQ(with("\"top-left\"", "\"top-middle\""),
            ":16: error: unknown corner 'top-middle': expected top-left, top-right, bottom-left "
            "or bottom-right");
  EXPECT_EQ(with("\"png\"", "\"jpg\""),
            ":28: error: unknown output format 'jpg': expected vtu, obj, png, gif or csv (did you "
            "mean 'png'?)");
}

TEST_F(SceneFiles, ImplicitSolverKeys) {
  auto implicit = [&](const std::string& table) {
    std::string text = kGood;
    text.replace(text.find("\"rk4\""), 5, "\"implicit_euler\"");
    text.replace(text.find("[mass]"), 6, "[implicit]\n" + table + "\n\n[mass]");
    return text;
  };
  const Scene s = read_scene(write(implicit("cg_tolerance = 1e-5\ncg_max_iterations = 40\n"
                                            "preconditioner = \"incomplete_cholesky\"\n"
                                            "newton_iterations = 3\njacobian = \"matrix_free\"")),
                             test_catalog());
  EXPECT_EQ(s.integrator, IntegratorKind::kImplicitEuler);
  EXPECT_EQ(s.implicit.cg_tolerance, 1e-5);
  EXPECT_EQ(s.implicit.cg_max_iterations, 40);
  EXPECT_EQ(s.implicit.preconditioner, PreconditionerKind::kIncompleteCholesky);
  EXPECT_EQ(s.implicit.newton_iterations, 3);
  EXPECT_EQ(s.implicit.jacobian, JacobianMode::kMatrixFree);
  // Defaults without the table.
  std::string plain = kGood;
  plain.replace(plain.find("\"rk4\""), 5, "\"implicit_euler\"");
  const Scene d = read_scene(write(plain), test_catalog());
  EXPECT_EQ(d.implicit.preconditioner, PreconditionerKind::kJacobi);
  EXPECT_EQ(d.implicit.newton_iterations, 1);
  EXPECT_TRUE(d.implicit.project_definite);
  EXPECT_FALSE(read_scene(write(implicit("project_definite = false")), test_catalog())
                   .implicit.project_definite);
  EXPECT_EQ(error(implicit("jacobian = \"matrix_free\"\nproject_definite = true")),
            ":14: error: 'project_definite' needs the element matrices: jacobian = "
            "\"assembled\"");

  EXPECT_EQ(error(implicit("preconditioner = \"ilu\"")),
            ":13: error: unknown preconditioner 'ilu': expected none, jacobi or "
            "incomplete_cholesky");
  EXPECT_EQ(error(implicit("cg_tolerance = 2.0")),
            ":13: error: 'cg_tolerance' is a relative residual: below 1");
  EXPECT_EQ(error(implicit("cg_iterations = 5")),
            ":13: error: unknown key 'cg_iterations' in [implicit] (did you mean "
            "'cg_max_iterations'?)");
  EXPECT_EQ(error(implicit("newton_iterations = 0")),
            ":13: error: 'newton_iterations' must be between 1 and 1000, not 0");
  EXPECT_EQ(error(implicit("jacobian = \"dense\"")),
            ":13: error: unknown jacobian 'dense': expected assembled or matrix_free");
  // [implicit] with an explicit integrator is a mistake worth naming.
  std::string rk4 = kGood;
  rk4.replace(rk4.find("[mass]"), 6, "[implicit]\ncg_tolerance = 1e-4\n\n[mass]");
  EXPECT_EQ(error(rk4),
            ":12: error: [implicit] sets the solver of integrator = \"implicit_euler\" or "
            "\"bdf2\", but the scene's integrator is 'rk4'");
}

TEST_F(SceneFiles, MissingPiecesAndBrokenToml) {
  EXPECT_EQ(error("[simulation]\ndt = 0.1\n"), ": error: the scene needs a [mesh] table");
  EXPECT_EQ(error("[mesh]\nsource = \"grid:quad:2x2\"\n"),
            ": error: the scene has no [[interaction]]: nothing would move but gravity");
  EXPECT_EQ(error("[mesh]\nsource = \"grid:quad:2x2\"\n[[interaction]]\nname = \"stretch\"\n"),
            ":3: error: interaction 'stretch' needs parameter 'stiffness' (N/m)");
  const std::string broken = error("[mesh]\nsource = \"grid:quad:2x2\n");
  EXPECT_EQ(broken.rfind(":2: error: not valid TOML: ", 0), 0u) << broken;
  EXPECT_THROW(read_scene((dir_ / "nope.toml").string(), test_catalog()), InputError);
}

TEST_F(SceneFiles, MeshPathsAreRelativeToTheScene) {
  write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "tri.obj");
  std::string text = kGood;
  text.replace(text.find("\"grid:quad:10x10\""), 17, "\"tri.obj\"");
  const Scene s = read_scene(write(text), test_catalog());
  EXPECT_EQ(s.mesh.source, (dir_ / "tri.obj").string());
}

const char* kDriven = R"(
[mesh]
source = "grid:tri:4x4"

[simulation]
gravity = [0, 0, 0]

[[handle]]
name = "grip"
select = { side = "top", within = 0.01 }
velocity = [0, 0.1, 0]
release = 0.5

[[handle]]
select = "bottom-left"
keyframes = [{ time = 0 }, { time = 1, translate = [0, 0, 0.1], rotate = [0, 0, 90] }]
pivot = [0, 0, 0]

[[load]]
select = { sphere = { center = [0.5, 0.5, 0], radius = 0.2 } }
force = [0, 0, 1]
ramp = 0.25

[[load]]
acceleration = [1, 0, 0]
per_vertex = true

[[initial_velocity]]
select = { box = { min = [0, 0, 0], max = [1, 0.5, 0] } }
velocity = [0, 0, 2]

[[obstacle]]
shape = "sphere"
center = [0.5, 0.5, 1]
radius = 0.1
velocity = [0, 0, -5]
friction = 0.3

[[obstacle]]
shape = "plane"
point = [0, 0, -1]
normal = [0, 0, 1]

[[notch]]
from = [0, 0.5, 0]
to = [0.3, 0.5, 0]

[drag]
coefficient = 0.5

[[interaction]]
name = "stretch"
stiffness = 60

[output]
formats = ["png", "gif"]
camera = "follow"
)";

TEST_F(SceneFiles, ReadsHandlesLoadsObstaclesAndNotches) {
  const Scene s = read_scene(write(kDriven), test_catalog());
  ASSERT_EQ(s.handles.size(), 2u);
  EXPECT_EQ(s.handles[0].motion.name, "grip");
  EXPECT_EQ(s.handles[0].select.kind, Selection::Kind::kSide);
  EXPECT_EQ(s.handles[0].select.within, 0.01);
  EXPECT_EQ(s.handles[0].motion.velocity, Vec3(0, 0.1, 0));
  EXPECT_EQ(s.handles[0].motion.release, 0.5);
  EXPECT_EQ(s.handles[1].motion.name, "handle2");
  EXPECT_EQ(s.handles[1].select.kind, Selection::Kind::kCorner);
  ASSERT_EQ(s.handles[1].motion.keyframes.size(), 2u);
  EXPECT_EQ(s.handles[1].motion.keyframes[1].rotate_degrees, Vec3(0, 0, 90));
  // Halfway: half the translation and a quarter turn's half about the pivot.
  const Vec3 half = s.handles[1].motion.place(Vec3(1, 0, 0), 0.5);
  EXPECT_NEAR(half.x(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(half.y(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(half.z(), 0.05, 1e-12);
  ASSERT_EQ(s.loads.size(), 2u);
  EXPECT_EQ(s.loads[0].select.kind, Selection::Kind::kSphere);
  EXPECT_EQ(s.loads[0].spec.ramp, 0.25);
  EXPECT_EQ(s.loads[1].select.kind, Selection::Kind::kAll);
  EXPECT_TRUE(s.loads[1].spec.per_vertex);
  ASSERT_EQ(s.initial_velocities.size(), 1u);
  EXPECT_EQ(s.initial_velocities[0].select.kind, Selection::Kind::kBox);
  ASSERT_EQ(s.obstacles.size(), 2u);
  EXPECT_EQ(s.obstacles[0].obstacle.shape, Obstacle::Shape::kSphere);
  EXPECT_EQ(s.obstacles[0].obstacle.friction, 0.3);
  EXPECT_EQ(s.obstacles[1].obstacle.shape, Obstacle::Shape::kPlane);
  ASSERT_EQ(s.notches.size(), 1u);
  EXPECT_EQ(s.notches[0].to, Vec3(0.3, 0.5, 0));
  EXPECT_EQ(s.drag.coefficient, 0.5);
  EXPECT_EQ(s.output.camera, CameraMode::kFollow);
}

TEST_F(SceneFiles, DriversAreCheckedWithFileLineAndWhatIsExpected) {
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = kDriven;
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    return error(text);
  };
  EXPECT_EQ(with("release = 0.5", "relase = 0.5"),
            ":12: error: unknown key 'relase' in [[handle]] (did you mean 'release'?)");
  EXPECT_EQ(with("velocity = [0, 0.1, 0]", "velocity = \"up\""),
            ":11: error: 'velocity' must be an array of 3 numbers, like [0, 0, -9.81]");
  EXPECT_EQ(with("radius = 0.1", "radius = -0.1"),
            ":35: error: 'radius' must be positive, not -0.1");
  EXPECT_EQ(with("radius = 0.2", "radius = -0.2"),
            ":20: error: 'radius' must be positive, not -0.2");
  EXPECT_EQ(with("select = \"bottom-left\"", "select = \"bottom-middle\""),
            ":15: error: unknown selection 'bottom-middle': expected a side (top, bottom, left, "
            "right, front, back), a corner (top-left, top-right, bottom-left, bottom-right) or "
            "all");
  EXPECT_EQ(with("shape = \"plane\"", "shape = \"plain\""),
            ":40: error: unknown obstacle shape 'plain': expected plane, sphere, box or capsule "
            "(did you mean 'plane'?)");
  EXPECT_EQ(with("friction = 0.3", "friction = -0.3"),
            ":37: error: 'friction' must not be negative, not -0.3");
  EXPECT_EQ(with("{ time = 1,", "{ time = 0,"), ":16: error: keyframe times must increase");
  EXPECT_EQ(with("name = \"grip\"\n", ""),
            "no error");  // a handle's name is optional
  EXPECT_EQ(
      with("[[initial_velocity]]\nselect = { box = { min = [0, 0, 0], max = [1, 0.5, 0] } }\n",
           "[[initial_velocity]]\n"),
      ":28: error: [[initial_velocity]] needs 'select': a side (\"top\", \"left\"...), a "
      "corner (\"top-left\"...), \"all\", or a table such as { box = { min = [..], max = "
      "[..] } }, { sphere = { center = [..], radius = r } }, { vertices = [..] }, { group = "
      "tag }");
  EXPECT_EQ(with("{ side = \"top\", within = 0.01 }", "{ side = \"top\", box = {} }"),
            ":10: error: a selection takes exactly one of side, corner, vertices, box, sphere or "
            "group");
  EXPECT_EQ(with("camera = \"follow\"", "camera = \"folow\""),
            ":57: error: unknown camera 'folow': expected fixed, follow or follow_union (did you "
            "mean 'follow'?)");
  EXPECT_EQ(with("coefficient = 0.5", "coefficient = 0"),
            ":49: error: 'coefficient' must be positive, not 0");
}

}  // namespace
}  // namespace rift
