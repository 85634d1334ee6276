// Rendering of the expression IR (ir/expr.hpp) as C++ over Eigen fixed-size
// types. Rendering decides nothing: every type, overload and conversion is in
// the IR. Operands are left as Eigen expressions inside one C++ expression
// (they live until its end); a value is materialised where it is named (a
// let, a force) and where the two branches of an `if` must agree on a type.
#pragma once

#include <functional>
#include <string>

#include "ir/expr.hpp"

namespace rift::emit {

struct RenderContext {
  /// The C++ expression of a dart place (pattern node or fold variable).
  std::function<std::string(int node)> dart;
  /// Position, Velocity and Read nodes; when empty, reads are `e_NAME[dart]`.
  std::function<std::string(const ir::Node& read)> read;
  std::string args = "args";      // the declaration's parameters
  std::string params = "params";  // the pack's parameters
  std::string map = "g";          // the rift::GMap
};

std::string render(const ir::Graph& g, ir::ExprId id, const RenderContext& ctx);

/// A real literal as C++ ("0.5", "2.0").
std::string real_literal(double v);

}  // namespace rift::emit
