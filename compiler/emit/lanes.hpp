// Which force bodies riftc also renders in lanes (rift/core/lanes.hpp): the
// body evaluated for kWidth consecutive matches at once, each lane computing
// exactly what the scalar evaluate() computes for its match.
//
// The lanes form covers the arithmetic of springs and other point-force laws:
// values of type real, vec3 and bool; reads of positions, velocities and
// real or vec3 columns through the match's slots; parameters; + - * / and
// negation; comparisons of reals; and, or, not; if-then-else (both branches
// computed, each lane keeps its own); a vec3's coordinate; and the built-ins
// sqrt, abs, min, max, clamp, real, vec3, dot, cross, norm, normalize and
// stop_gradient. A body with anything else (a mat3, an integer value, a
// transcendental function, a fold, a stored value) has only its scalar
// passes, unchanged.
#pragma once

#include "ir/body.hpp"

namespace rift::emit {

/// Whether the forces, lets and whens of `b` have a lanes form (see above).
/// A body without forces, or with `store` statements, has none.
bool renders_in_lanes(const ir::Body& b);

/// The C++ type of a lanes body's value of type t (real, vec3 or bool).
const char* lanes_type(ir::Type t);

}  // namespace rift::emit
