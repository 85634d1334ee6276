#include "rift/embed/value.hpp"

namespace rift {

std::string_view to_string(ValueType type) {
  switch (type) {
    case ValueType::kReal:
      return "real";
    case ValueType::kInt:
      return "int";
    case ValueType::kBool:
      return "bool";
    case ValueType::kVec3:
      return "vec3";
    case ValueType::kMat3:
      return "mat3";
  }
  return "?";
}

std::string_view to_string(MergePolicy policy) {
  switch (policy) {
    case MergePolicy::kKeepFirst:
      return "keep";
    case MergePolicy::kSum:
      return "sum";
    case MergePolicy::kMean:
      return "mean";
    case MergePolicy::kRefuse:
      return "refuse";
  }
  return "?";
}

std::optional<ValueType> parse_value_type(std::string_view name) {
  for (ValueType t :
       {ValueType::kReal, ValueType::kInt, ValueType::kBool, ValueType::kVec3, ValueType::kMat3}) {
    if (to_string(t) == name) return t;
  }
  return std::nullopt;
}

std::optional<MergePolicy> parse_merge_policy(std::string_view name) {
  for (MergePolicy p :
       {MergePolicy::kKeepFirst, MergePolicy::kSum, MergePolicy::kMean, MergePolicy::kRefuse}) {
    if (to_string(p) == name) return p;
  }
  return std::nullopt;
}

}  // namespace rift
