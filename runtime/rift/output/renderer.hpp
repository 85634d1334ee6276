// A small software rasteriser for frame previews: z-buffered, flat Lambert
// shaded faces, element edges drawn inside each face (so they are depth
// correct by construction), supersampled for smooth edges. Torn elements are
// tinted red and edges made by tearing are drawn thick and dark.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rift/output/camera.hpp"
#include "rift/output/frame_mesh.hpp"

namespace rift {

using Colour = std::array<float, 3>;  ///< linear 0..1 RGB

struct RenderOptions {
  int width = 800;
  int height = 600;
  int supersample = 2;    ///< samples per pixel along each axis (1 to 4)
  bool edges = true;      ///< draw element edges
  Real edge_width = 1.0;  ///< pixels of an element edge
  Real tear_width = 3.0;  ///< pixels of an edge made by tearing
  Colour background{1.0f, 1.0f, 1.0f};
  Colour front{0.62f, 0.76f, 0.93f};  ///< faces seen from their front (2D) or outside (3D)
  Colour back{0.80f, 0.80f, 0.74f};   ///< back faces of a surface
  Colour torn{0.88f, 0.16f, 0.12f};   ///< torn elements (2D), crack faces (3D)
  Colour tear_edge{0.18f, 0.0f, 0.0f};
  Colour scenery{0.56f, 0.56f, 0.60f};  ///< obstacles and other props
};

/// 8-bit RGB pixels, row by row from the top.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;

  std::array<std::uint8_t, 3> pixel(int x, int y) const {
    const std::size_t k = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                               static_cast<std::size_t>(x));
    return {rgb[k], rgb[k + 1], rgb[k + 2]};
  }
};

class Renderer {
 public:
  /// Throws std::invalid_argument for a size outside 1..16384 or a bad supersample.
  explicit Renderer(const RenderOptions& options = {});

  /// A camera that frames `frame` in this renderer's image; keep it for the
  /// following frames so that the view stays put.
  Camera frame_camera(const FrameMesh& frame, const CameraView& view = {}) const;

  /// Renders the boundary surface of `frame`, and the faces of `scenery`
  /// (obstacles: flat grey, no edges) when given; the image lives until the
  /// next call.
  const Image& render(const FrameMesh& frame, const Camera& camera,
                      const FrameMesh* scenery = nullptr);

  const RenderOptions& options() const { return options_; }

 private:
  struct EdgeStroke {
    Real ax, ay;      // start, supersampled pixels
    Real ux, uy;      // unit direction
    Real length;      // in supersampled pixels
    Real half_width;  // plus half a sample of antialiasing
    Colour colour;
    float strength;  // 1: replaces the face colour, < 1: blends
  };
  void draw_face(const FrameMesh& frame, std::size_t f, const Camera& camera, bool scenery);
  void fill_triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c,
                     const Colour& colour);
  void resolve();

  RenderOptions options_;
  int w_ = 0;  // supersampled size
  int h_ = 0;
  std::vector<float> colour_;  // 3 per sample
  std::vector<float> depth_;   // 1 / view depth per sample; 0 is empty
  std::vector<ScreenPoint> projected_;
  std::vector<EdgeStroke> strokes_;
  Vec3 light_ = Vec3::Zero();
  Vec3 fill_ = Vec3::Zero();
  Image image_;
};

}  // namespace rift
