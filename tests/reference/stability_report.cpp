// rift_reference_stability: the figures of docs/physics.md, "Time step".
// For each Table 2 mesh of the paper's cloth: the spectrum of the linearised
// hanging cloth (damped and undamped), RK4's limit on dt, and runs at 1, 2, 4
// and 8 times the chosen dt from a start perturbed by 1 mm.
#include <cstdio>

#include "linear_stability.hpp"
#include "stability.hpp"

using namespace rift;
using namespace rift::reference;

int main() {
  const char* names[] = {"quads", "triangles", "mixed"};
  std::printf("dt = %g s\n\n", kPaperDt);
  std::printf("%-10s %-9s %10s %10s %10s %6s %12s %12s\n", "mesh", "damping", "max|l|", "max Im l",
              "min Re l", "grow", "RK4 dt max", "|R(l dt)|max");
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    for (bool damped : {true, false}) {
      // Both linearised at the damped cloth's rest shape.
      ClothParameters p;
      if (!damped) p.stretch_c = p.shear_c = p.bend_c = 0;
      ReferenceCloth cloth = paper_cloth(kind, 10, 10, p);
      cloth.positions() = settled_cloth(kind).positions();
      const Spectrum s = linear_spectrum(cloth);
      std::printf("%-10s %-9s %10.1f %10.1f %10.1f %6zu %12.3e %12.9f\n",
                  names[static_cast<int>(kind)], damped ? "0.1" : "none", s.max_modulus,
                  s.max_imaginary, s.most_negative_real, s.growing_modes, s.rk4_limit(),
                  s.max_amplification(kPaperDt));
    }
  }
  std::printf("\nruns of 2 s from the hung cloth perturbed by 1 mm (blow-up time or 'stable')\n");
  std::printf("%-10s", "mesh");
  for (int multiple : {1, 2, 4, 8})
    std::printf(" %12s", (std::to_string(multiple) + " x dt").c_str());
  std::printf("\n");
  for (GridKind kind : {GridKind::Quad, GridKind::Tri, GridKind::Mix}) {
    std::printf("%-10s", names[static_cast<int>(kind)]);
    for (int multiple : {1, 2, 4, 8}) {
      const auto t = blow_up_time(kind, multiple * kPaperDt);
      if (t) {
        std::printf(" %10.3f s", *t);
      } else {
        std::printf(" %12s", "stable");
      }
    }
    std::printf("\n");
  }
  return 0;
}
