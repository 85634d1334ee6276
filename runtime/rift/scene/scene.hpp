// A scene: the mesh, its interactions and criteria with their parameters,
// the integrator and time step, masses, pins and outputs. Read from TOML by
// read_scene; docs/scenes.md is the reference of every key.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rift/embed/value.hpp"
#include "rift/pack/catalog.hpp"
#include "rift/pack/component_use.hpp"
#include "rift/scene/selection.hpp"
#include "rift/sim/handles.hpp"
#include "rift/sim/implicit_euler.hpp"
#include "rift/sim/integrator.hpp"
#include "rift/sim/loads.hpp"
#include "rift/sim/obstacles.hpp"

namespace rift {

struct SceneMesh {
  std::string source;  ///< generator spelling, or a file path resolved against the scene's folder
  Vec3 scale = Vec3::Ones();
  Vec3 rotate_degrees = Vec3::Zero();  ///< about x, then y, then z, after scaling
  Vec3 translate = Vec3::Zero();
};

struct ScenePins {
  int line = 0;                        ///< line of the [pin] table, for messages
  std::vector<std::string> corners;    ///< "top-left", "top-right", "bottom-left", "bottom-right"
  std::vector<std::int64_t> vertices;  ///< point indices of the source mesh (0-based)
  std::vector<std::pair<Vec3, Vec3>> boxes;  ///< every vertex inside [min, max]
};

/// [[handle]]: a selection moved as the motion says ([pin] is a fixed one).
struct SceneHandle {
  int line = 0;
  Selection select;
  HandleMotion motion;
  bool pivot_given = false;  ///< else the centre of the selected vertices
};

/// [[load]]: a force and/or an acceleration on a selection.
struct SceneLoad {
  int line = 0;
  Selection select;  ///< default: every vertex
  LoadSpec spec;
};

/// [[initial_velocity]]: the velocity of a selection at t = 0.
struct SceneInitialVelocity {
  int line = 0;
  Selection select;
  Vec3 velocity = Vec3::Zero();
};

/// [[obstacle]].
struct SceneObstacle {
  int line = 0;
  Obstacle obstacle;
};

/// [[notch]]: a cut made before the first step, along the segment from ->
/// to (2D), or the parallelogram from, to, to + depth, from + depth (3D).
struct SceneNotch {
  int line = 0;
  Vec3 from = Vec3::Zero(), to = Vec3::Zero();
  Vec3 depth = Vec3::Zero();
};

/// [drag]: linear air drag on the faces of a surface.
struct SceneDrag {
  int line = 0;
  Real coefficient = 0;  ///< N s / m^3; 0: none
  Vec3 wind = Vec3::Zero();
};

enum class CameraMode { kFixed, kFollow, kFollowUnion };

struct SceneOutput {
  std::string dir;  ///< default: "out/<scene name>" next to the working dir
  int every = 10;   ///< a frame every `every` steps
  std::vector<std::string> formats{"vtu", "csv"};  ///< among vtu, obj, png, gif, csv
  CameraMode camera = CameraMode::kFixed;
  int gif_delay_ms = 80;   ///< between GIF frames
  int png_every = 0;       ///< a PNG every k-th frame (0: same as frames)
  bool vtu_ascii = false;  ///< vtu_encoding = "ascii"; default "binary" (appended raw)
  int width = 800, height = 600;
};

struct SceneTearing {
  int max_per_step = 0;  ///< 0: no cap
};

struct Scene {
  std::string path;  ///< the scene file
  std::string name;  ///< its stem
  SceneMesh mesh;
  IntegratorKind integrator = IntegratorKind::kRK4;
  Real dt = 1e-3;
  ImplicitSettings implicit;  ///< [implicit], for integrator = "implicit_euler"
  int implicit_line = 0;      ///< line of [implicit], 0 when absent
  std::int64_t steps = 1000;
  Vec3 gravity = Vec3(0, 0, -9.81);
  /// Safety factor of the divergence check (rift/sim/divergence.hpp); 0: off.
  Real divergence_factor = 100;
  std::optional<Real> total_mass;
  std::optional<Real> density;
  ScenePins pins;
  std::vector<SceneHandle> handles;
  std::vector<SceneLoad> loads;
  std::vector<SceneInitialVelocity> initial_velocities;
  std::vector<SceneObstacle> obstacles;
  std::vector<SceneNotch> notches;
  SceneDrag drag;
  std::vector<ComponentUse> interactions;
  std::vector<ComponentUse> criteria;
  SceneTearing tearing;
  SceneOutput output;
};

/// Reads and validates a scene. Throws InputError naming the file, the line
/// and what is expected: unknown keys (with the closest known key), values
/// of the wrong type or range, unknown interactions or criteria, missing
/// parameters, a mesh file that does not exist.
Scene read_scene(const std::string& path, const Catalog& catalog);

}  // namespace rift
