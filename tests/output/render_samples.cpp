// Renders the sample pictures of docs/outputs.md and the ones used to judge
// the renderer by eye: rift_output_samples OUTPUT_FOLDER.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/output/frame_mesh.hpp"
#include "rift/output/png_writer.hpp"
#include "rift/output/renderer.hpp"

namespace {

using namespace rift;

void bend(GMap& map) {
  auto position = map.embedding<Vec3>("position");
  for (Vec3& p : position.values()) {
    const Real angle = (p.x() - 0.5) * 2.2;
    p = Vec3(0.8 * std::sin(angle), p.y(), 0.8 * (std::cos(angle) - 1.0) + 0.15 * p.y() * p.y());
  }
}

// Cuts the cloth along x = 0.5 from y = 0 to y = `length` and opens the cut a
// little, as a tear would once the pieces move apart.
void tear_cloth(GMap& map, Real length) {
  auto position = map.embedding<Vec3>("position");
  map.for_each_dart([&](Dart d) {
    if (map.is_free(d, 2)) return;
    const Vec3 a = position[d];
    const Vec3 b = position[map.alpha(d, 0)];
    if (std::abs(a.x() - 0.5) < 1e-9 && std::abs(b.x() - 0.5) < 1e-9 &&
        std::max(a.y(), b.y()) <= length + 1e-9) {
      map.unsew(d, 2);
    }
  });
  // Each vertex orbit on the cut moves toward the side of its faces.
  map.for_each_cell(vertex_orbit(2), [&](Dart d) {
    const Vec3 p = position[d];
    if (std::abs(p.x() - 0.5) > 1e-9 || p.y() >= length - 1e-9) return;
    Real side = 0;
    map.for_each_in_orbit(d, vertex_orbit(2),
                          [&](Dart x) { side += position[map.alpha(x, 0)].x() - 0.5; });
    const Real opening = 0.035 * (1.0 - p.y() / length);
    position[d] = p + Vec3(side > 0 ? opening : -opening, 0, 0);
  });
}

void render(GMap& map, const std::vector<std::uint8_t>& boundary, const std::filesystem::path& path,
            const RenderOptions& look = {}) {
  FrameOptions options;
  options.original_boundary = boundary;
  const FrameMesh frame = extract_frame_mesh(map, options);
  Renderer renderer(look);
  write_png(renderer.render(frame, renderer.frame_camera(frame)), path);
  std::printf("%s: %zu points, %zu elements, %zu torn\n", path.c_str(), frame.point_count(),
              frame.element_count(), frame.torn_count());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: rift_output_samples OUTPUT_FOLDER\n");
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    {
      GMap map = assemble_gmap(make_grid(GridKind::Quad, 10, 10));
      const auto boundary = record_boundary_darts(map);
      bend(map);
      render(map, boundary, dir / "cloth.png");
    }
    {
      GMap map = assemble_gmap(make_grid(GridKind::Quad, 10, 10));
      const auto boundary = record_boundary_darts(map);
      tear_cloth(map, 0.6);
      bend(map);
      render(map, boundary, dir / "cloth_torn.png");
      // The small picture of docs/outputs.md.
      render(map, boundary, dir / "outputs_torn_cloth.png",
             RenderOptions{.width = 480, .height = 360});
    }
    {
      GMap map = assemble_gmap(make_block(BlockKind::Tet, 3, 3, 3));
      const auto boundary = record_boundary_darts(map);
      render(map, boundary, dir / "block_tet.png");
      // Remove the tetrahedra of the corner cube at the top: unsew, then delete.
      auto position = map.embedding<Vec3>("position");
      std::vector<Dart> doomed;
      map.for_each_cell(Orbit{0, 1, 2}, [&](Dart d) {
        Vec3 centre = Vec3::Zero();
        int n = 0;
        map.for_each_in_orbit(d, Orbit{0, 1, 2}, [&](Dart x) {
          centre += position[x];
          ++n;
        });
        centre /= n;
        if (centre.x() > 2.0 / 3 && centre.y() > 2.0 / 3 && centre.z() > 2.0 / 3) {
          map.for_each_in_orbit(d, Orbit{0, 1, 2}, [&](Dart x) { doomed.push_back(x); });
        }
      });
      for (Dart d : doomed) {
        if (!map.is_free(d, 3)) map.unsew(d, 3);
      }
      for (Dart d : doomed)
        map.delete_dart(d);
      render(map, boundary, dir / "block_tet_removed.png");
    }
    {
      GMap map = assemble_gmap(make_block(BlockKind::Hex, 4, 4, 4));
      const auto boundary = record_boundary_darts(map);
      auto position = map.embedding<Vec3>("position");
      std::vector<Dart> cut;
      map.for_each_cell(Orbit{0, 1, 3}, [&](Dart d) {
        if (map.is_free(d, 3)) return;
        bool on_plane = true;
        bool upper = true;
        map.for_each_in_orbit(d, Orbit{0, 1}, [&](Dart x) {
          on_plane = on_plane && std::abs(position[x].x() - 0.5) < 1e-9;
          upper = upper && position[x].y() > 0.5 - 1e-9;
        });
        if (on_plane && upper) cut.push_back(d);
      });
      for (Dart d : cut)
        map.unsew(d, 3);
      // Open the crack: each side's vertex orbits on the plane move apart.
      map.for_each_cell(vertex_orbit(3), [&](Dart d) {
        const Vec3 p = position[d];
        if (std::abs(p.x() - 0.5) > 1e-9 || p.y() <= 0.5 + 1e-9) return;
        Real side = 0;
        map.for_each_in_orbit(d, vertex_orbit(3),
                              [&](Dart x) { side += position[map.alpha(x, 0)].x() - 0.5; });
        const Real opening = 0.08 * (p.y() - 0.5);
        position[d] = p + Vec3(side > 0 ? opening : -opening, 0, 0);
      });
      render(map, boundary, dir / "block_hex_crack.png");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
