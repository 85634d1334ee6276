// The loads of a scene: a force on a group of vertices (a total spread by
// mass, or the same force on each vertex), optionally ramped up linearly; a
// uniform acceleration field; a linear air drag on the faces of a surface.
#pragma once

#include <memory>
#include <vector>

#include "rift/sim/external_force.hpp"
#include "rift/sim/vertex_groups.hpp"

namespace rift {

struct LoadSpec {
  std::string name = "load";
  int group = -1;                    ///< -1: every vertex
  Vec3 force = Vec3::Zero();         ///< N: total (by mass) or per vertex
  bool per_vertex = false;           ///< the same force on each vertex
  Vec3 acceleration = Vec3::Zero();  ///< m/s^2, times each vertex's mass
  Real start = 0;                    ///< s: nothing before
  Real ramp = 0;                     ///< s: from 0 to full over this long (0: at once)
};

/// A force and/or an acceleration on a group of vertices.
class GroupLoad : public ExternalForce {
 public:
  GroupLoad(LoadSpec spec, std::shared_ptr<const VertexGroups> groups)
      : spec_(std::move(spec)), groups_(std::move(groups)) {}
  const std::string& name() const override { return spec_.name; }
  void add_forces(const GMap& map, const ExternalInput& in, Vec3* f) override;
  /// The factor of the full load at time t (ramp and start).
  Real factor(Real t) const;

 private:
  LoadSpec spec_;
  std::shared_ptr<const VertexGroups> groups_;
};

/// Air drag on every face of a 2D surface: each face loses
/// c A ((v_face - wind) . n) n, shared among its corners. Only the normal
/// component: a sheet moving in its own plane meets no resistance.
class SurfaceDrag : public ExternalForce {
 public:
  SurfaceDrag(Real coefficient, Vec3 wind) : coefficient_(coefficient), wind_(wind) {}
  const std::string& name() const override { return name_; }
  void add_forces(const GMap& map, const ExternalInput& in, Vec3* f) override;

 private:
  std::string name_ = "drag";
  Real coefficient_;  // N s / m^3
  Vec3 wind_;
  std::vector<Slot> corners_;
};

}  // namespace rift
