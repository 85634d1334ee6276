// What lowering reads from resolve/ and check/, declared only: the headers
// of lower/ name these types in the signatures of the lowering functions, and
// emit/, which includes those headers for the plans, sees nothing of check/
// or resolve/ (the test riftc.EmitDependsOnPlansOnly checks it). The sources of
// lower/ include the definitions.
#pragma once

namespace rift::check {
struct RuleGraph;
struct CheckedRule;
struct CheckedInteraction;
class ExprTypes;
}  // namespace rift::check

namespace rift::resolve {
struct Symbols;
}  // namespace rift::resolve
