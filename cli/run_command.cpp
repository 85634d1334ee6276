// `rift run SCENE`: the simulation with its outputs, a progress bar and a
// summary. Frames already written stay readable whatever happens next.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "rift/core/interrupt.hpp"
#include "rift/core/parallel.hpp"
#include "rift/core/state_embeddings.hpp"
#include "rift/output/frame_outputs.hpp"
#include "rift/output/scenery.hpp"
#include "rift/scene/scene_setup.hpp"

namespace rift::cli {

namespace {

std::size_t count_elements(const GMap& map) {
  return map.count_cells(Orbit::all(map.dimension() - 1));
}

// Free edges (2D) or faces (3D): the boundary, which tearing lengthens.
std::size_t count_free_sides(const GMap& map) {
  const int n = map.dimension();
  std::size_t sides = 0;
  const Orbit side = n == 2 ? Orbit{0} : Orbit{0, 1};  // within one element
  map.for_each_cell(side, [&](Dart d) { sides += map.is_free(d, n) ? 1 : 0; });
  return sides;
}

}  // namespace

CLI::App* add_run_command(CLI::App& app, RunOptions& options) {
  CLI::App* cmd =
      app.add_subcommand("run", "Run a scene and write its frames (VTU/PVD, OBJ, PNG, CSV)");
  cmd->add_option("SCENE", options.scene, "The scene file (TOML); see docs/scenes.md")->required();
  cmd->add_option("--steps", options.steps, "Number of steps (default: the scene's)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--out", options.out, "Output folder (default: the scene's, out/<scene name>)");
  cmd->add_flag("--check", options.check,
                "Check the G-map's validity after every rewrite and stop at the first failure");
  cmd->add_flag("--quiet", options.quiet, "No progress bar and no summary");
  add_threads_option(*cmd, options.threads);
  return cmd;
}

int run_run(const RunOptions& options, const PackRegistry& packs) {
  set_thread_count(options.threads);
  const Scene scene = read_scene(options.scene, packs.catalog());
  SetupReport setup;
  std::unique_ptr<Simulation> sim = build_simulation(scene, packs, {options.check}, &setup);
  for (const std::string& warning : assembly_warnings(setup.assembly, sim->map().dimension()))
    fmt::print(stderr, "{}: warning: {}\n", scene.mesh.source, warning);
  for (const std::string& warning : setup.warnings)
    fmt::print(stderr, "{}: warning: {}\n", options.scene, warning);
  const std::int64_t steps = options.steps.value_or(scene.steps);

  OutputConfig config;
  config.directory = options.out.empty() ? scene.output.dir : options.out;
  config.name = scene.name;
  auto wants = [&](const char* f) {
    return std::find(scene.output.formats.begin(), scene.output.formats.end(), f) !=
           scene.output.formats.end();
  };
  config.vtu = wants("vtu");
  config.vtu_encoding = scene.output.vtu_ascii ? VtuEncoding::kAscii : VtuEncoding::kAppendedBinary;
  config.obj = wants("obj");
  config.png = wants("png");
  config.gif = wants("gif");
  config.gif_delay_ms = scene.output.gif_delay_ms;
  switch (scene.output.camera) {
    case CameraMode::kFixed:
      config.camera = OutputConfig::Camera::kFixed;
      break;
    case CameraMode::kFollow:
      config.camera = OutputConfig::Camera::kFollow;
      break;
    case CameraMode::kFollowUnion:
      config.camera = OutputConfig::Camera::kFollowUnion;
      break;
  }
  config.png_every = scene.output.png_every > 0 ? scene.output.png_every : 1;
  config.render.width = scene.output.width;
  config.render.height = scene.output.height;
  config.frame.element_id = std::string(state::kElementIndex);
  // Look at the object upright: "up" is against gravity, the eye in front,
  // a little to the right and above.
  // Without gravity, a sheet flat in the x-y plane is seen from above.
  GMap& body = sim->map();
  Vec3 body_lo = Vec3::Constant(INFINITY), body_hi = Vec3::Constant(-INFINITY);
  body.for_each_cell(Orbit::cell(0, body.dimension()), [&](Dart d) {
    body_lo = body_lo.cwiseMin(sim->position()[d]);
    body_hi = body_hi.cwiseMax(sim->position()[d]);
  });
  const Vec3 up =
      scene.gravity.norm() > 0 ? Vec3(-scene.gravity.normalized()) : default_up(body_lo, body_hi);
  int up_axis = 0;
  up.cwiseAbs().maxCoeff(&up_axis);
  config.view.up = up;
  const int front_axis = up_axis == 1 ? 2 : 1;  // z in front when y is up, else y
  const int side_axis = 3 - up_axis - front_axis;
  Vec3 direction = Vec3::Zero();
  direction[side_axis] = 0.45;
  direction[up_axis] = 0.35 * (up[up_axis] > 0 ? 1 : -1);
  direction[front_axis] = up_axis == 1 ? 1.0 : -1.0;
  if (scene.gravity.norm() == 0 && up_axis == 1) {
    // A flat sheet without gravity (a specimen on a test bench): almost
    // straight on, so that cracks in its plane show undistorted.
    direction = Vec3(0.12, 0.1, 1.0);
  }
  config.view.direction = direction;
  const std::string torn_column = sim->map().dimension() == 2 ? "torn_edges" : "torn_faces";
  if (wants("csv")) {
    config.csv_columns = {"step",          "time",     "kinetic_energy", "potential_energy",
                          "tears",         "vertices", "elements",       "step_ms",
                          "external_work", torn_column};
    if (const Handles* handles = sim->handles()) {
      for (std::size_t h = 0; h < handles->count(); ++h) {
        for (const char* axis : {"_fx", "_fy", "_fz"})
          config.csv_columns.push_back(handles->motion(static_cast<int>(h)).name + axis);
      }
    }
  }
  // Forces per vertex for the point data, refreshed before each frame.
  GMap& map = sim->map();
  const std::size_t free_at_start = count_free_sides(map);
  Embedding<Vec3> force = map.add_embedding<Vec3>("force", Orbit::cell(0, map.dimension()),
                                                  MergePolicy::kSum, Vec3::Zero());
  FrameOutputs outputs(config);

  const bool verbose = !options.quiet;
  if (verbose) {
    fmt::print(
        stderr,
        "rift: {} — {} vertices, {} elements, {} pinned, mass {:.4g} kg, {} steps of {} s ({})\n",
        scene.name, map.count_cells_of_dimension(0), count_elements(map), setup.pinned_vertices,
        setup.total_mass, steps, scene.dt, to_string(scene.integrator));
  }
  double step_ms = 0;
  std::vector<Vec3> scenery_points;
  std::vector<std::array<std::uint32_t, 3>> scenery_triangles;
  FrameMesh scenery;
  auto write_frame = [&] {
    force.values() = sim->internal_forces();
    force.values().resize(force.attachment().slot_capacity(), Vec3::Zero());
    const FrameMesh* props = nullptr;
    if (sim->contact()) {
      Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
      map.for_each_cell(Orbit::cell(0, map.dimension()), [&](Dart d) {
        lo = lo.cwiseMin(sim->position()[d]);
        hi = hi.cwiseMax(sim->position()[d]);
      });
      scenery_points.clear();
      scenery_triangles.clear();
      for (const Obstacle& o : sim->contact()->obstacles())
        tessellate(o, sim->time(), lo, hi, scenery_points, scenery_triangles);
      make_scenery(scenery_points, scenery_triangles, scenery);
      props = &scenery;
    }
    outputs.write_frame(map, sim->time(), props);
    if (!config.csv_columns.empty()) {
      std::vector<double> row{static_cast<double>(sim->steps_done()),
                              sim->time(),
                              sim->kinetic_energy(),
                              sim->potential_energy(),
                              static_cast<double>(sim->tears()),
                              static_cast<double>(map.count_cells_of_dimension(0)),
                              static_cast<double>(count_elements(map)),
                              step_ms,
                              sim->external_work(),
                              static_cast<double>(count_free_sides(map) - free_at_start)};
      if (const Handles* handles = sim->handles()) {
        const std::vector<Vec3>& reactions = sim->handle_reactions();
        for (std::size_t h = 0; h < handles->count(); ++h) {
          const Vec3 f = h < reactions.size() ? reactions[h] : Vec3::Zero();
          row.insert(row.end(), {f.x(), f.y(), f.z()});
        }
      }
      outputs.write_statistics(row);
    }
  };

  // Ctrl-C raises a flag that the step polls (rift/core/interrupt.hpp): a
  // frame being written is always finished, and a step stops part-way.
  InterruptHandler interrupt_handler;
  Progress progress(steps, verbose && Progress::stderr_is_terminal());
  const auto start = std::chrono::steady_clock::now();
  write_frame();
  std::string failure;
  std::int64_t done = 0;
  double total_step_ms = 0;
  bool interrupted = false, interrupted_mid_step = false;
  try {
    for (done = 0; done < steps && !interrupt_requested();) {
      const auto t0 = std::chrono::steady_clock::now();
      sim->step();
      step_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      total_step_ms += step_ms;
      ++done;
      if (done % scene.output.every == 0 || done == steps) write_frame();
      progress.update(done, fmt::format("step {}/{}  t={:.4g}s  tears={}", done, steps, sim->time(),
                                        sim->tears()));
    }
    interrupted = interrupt_requested();
    // The state after the last finished step, unless a frame already shows it.
    if (interrupted && done % scene.output.every != 0) write_frame();
  } catch (const Interrupted&) {
    // A step abandoned part-way is not a state worth a frame.
    interrupted = interrupted_mid_step = true;
  } catch (const SimulationError& e) {
    failure = e.what();
  }
  progress.finish();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (!failure.empty()) {
    fmt::print(stderr, "rift: error: {}\n", failure);
    fmt::print(stderr, "rift: the {} frames written before the failure are in {}\n",
               outputs.frames_written(), config.directory.string());
    return 1;
  }
  if (interrupted_mid_step && verbose) {
    fmt::print(stderr, "rift: interrupted during step {}; it was abandoned part-way\n", done + 1);
  }
  if (verbose) {
    fmt::print(stderr,
               "rift: {} {} steps ({:.4g} s simulated) in {} — {:.3f} ms/step, {} tears, {} "
               "vertices\n",
               interrupted ? "interrupted after" : "done:", done, sim->time(),
               format_duration(wall), done > 0 ? total_step_ms / static_cast<double>(done) : 0.0,
               sim->tears(), map.count_cells_of_dimension(0));
    fmt::print(stderr, "rift: {} frames in {}/ (open {}.pvd in ParaView{}{})\n",
               outputs.frames_written(), config.directory.string(), scene.name,
               config.png ? ", PNG renders frame_*.png" : "",
               config.csv_columns.empty() ? "" : fmt::format(", statistics {}.csv", scene.name));
  }
  return interrupted ? 130 : 0;
}

}  // namespace rift::cli
