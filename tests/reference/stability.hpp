// Shared by the stability test and report: settle the paper's cloth, and run
// it from a perturbed start to see whether a time step blows up.
#pragma once

#include <cmath>
#include <optional>

#include "paper_cloth.hpp"

namespace rift::reference {

/// Settles the hanging cloth (damped, RK4 at kPaperDt) for `seconds`.
inline ReferenceCloth settled_cloth(GridKind kind, const ClothParameters& params = {},
                                    Real seconds = 10) {
  ReferenceCloth cloth = paper_cloth(kind, 10, 10, params);
  const int steps = static_cast<int>(std::lround(seconds / kPaperDt));
  for (int s = 0; s < steps; ++s)
    cloth.step_rk4(kPaperDt);
  return cloth;
}

/// Runs the paper's cloth, hung and perturbed by 1 mm, for `seconds` with
/// step dt. Returns the time at which it blew up (a non-finite coordinate or
/// a vertex farther than 2 m from the origin), or nothing if it did not.
inline std::optional<Real> blow_up_time(GridKind kind, Real dt, Real seconds = 2) {
  ReferenceCloth cloth = paper_cloth(kind);
  jiggle(cloth, 1e-3, 1);
  const int steps = static_cast<int>(std::lround(seconds / dt));
  for (int s = 0; s < steps; ++s) {
    cloth.step_rk4(dt);
    for (const Vec3& x : cloth.positions()) {
      if (!x.allFinite() || x.norm() > 2) return cloth.time();
    }
  }
  return std::nullopt;
}

}  // namespace rift::reference
