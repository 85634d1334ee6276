// The conditions without which a criterion's measure cannot pass.
//
// The paper's criteria guard a degenerate case with a literal:
// `measure (if l > 0.0 then |f . n| / l else 0.0) > threshold`, threshold a
// parameter declared `> 0`. Where the condition fails the measure is 0, and
// 0 > threshold is false for every threshold a scene may give: the cell
// cannot be a candidate. Each conjunct of such a condition is then a guard:
// collect() tests it as soon as the lets it reads are computed and leaves
// the cell when it fails, before the lets only the rest of the measure
// reads (the atomic edge criterion tests its first face's contraction
// before it sums the second face's forces). The guards are those of `and`
// and `if` in the order C++ evaluates them, so a guard runs only where the
// ones before it hold, as the measure's own short-circuits did: the values
// computed and the candidates found are the same, only fewer lets are
// computed where a cell fails.
#pragma once

#include <vector>

#include "ast/decl.hpp"
#include "ir/body.hpp"

namespace rift::lower {

/// The guards of `measure op threshold` (op: ">", ">=", "<" or "<="), in
/// the order to test them; empty where the measure has none. `params` are
/// the criterion's, whose bounds say which thresholds a scene may give.
/// Guards are nodes of body.graph: a conjunct as written, or a new node
/// where a cheaper test is equal (`norm(v) > 0` is tested as
/// `dot(v, v) > 0`, without the square root).
std::vector<ir::ExprId> measure_guards(ir::Body& body, ir::ExprId measure, ir::ExprId threshold,
                                       const std::string& op,
                                       const std::vector<ast::Param>& params);

}  // namespace rift::lower
