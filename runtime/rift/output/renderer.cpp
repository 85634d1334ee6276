#include "rift/output/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rift {

namespace {

Colour scale(const Colour& c, float s) {
  return {c[0] * s, c[1] * s, c[2] * s};
}
Colour mix(const Colour& a, const Colour& b, float t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

}  // namespace

Renderer::Renderer(const RenderOptions& options) : options_(options) {
  if (options_.width < 1 || options_.height < 1 || options_.width > 16384 ||
      options_.height > 16384) {
    throw std::invalid_argument("image size must be between 1x1 and 16384x16384");
  }
  if (options_.supersample < 1 || options_.supersample > 4) {
    throw std::invalid_argument("supersample must be 1, 2, 3 or 4");
  }
  w_ = options_.width * options_.supersample;
  h_ = options_.height * options_.supersample;
}

Camera Renderer::frame_camera(const FrameMesh& frame, const CameraView& view) const {
  return Camera::framing(frame.points, static_cast<Real>(options_.width) / options_.height, view);
}

const Image& Renderer::render(const FrameMesh& frame, const Camera& camera,
                              const FrameMesh* scenery) {
  const std::size_t samples = static_cast<std::size_t>(w_) * static_cast<std::size_t>(h_);
  colour_.resize(3 * samples);
  for (std::size_t k = 0; k < samples; ++k) {
    colour_[3 * k] = options_.background[0];
    colour_[3 * k + 1] = options_.background[1];
    colour_[3 * k + 2] = options_.background[2];
  }
  depth_.assign(samples, 0.0f);
  projected_.resize(frame.points.size());
  for (std::size_t p = 0; p < frame.points.size(); ++p)
    projected_[p] = camera.project(frame.points[p], w_, h_);
  // Key light from above left of the camera, fill light from the right;
  // faces are lit on both sides.
  light_ = (-camera.forward() + 0.55 * camera.up() - 0.35 * camera.right()).normalized();
  fill_ = (-0.6 * camera.forward() - 0.2 * camera.up() + camera.right()).normalized();
  for (std::size_t f = 0; f < frame.face_count(); ++f)
    draw_face(frame, f, camera, false);
  if (scenery) {
    projected_.resize(scenery->points.size());
    for (std::size_t p = 0; p < scenery->points.size(); ++p)
      projected_[p] = camera.project(scenery->points[p], w_, h_);
    for (std::size_t f = 0; f < scenery->face_count(); ++f)
      draw_face(*scenery, f, camera, true);
  }
  resolve();
  return image_;
}

void Renderer::draw_face(const FrameMesh& frame, std::size_t f, const Camera& camera,
                         bool scenery) {
  const std::uint32_t begin = frame.face_offsets[f];
  const std::uint32_t end = frame.face_offsets[f + 1];
  const std::uint32_t* ids = frame.face_vertices.data();
  const Real near = 1e-9;
  Vec3 normal = Vec3::Zero();
  Vec3 centre = Vec3::Zero();
  for (std::uint32_t k = begin; k < end; ++k) {
    const ScreenPoint& s = projected_[ids[k]];
    // Behind the camera or not a number (a blown-up simulation): not drawn.
    if (!(s.depth > near) || !std::isfinite(s.x) || !std::isfinite(s.y)) return;
    const Vec3& a = frame.points[ids[k]];
    const Vec3& b = frame.points[ids[k + 1 < end ? k + 1 : begin]];
    normal += a.cross(b);
    centre += a;
  }
  centre /= static_cast<Real>(end - begin);
  const Real length = normal.norm();
  if (length <= 0) return;
  normal /= length;
  const bool facing = normal.dot(camera.eye() - centre) >= 0;
  if (!facing) normal = -normal;

  Colour base = facing || frame.dimension == 3 ? options_.front : options_.back;
  const std::uint32_t element = frame.face_element[f];
  if (scenery) {
    base = options_.scenery;
  } else if (frame.face_torn[f]) {
    base = options_.torn;
  } else if (element != FrameMesh::kNoElement && frame.torn[element]) {
    base = mix(base, options_.torn, 0.45f);
  }
  const float light = 0.42f + 0.5f * static_cast<float>(std::max(Real(0), normal.dot(light_))) +
                      0.18f * static_cast<float>(std::max(Real(0), normal.dot(fill_)));
  const Colour shaded = scale(base, light);

  strokes_.clear();
  if (options_.edges && !scenery) {
    const Real ss = options_.supersample;
    for (std::uint32_t k = begin; k < end; ++k) {
      const ScreenPoint& a = projected_[ids[k]];
      const ScreenPoint& b = projected_[ids[k + 1 < end ? k + 1 : begin]];
      const EdgeKind kind = frame.face_edge_kind[k];
      const Real span = std::hypot(b.x - a.x, b.y - a.y);
      if (span <= 0) continue;
      EdgeStroke s{a.x,
                   a.y,
                   (b.x - a.x) / span,
                   (b.y - a.y) / span,
                   span,
                   0.5 * options_.edge_width * ss,
                   scale(shaded, 0.45f),
                   0.85f};
      if (kind == EdgeKind::kBoundary) {
        s.colour = scale(shaded, 0.3f);
        s.half_width *= 1.3;
        s.strength = 1.0f;
      } else if (kind == EdgeKind::kTear) {
        s.colour = options_.tear_edge;
        s.half_width = 0.5 * options_.tear_width * ss;
        s.strength = 1.0f;
      }
      strokes_.push_back(s);
    }
    // Tears last, so that they stay on top where strokes cross.
    std::stable_partition(strokes_.begin(), strokes_.end(),
                          [&](const EdgeStroke& s) { return s.strength < 1.0f; });
  }
  for (std::uint32_t k = begin + 1; k + 1 < end; ++k) {
    fill_triangle(projected_[ids[begin]], projected_[ids[k]], projected_[ids[k + 1]], shaded);
  }
}

void Renderer::fill_triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c,
                             const Colour& colour) {
  const Real area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (std::abs(area) < 1e-12) return;
  // Clamp in floating point first: far-off or non-finite corners must not
  // overflow the integer conversion.
  const auto clamp_to = [](Real v, int hi) {
    return static_cast<int>(std::clamp(v, Real(0), static_cast<Real>(hi)));
  };
  const Real min_x = std::floor(std::min({a.x, b.x, c.x}));
  const Real max_x = std::ceil(std::max({a.x, b.x, c.x}));
  const Real min_y = std::floor(std::min({a.y, b.y, c.y}));
  const Real max_y = std::ceil(std::max({a.y, b.y, c.y}));
  if (!(max_x >= 0 && max_y >= 0 && min_x < w_ && min_y < h_)) return;  // also NaN
  const int x0 = clamp_to(min_x, w_ - 1);
  const int x1 = clamp_to(max_x, w_ - 1);
  const int y0 = clamp_to(min_y, h_ - 1);
  const int y1 = clamp_to(max_y, h_ - 1);
  const Real inv_area = 1.0 / area;
  // 1/depth is linear in screen space under perspective.
  const Real za = 1.0 / a.depth;
  const Real zb = 1.0 / b.depth;
  const Real zc = 1.0 / c.depth;
  // Barycentric weights are affine in the sample position: step them along x.
  const Real dwa = (b.y - c.y) * inv_area;
  const Real dwb = (c.y - a.y) * inv_area;
  for (int y = y0; y <= y1; ++y) {
    const Real py = y + 0.5;
    const Real px0 = x0 + 0.5;
    Real wa = ((b.x - px0) * (c.y - py) - (b.y - py) * (c.x - px0)) * inv_area;
    Real wb = ((c.x - px0) * (a.y - py) - (c.y - py) * (a.x - px0)) * inv_area;
    bool entered = false;
    for (int x = x0; x <= x1; ++x, wa += dwa, wb += dwb) {
      const Real px = x + 0.5;
      const Real wc = 1.0 - wa - wb;
      if (wa < 0 || wb < 0 || wc < 0) {
        if (entered) break;  // the samples of a triangle's row are one run
        continue;
      }
      entered = true;
      const std::size_t k =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(x);
      const auto inv_depth = static_cast<float>(wa * za + wb * zb + wc * zc);
      if (inv_depth <= depth_[k]) continue;
      depth_[k] = inv_depth;
      Colour c2 = colour;
      for (const EdgeStroke& s : strokes_) {
        // Distance to the segment: across the line first, which rejects most
        // samples without a square root.
        const Real rx = px - s.ax;
        const Real ry = py - s.ay;
        const Real across = std::abs(rx * s.uy - ry * s.ux);
        const Real reach = s.half_width + 0.5;
        if (across >= reach) continue;
        const Real along = rx * s.ux + ry * s.uy;
        Real d = across;
        if (along < 0 || along > s.length) {
          const Real beyond = along < 0 ? -along : along - s.length;
          d = std::sqrt(across * across + beyond * beyond);
        }
        const Real cover = std::min(reach - d, Real(1));
        if (cover > 0) c2 = mix(c2, s.colour, static_cast<float>(cover) * s.strength);
      }
      colour_[3 * k] = c2[0];
      colour_[3 * k + 1] = c2[1];
      colour_[3 * k + 2] = c2[2];
    }
  }
}

void Renderer::resolve() {
  const int ss = options_.supersample;
  image_.width = options_.width;
  image_.height = options_.height;
  image_.rgb.resize(3 * static_cast<std::size_t>(image_.width) *
                    static_cast<std::size_t>(image_.height));
  const float norm = 255.0f / static_cast<float>(ss * ss);
  std::size_t out = 0;
  for (int y = 0; y < image_.height; ++y) {
    for (int x = 0; x < image_.width; ++x) {
      float sum[3] = {0, 0, 0};
      for (int sy = 0; sy < ss; ++sy) {
        const std::size_t row =
            static_cast<std::size_t>(y * ss + sy) * static_cast<std::size_t>(w_);
        for (int sx = 0; sx < ss; ++sx) {
          const std::size_t k = 3 * (row + static_cast<std::size_t>(x * ss + sx));
          sum[0] += colour_[k];
          sum[1] += colour_[k + 1];
          sum[2] += colour_[k + 2];
        }
      }
      for (float s : sum)
        image_.rgb[out++] = static_cast<std::uint8_t>(std::clamp(s * norm + 0.5f, 0.0f, 255.0f));
    }
  }
}

}  // namespace rift
