// The scene drivers the experiments use: handles (fixed, keyframed,
// released, their reaction), loads, initial velocities, contact with
// friction, notches, selections and physical groups, and setup errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "experiment_support.hpp"
#include "rift/core/input_error.hpp"
#include "rift/io/load_map.hpp"
#include "rift/io/read_mesh.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/output/gif_writer.hpp"
#include "rift/scene/selection.hpp"

namespace rift::experiment_test {
namespace {

const char* kSprings = R"(
[[interaction]]
name = "stretch"
stiffness = 60.0
damping = 0.5
[[interaction]]
name = "shear"
stiffness = 43.0
damping = 0.5
)";

std::string cloth(const std::string& body, const std::string& simulation = "") {
  return "[mesh]\nsource = \"grid:quad:6x6\"\nrotate = [90, 0, 0]\n[simulation]\n"
         "integrator = \"rk4\"\ndt = 0.001\n" +
         simulation + "[mass]\ntotal = 0.1\n" + body + kSprings;
}

TEST(Handles, ReactionOfAHangingClothIsItsWeight) {
  auto sim =
      simulate(scene_of("reaction", cloth("[[handle]]\nname = \"rail\"\nselect = \"top\"\n")));
  for (int k = 0; k < 3000; ++k)
    sim->step();
  ASSERT_EQ(sim->handle_reactions().size(), 1u);
  const Vec3 r = sim->handle_reactions()[0];
  EXPECT_NEAR(r.z(), 0.1 * 9.81, 0.01 * 0.981);
  EXPECT_NEAR(r.x(), 0.0, 1e-3);
  // The rail did not move.
  sim->map().for_each_cell(Orbit::cell(0, 2), [&](Dart d) {
    if (sim->handles()->handle_of(d) == 0) {
      EXPECT_NEAR(sim->position()[d].z(), 1.0, 1e-12);
    }
  });
}

TEST(Handles, PinIsAFixedHandleAndKeyframesRotateAboutThePivot) {
  auto sim = simulate(
      scene_of("keyframes",
               cloth("[pin]\ncorners = [\"top-left\"]\n"
                     "[[handle]]\nname = \"crank\"\nselect = \"top-right\"\npivot = [1, 0, 0.5]\n"
                     "keyframes = [{ time = 0 }, { time = 0.1, rotate = [0, 90, 0] }]\n",
                     "gravity = [0, 0, 0]\n")));
  ASSERT_EQ(sim->handles()->count(), 2u);
  EXPECT_EQ(sim->handles()->motion(0).name, "pin");
  for (int k = 0; k < 100; ++k)
    sim->step();
  // (1, 0, 1) turned by 90 degrees about +y through (1, 0, 0.5): (1.5, 0, 0.5).
  bool seen = false;
  sim->map().for_each_cell(Orbit::cell(0, 2), [&](Dart d) {
    if (sim->handles()->handle_of(d) != 1) return;
    seen = true;
    EXPECT_NEAR(sim->position()[d].x(), 1.5, 1e-9);
    EXPECT_NEAR(sim->position()[d].z(), 0.5, 1e-9);
  });
  EXPECT_TRUE(seen);
}

TEST(Handles, ReleasedHandleLetsGo) {
  auto sim = simulate(scene_of("release", cloth("[[handle]]\nselect = \"top\"\nrelease = 0.05\n")));
  for (int k = 0; k < 100; ++k)
    sim->step();
  // 0.05 s of free fall: the rail fell by about g t^2 / 2 = 1.2 cm.
  sim->map().for_each_cell(Orbit::cell(0, 2), [&](Dart d) {
    if (sim->handles()->handle_of(d) == 0) {
      EXPECT_LT(sim->position()[d].z(), 0.995);
    }
  });
}

TEST(Handles, PinsKeepNoRestPositionsAndHoldTheirVerticesExactlyThroughTears) {
  // A pin holds its vertices where they are: its target is their position,
  // so no rest position is kept; tears that split a pinned vertex leave
  // both halves pinned, exactly where they were.
  auto sim = simulate(scene_of(
      "pins_tear", cloth("[pin]\nbox = [{ min = [-1, -1, 0.99], max = [2, 1, 1.01] "
                         "}]\n[[criterion]]\nname = \"spring_split\"\nthreshold = 0.02\n")));
  EXPECT_FALSE(sim->handles()->keeps_rest());
  EXPECT_FALSE(sim->map().embedding<Vec3>("handle_rest"));
  std::vector<Vec3> pinned_at;
  sim->map().for_each_cell(Orbit::cell(0, 2), [&](Dart d) {
    if (sim->handles()->handle_of(d) == 0) pinned_at.push_back(sim->position()[d]);
  });
  ASSERT_EQ(pinned_at.size(), 7u);
  std::size_t tears = 0;
  for (int k = 0; k < 300; ++k) {
    sim->step();
    tears += sim->tears_last_step();
  }
  EXPECT_GT(tears, 0u);
  EXPECT_TRUE(sim->map().is_valid());
  std::size_t held = 0;
  sim->map().for_each_cell(Orbit::cell(0, 2), [&](Dart d) {
    if (sim->handles()->handle_of(d) != 0) return;
    ++held;
    const Vec3& x = sim->position()[d];
    EXPECT_TRUE(
        std::any_of(pinned_at.begin(), pinned_at.end(), [&](const Vec3& p) { return p == x; }))
        << "a pinned vertex moved to " << x.transpose();
  });
  EXPECT_GE(held, pinned_at.size());
}

TEST(Handles, MovingHandlesAndHoldsAwayFromTheVertexKeepRestPositions) {
  // A moving handle needs each vertex's rest position.
  auto moving = simulate(
      scene_of("moving", cloth("[pin]\ncorners = [\"top-left\"]\n"
                               "[[handle]]\nselect = \"top-right\"\nvelocity = [0.1, 0, 0]\n")));
  EXPECT_TRUE(moving->handles()->keeps_rest());
  // A fixed handle told to hold a vertex elsewhere puts it there.
  rift::GMap map = rift::load_map("grid:quad:2x2");
  const Embedding<Vec3> x = map.embedding<Vec3>("position");
  ASSERT_TRUE(x);
  Handles handles(map);
  const int h = handles.add(HandleMotion{});
  EXPECT_FALSE(handles.keeps_rest());
  const Dart d = 0;
  ASSERT_TRUE(handles.hold(d, h, x[d]));
  EXPECT_FALSE(handles.keeps_rest());
  const Vec3 elsewhere = x[d] + Vec3(0, 0, 0.5);
  const Dart other = map.alpha(d, 0);
  ASSERT_TRUE(handles.hold(other, h, elsewhere));
  EXPECT_TRUE(handles.keeps_rest());
  EXPECT_EQ(handles.target(x.attachment().slot(other), 1.0), elsewhere);
  // The vertex held before keeps its place.
  EXPECT_EQ(handles.target(x.attachment().slot(d), 1.0), x[d]);
}
TEST(Handles, ImplicitStepSolvesBackwardEulerWithTheHandlesMotion) {
  // A moving handle is a Dirichlet degree of freedom of the implicit solve:
  // its vertices land exactly on the prescribed path, and the free vertices'
  // end-of-step state solves backward Euler with the handle where it ends
  // the step, g = M (v1 - v0) - h (f(x1, v1) + M g) = 0. Imposed after the
  // solve instead (the solve seeing the handle stand still), g would be of
  // the order h² k u per vertex next to the handle.
  const Real h = 0.01;
  auto sim = simulate(scene_of(
      "implicit_handle",
      "[mesh]\nsource = \"grid:quad:6x6\"\nrotate = [90, 0, 0]\n[simulation]\n"
      "integrator = \"implicit_euler\"\ndt = 0.01\n[mass]\ntotal = 0.1\n"
      "[implicit]\nnewton_iterations = 30\nnewton_tolerance = 1e-13\ncg_tolerance = 1e-12\n"
      "cg_max_iterations = 2000\n"
      "[pin]\ncorners = [\"bottom-left\"]\n"
      "[[handle]]\nname = \"crank\"\nselect = \"top\"\npivot = [0.5, 0, 1]\n"
      "velocity = [0.3, 0, 0.2]\n"
      "keyframes = [{ time = 0 }, { time = 0.1, rotate = [0, 30, 0] }]\n" +
          std::string(kSprings)));
  const Handles& handles = *sim->handles();
  const auto& x = sim->position().values();
  const auto& v = sim->velocity().values();
  const auto& mass = sim->vertex_mass().values();
  const OrbitAttachment& att = sim->position().attachment();
  // The first steps, while Newton converges fully (later, the damped
  // springs' non-symmetric ∂f/∂x leaves CG's Newton systems inexact).
  for (int k = 0; k < 4; ++k) {
    const std::vector<Vec3> x0 = x, v0 = v;
    const Real t0 = sim->time();
    sim->step();
    // The step's end velocities: a held vertex's is the one that carried it
    // onto the path, (x1 - x0) / h (the loop then sets the next interval's,
    // which differs on the keyframed turn).
    std::vector<Vec3> v1 = v;
    for (Slot s = 0; s < x.size(); ++s) {
      if (att.slot_alive(s) && handles.holds(s, t0)) v1[s] = (x[s] - x0[s]) / h;
    }
    std::vector<Vec3> f(x.size(), Vec3::Zero());
    for (const auto& m : sim->force_models())
      m->add_forces({x.data(), v1.data()}, f.data(), false);
    Real worst = 0, scale = 0, held = 0;
    for (Slot s = 0; s < x.size(); ++s) {
      if (!att.slot_alive(s)) continue;
      if (handles.holds(s, t0)) {
        // Exactly on the path (the keyframed turn plus the constant velocity).
        EXPECT_LT((x[s] - handles.target(s, sim->time())).norm(), 1e-12) << "step " << k;
        held += 1;
        continue;
      }
      const Vec3 g = mass[s] * (v[s] - v0[s]) - h * (f[s] + mass[s] * sim->settings().gravity);
      worst = std::max(worst, g.norm());
      scale = std::max(scale, h * f[s].norm());
    }
    EXPECT_EQ(held, 8.0);  // the top row of 7 and the pinned corner (a fixed handle)
    ASSERT_GT(scale, 0.0);
    EXPECT_LT(worst, 1e-7 * scale) << "step " << k;
  }
}

TEST(Loads, ForcesRampsAndInitialVelocitiesGiveTheMomentum) {
  const std::string body =
      "[[load]]\nforce = [1, 0, 0]\n"                                         // 1 N in total
      "[[load]]\nselect = \"top\"\nforce = [0, 0.1, 0]\nper_vertex = true\n"  // 7 vertices
      "[[load]]\nacceleration = [0, 0, 2]\nramp = 0.05\n"
      "[[initial_velocity]]\nselect = \"all\"\nvelocity = [0, 0, -1]\n";
  auto sim = simulate(scene_of("loads", cloth(body, "gravity = [0, 0, 0]\n")));
  const Real m = sim->total_mass();
  EXPECT_NEAR(sim->momentum().z(), -m, 1e-12);
  for (int k = 0; k < 100; ++k)
    sim->step();
  const Vec3 p = sim->momentum();
  EXPECT_NEAR(p.x(), 1.0 * 0.1, 1e-9);
  EXPECT_NEAR(p.y(), 7 * 0.1 * 0.1, 1e-9);
  // Ramp: full after 0.05 s, so the impulse is m a (0.1 - 0.025), give or
  // take the first-order sampling of the ramp at step starts.
  EXPECT_NEAR(p.z(), -m + m * 2 * 0.075, 0.02 * m * 2 * 0.075);
  EXPECT_GT(sim->external_work(), 0.0);
}

// Air drag on a flat sheet falling face first: m dv/dt = -m g - c A v, so
// v(t) = -v_t (1 - exp(-t / tau)) with v_t = m g / (c A), tau = m / (c A).
// A velocity in the sheet's own plane meets no drag and stays.
TEST(Drag, FallingSheetApproachesItsTerminalVelocity) {
  auto sheet = [](const std::string& wind) {
    return "[mesh]\nsource = \"grid:quad:6x6\"\n[simulation]\nintegrator = \"rk4\"\n"
           "dt = 0.001\ngravity = [0, 0, -9.81]\n[mass]\ntotal = 0.1\n[drag]\n"
           "coefficient = 0.5\n" +
           wind + "[[initial_velocity]]\nselect = \"all\"\nvelocity = [0.3, 0, 0]\n" +
           std::string(kSprings);
  };
  const Real c = 0.5, area = 1.0;
  auto fall = [&](const std::string& wind, Real wind_z) {
    auto sim = simulate(scene_of("drag", sheet(wind)));
    const Real m = sim->total_mass();
    const Real tau = m / (c * area), terminal = m * 9.81 / (c * area);
    for (int k = 0; k < 400; ++k)
      sim->step();
    const Real t = sim->time();
    const Vec3 v = sim->momentum() / m;
    // Relative to the air, the sheet tends to -v_t.
    EXPECT_NEAR(v.z() - wind_z, -terminal - (-terminal - (-wind_z)) * std::exp(-t / tau),
                1e-6 * terminal);
    EXPECT_NEAR(v.x(), 0.3, 1e-9);  // in its own plane: no drag
    // Still flat: the drag per unit mass is the same everywhere.
    Real lo = INFINITY, hi = -INFINITY;
    sim->map().for_each_cell(Orbit::cell(0, 2), [&](Dart d) {
      lo = std::min(lo, sim->position()[d].z());
      hi = std::max(hi, sim->position()[d].z());
    });
    EXPECT_LT(hi - lo, 1e-6);
  };
  fall("", 0.0);
  fall("wind = [0, 0, 1.5]\n", 1.5);  // an updraft: the sheet falls slower
}

TEST(Contact, GroundStopsTheFallAndFrictionSlowsASlide) {
  const std::string body =
      "[[obstacle]]\nshape = \"plane\"\npoint = [0, 0, 0]\nfriction = 0.5\n"
      "[[initial_velocity]]\nselect = \"all\"\nvelocity = [1, 0, 0]\n";
  auto sim = simulate(scene_of(
      "ground",
      "[mesh]\nsource = \"grid:quad:4x4\"\n[simulation]\nintegrator = "
      "\"symplectic_euler\"\ndt = 0.001\n[mass]\ntotal = 0.1\n" +
          body + "[[obstacle]]\nshape = \"box\"\nmin = [5, -1, -1]\nmax = [6, 2, 1]\n" + kSprings));
  // The sheet lies on the ground (z = 0) and slides, losing mu g = 4.9 m/s
  // per second: each step gravity pushes it in by g dt^2, the projection
  // takes g dt of normal velocity, friction mu g dt of tangential.
  for (int k = 0; k < 100; ++k)
    sim->step();
  Real lowest = INFINITY;
  sim->map().for_each_cell(Orbit::cell(0, 2),
                           [&](Dart d) { lowest = std::min(lowest, sim->position()[d].z()); });
  EXPECT_GE(lowest, -1e-12);
  const Real vx = sim->momentum().x() / sim->total_mass();
  EXPECT_NEAR(vx, 1.0 - 0.5 * 9.81 * 0.1, 0.02);
}

TEST(Notches, CutThroughThePacksRuleKeepTheMapValidAndTheMass) {
  SetupReport report;
  auto sim = simulate(scene_of("notch2d",
                               "[mesh]\nsource = \"grid:tri:10x10\"\n"
                               "[[notch]]\nfrom = [0, 0.5, 0]\nto = [0.46, 0.5, 0]\n" +
                                   std::string(kSprings)),
                      &report);
  EXPECT_EQ(report.notch_cuts, 5u);  // 4.5 edges: those whose middle is on the segment
  EXPECT_TRUE(sim->map().is_valid());
  // Each cut edge splits its left end (the tip stays whole).
  EXPECT_EQ(sim->map().count_cells_of_dimension(0), 121u + 5u);
  EXPECT_NEAR(sim->total_mass(), 1.0, 1e-12);
}

// A planar patch in a tetrahedral block cuts exactly the faces it crosses:
// the patch x = 0.5, 0 <= y <= 1, 0 <= z <= 0.5 of the unit block of 4 x 2 x 4
// cubes (six tetrahedra each) covers 2 x 2 cube faces, two triangles each.
// (An earlier version of this test counted 13 because it reused the report
// of a 2D notch of 5 cuts: the cut itself was right.)
TEST(Notches, PatchCutsExactlyTheFacesItCrosses) {
  SetupReport report;
  auto bar =
      simulate(scene_of("notch3d",
                        "[mesh]\nsource = \"block:tet:4x2x4\"\n[[notch]]\nfrom = [0.5, 0, 0]\n"
                        "to = [0.5, 1, 0]\ndepth = [0, 0, 0.5]\n"
                        "[[interaction]]\nname = \"corotational\"\n"),
               &report);
  EXPECT_EQ(report.notch_cuts, 2u * 2u * 2u);
  EXPECT_TRUE(bar->map().is_valid());
  EXPECT_NEAR(bar->total_mass(), 1.0, 1e-12);
  // The new free faces: each cut face twice (one per side), all in the
  // patch; none elsewhere.
  const GMap& g = bar->map();
  const Embedding<Vec3> position = g.embedding<Vec3>("position");
  std::size_t in_patch = 0, elsewhere_inside = 0;
  g.for_each_cell(Orbit{0, 1}, [&](Dart d) {
    if (!g.is_free(d, 3)) return;
    Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
    g.for_each_in_orbit(d, Orbit{0, 1}, [&](Dart x) {
      lo = lo.cwiseMin(position[x]);
      hi = hi.cwiseMax(position[x]);
    });
    const bool on_hull = hi.x() < 1e-12 || lo.x() > 1 - 1e-12 || hi.y() < 1e-12 ||
                         lo.y() > 1 - 1e-12 || hi.z() < 1e-12 || lo.z() > 1 - 1e-12;
    if (on_hull) return;
    if (std::abs(lo.x() - 0.5) < 1e-12 && std::abs(hi.x() - 0.5) < 1e-12 && hi.z() <= 0.5 + 1e-12)
      ++in_patch;
    else
      ++elsewhere_inside;
  });
  EXPECT_EQ(in_patch, 2u * 8u);
  EXPECT_EQ(elsewhere_inside, 0u);
}

// Selections list their vertices as GMap::for_each_cell visits them (each
// vertex's smallest dart, in increasing order), also on a map whose vertex
// slots do not follow the darts' order: a notch's cuts split vertices, whose
// new halves take slots at the end.
TEST(Selections, ListVerticesInTheOrderOfTheCellsWhateverTheSlots) {
  SetupReport report;
  auto sim = simulate(scene_of("notch_selection",
                               "[mesh]\nsource = \"grid:mix:10x10\"\n"
                               "[[notch]]\nfrom = [0, 0.5, 0]\nto = [0.46, 0.5, 0]\n" +
                                   std::string(kSprings)),
                      &report);
  ASSERT_GT(report.notch_cuts, 0u);
  const GMap& map = sim->map();
  const Embedding<Vec3>& position = sim->position();
  std::vector<Dart> cells;
  map.for_each_cell(Orbit{1, 2}, [&](Dart d) { cells.push_back(d); });
  // The premise: the slots of the cells, in cell order, are not in order.
  bool slots_out_of_order = false;
  for (std::size_t i = 1; i < cells.size(); ++i)
    slots_out_of_order =
        slots_out_of_order || position.slot(cells[i]) < position.slot(cells[i - 1]);
  ASSERT_TRUE(slots_out_of_order);

  const Vec3 up(0, 1, 0);
  Selection all;
  EXPECT_EQ(select_vertices(map, all, up), cells);
  Selection box;
  box.kind = Selection::Kind::kBox;
  box.lo = Vec3(0.2, -1, -1);
  box.hi = Vec3(0.7, 0.5, 1);
  std::vector<Dart> in_box;
  for (const Dart d : cells) {
    const Vec3& p = position[d];
    if ((p.array() >= box.lo.array()).all() && (p.array() <= box.hi.array()).all())
      in_box.push_back(d);
  }
  ASSERT_FALSE(in_box.empty());
  EXPECT_EQ(select_vertices(map, box, up), in_box);
  Selection corner;
  corner.kind = Selection::Kind::kCorner;
  corner.name = "bottom-left";
  const auto found = select_vertices(map, corner, up);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(position[found[0]], Vec3(0, 0, 0));
}

TEST(Selections, SidesCornersShapesAndGroups) {
  MeshData mesh = make_grid(GridKind::Quad, 4, 4);
  GMap map = assemble_gmap(mesh);
  const Vec3 up(0, 1, 0);
  auto count = [&](Selection s) { return select_vertices(map, s, up).size(); };
  Selection s;
  EXPECT_EQ(count(s), 25u);
  s.kind = Selection::Kind::kSide;
  s.name = "top";
  EXPECT_EQ(count(s), 5u);
  s.within = 0.3;  // two rows
  EXPECT_EQ(count(s), 10u);
  s.within = 0;
  s.name = "left";
  EXPECT_EQ(count(s), 5u);
  s.kind = Selection::Kind::kCorner;
  s.name = "top-right";
  const auto corner = select_vertices(map, s, up);
  ASSERT_EQ(corner.size(), 1u);
  EXPECT_EQ(map.embedding<Vec3>("position")[corner[0]], Vec3(1, 1, 0));
  s.kind = Selection::Kind::kSphere;
  s.centre = Vec3(0.5, 0.5, 0);
  s.radius = 0.26;
  EXPECT_EQ(count(s), 5u);
  s.kind = Selection::Kind::kBox;
  s.lo = Vec3(-1, -1, -1);
  s.hi = Vec3(0.3, 2, 1);
  EXPECT_EQ(count(s), 10u);

  // A Gmsh file with two physical groups: 2 triangles in group 7, one in 9.
  const std::string path = ::testing::TempDir() + "rift_groups.msh";
  std::ofstream(path) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n"
                         "3 1 1 0\n4 0 1 0\n5 2 0 0\n$EndNodes\n$Elements\n3\n"
                         "1 2 2 7 1 1 2 3\n2 2 2 7 1 1 3 4\n3 2 2 9 2 2 5 3\n$EndElements\n";
  GMap groups = assemble_gmap(read_mesh_file(path));
  s.kind = Selection::Kind::kGroup;
  s.group = 7;
  EXPECT_EQ(select_vertices(groups, s, up).size(), 4u);
  s.group = 9;
  EXPECT_EQ(select_vertices(groups, s, up).size(), 3u);
  s.group = 8;
  EXPECT_EQ(select_vertices(groups, s, up).size(), 0u);
}

// Gmsh 4.1 keeps physical groups in $Entities: an element's group is its
// entity's first physical tag. The same mesh as above.
TEST(Selections, GroupsOfAGmsh4File) {
  const std::string path = ::testing::TempDir() + "rift_groups4.msh";
  std::ofstream(path) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                         "$Entities\n0 0 2 0\n1 0 0 0 1 1 0 1 7 0\n2 1 0 0 2 1 0 2 9 11 0\n"
                         "$EndEntities\n"
                         "$Nodes\n1 5 1 5\n2 1 0 5\n1\n2\n3\n4\n5\n"
                         "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n$EndNodes\n"
                         "$Elements\n2 3 1 3\n2 1 2 2\n1 1 2 3\n2 1 3 4\n2 2 2 1\n3 2 5 3\n"
                         "$EndElements\n";
  const MeshData mesh = read_mesh_file(path);
  EXPECT_EQ(mesh.element_tags, (std::vector<std::int64_t>{7, 7, 9}));
  GMap map = assemble_gmap(mesh);
  Selection s;
  s.kind = Selection::Kind::kGroup;
  const Vec3 up(0, 1, 0);
  s.group = 7;
  EXPECT_EQ(select_vertices(map, s, up).size(), 4u);
  s.group = 9;
  EXPECT_EQ(select_vertices(map, s, up).size(), 3u);
  s.group = 11;  // the second physical tag of entity 2: not its group
  EXPECT_EQ(select_vertices(map, s, up).size(), 0u);

  // An entity without physical tag leaves its elements, and so the mesh,
  // without groups (Gmsh writes such files when asked to save everything).
  std::ofstream(path) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                         "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 0 0\n$EndEntities\n"
                         "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n1 1 0\n$EndNodes\n"
                         "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n";
  EXPECT_TRUE(read_mesh_file(path).element_tags.empty());
}

// VTU: the cell data array of integers (the one CellData's Scalars names,
// else the first) holds the cells' groups; the same for PointData and points.
TEST(Selections, GroupsOfAVtuFile) {
  const std::string path = ::testing::TempDir() + "rift_groups.vtu";
  std::ofstream(path)
      << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "<UnstructuredGrid>\n<Piece NumberOfPoints=\"5\" NumberOfCells=\"3\">\n"
         "<PointData Scalars=\"pin\">\n"
         "<DataArray type=\"Int32\" Name=\"other\" format=\"ascii\">5 5 5 5 5</DataArray>\n"
         "<DataArray type=\"Int32\" Name=\"pin\" format=\"ascii\">0 0 0 0 4</DataArray>\n"
         "</PointData>\n<CellData>\n"
         "<DataArray type=\"Float32\" Name=\"quality\" format=\"ascii\">1 1 1</DataArray>\n"
         "<DataArray type=\"Int32\" Name=\"gmsh:physical\" format=\"ascii\">7 7 9</DataArray>\n"
         "</CellData>\n<Points>\n"
         "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
         "0 0 0 1 0 0 1 1 0 0 1 0 2 0 0</DataArray>\n</Points>\n<Cells>\n"
         "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">"
         "0 1 2 0 2 3 1 4 2</DataArray>\n"
         "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6 9</DataArray>\n"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5 5 5</DataArray>\n"
         "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  const MeshData mesh = read_mesh_file(path);
  EXPECT_EQ(mesh.element_tags, (std::vector<std::int64_t>{7, 7, 9}));
  EXPECT_EQ(mesh.point_tags, (std::vector<std::int64_t>{0, 0, 0, 0, 4}));
  GMap map = assemble_gmap(mesh);
  Selection s;
  s.kind = Selection::Kind::kGroup;
  const Vec3 up(0, 1, 0);
  s.group = 7;
  EXPECT_EQ(select_vertices(map, s, up).size(), 4u);
  s.group = 9;
  EXPECT_EQ(select_vertices(map, s, up).size(), 3u);
  s.group = 4;  // the point group: point 4 alone
  const auto point = select_vertices(map, s, up);
  ASSERT_EQ(point.size(), 1u);
  EXPECT_EQ(map.embedding<Vec3>("position")[point[0]], Vec3(2, 0, 0));
  s.group = 5;  // the array the Scalars attribute does not name
  EXPECT_EQ(select_vertices(map, s, up).size(), 0u);
}

std::string setup_error(const std::string& name, const std::string& toml) {
  try {
    simulate(scene_of(name, toml));
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ": " + e.problem();
  }
  return "no error";
}

TEST(SetupErrors, NameTheLineAndWhatIsWrong) {
  EXPECT_EQ(setup_error("both", cloth("[pin]\ncorners = [\"top-left\"]\n[[handle]]\nname = "
                                      "\"grip\"\nselect = \"top\"\n")),
            "11: the vertex at (0, 0, 1) is held by both [pin] and [[handle]] 'grip': a vertex can "
            "follow one prescribed motion only");
  EXPECT_EQ(setup_error("empty", cloth("[[load]]\nselect = { sphere = { center = [5, 5, 5], "
                                       "radius = 0.1 } }\nforce = [1, 0, 0]\n")),
            "10: [[load]] 'load1': the selection (sphere) holds no vertex");
  EXPECT_EQ(setup_error("nogroup", cloth("[[handle]]\nselect = { group = 2 }\n")),
            "10: [[handle]] 'handle1': the selection (group 2) holds no vertex (the mesh has no "
            "physical groups: Gmsh physical tags, Medit references or VTU cell data)");
  EXPECT_EQ(setup_error("far", cloth("[[notch]]\nfrom = [3, 0, 0]\nto = [4, 0, 0]\n")),
            "9: the notch crosses no inner edge of the mesh: check 'from' and 'to' against the "
            "mesh's extent");
  EXPECT_EQ(setup_error("vertex", cloth("[[handle]]\nselect = { vertices = [400] }\n")),
            "10: [[handle]] 'handle1': vertex 400 is not a point of the mesh (points are numbered "
            "from 0)");
}

// A minimal GIF decoder (LZW, variable width): enough to check that what the
// encoder wrote decodes to the palette indices of the image.
std::vector<std::uint8_t> decode_first_frame(const std::vector<std::uint8_t>& gif, int& w, int& h) {
  std::size_t k = 13 + 3 * 256 + 19 + 8;  // header, palette, loop extension, control extension
  EXPECT_EQ(gif[k], 0x2c);
  w = gif[k + 5] | (gif[k + 6] << 8);
  h = gif[k + 7] | (gif[k + 8] << 8);
  k += 10;
  const int min_size = gif[k++];
  std::vector<std::uint8_t> data;
  while (gif[k] != 0) {
    const int n = gif[k++];
    data.insert(data.end(), gif.begin() + static_cast<long>(k),
                gif.begin() + static_cast<long>(k) + n);
    k += static_cast<std::size_t>(n);
  }
  const int clear = 1 << min_size, end = clear + 1;
  std::vector<std::vector<std::uint8_t>> table;
  auto reset = [&] {
    table.assign(static_cast<std::size_t>(end + 1), {});
    for (int i = 0; i < clear; ++i)
      table[static_cast<std::size_t>(i)] = {static_cast<std::uint8_t>(i)};
  };
  reset();
  int width = min_size + 1;
  std::size_t bit = 0;
  std::vector<std::uint8_t> out;
  int previous = -1;
  while (bit + static_cast<std::size_t>(width) <= 8 * data.size()) {
    int code = 0;
    for (int b = 0; b < width; ++b, ++bit)
      code |= ((data[bit / 8] >> (bit % 8)) & 1) << b;
    if (code == clear) {
      reset();
      width = min_size + 1;
      previous = -1;
      continue;
    }
    if (code == end) break;
    std::vector<std::uint8_t> entry;
    if (code < static_cast<int>(table.size())) {
      entry = table[static_cast<std::size_t>(code)];
    } else {
      entry = table[static_cast<std::size_t>(previous)];
      entry.push_back(entry[0]);
    }
    if (previous >= 0 && table.size() < 4096) {
      auto grown = table[static_cast<std::size_t>(previous)];
      grown.push_back(entry[0]);
      table.push_back(grown);
    }
    if (static_cast<int>(table.size()) == (1 << width) && width < 12) ++width;
    out.insert(out.end(), entry.begin(), entry.end());
    previous = code;
  }
  return out;
}

TEST(Gif, FramesDecodeToTheirPaletteColours) {
  Image image;
  image.width = 97;
  image.height = 61;
  image.rgb.resize(3 * 97 * 61);
  for (std::size_t i = 0; i < image.rgb.size(); ++i)
    image.rgb[i] = static_cast<std::uint8_t>((i * 37 + (i / 291) * 11) % 256);
  const auto gif = encode_gif({&image, &image}, 50);
  ASSERT_GT(gif.size(), 800u);
  EXPECT_EQ(std::string(gif.begin(), gif.begin() + 6), "GIF89a");
  EXPECT_EQ(gif.back(), 0x3b);
  int w = 0, h = 0;
  const auto indices = decode_first_frame(gif, w, h);
  EXPECT_EQ(w, 97);
  EXPECT_EQ(h, 61);
  ASSERT_EQ(indices.size(), 97u * 61u);
  for (std::size_t p = 0; p < indices.size(); ++p) {
    ASSERT_EQ(indices[p],
              gif_palette_index(image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]))
        << "pixel " << p;
  }
}

}  // namespace
}  // namespace rift::experiment_test
