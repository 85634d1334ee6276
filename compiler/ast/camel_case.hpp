// The CamelCase form of a rule-language name, from which the generated C++
// class names are made (emit/names.hpp) and whose clashes the checks report
// (check/kernels.hpp): one definition for both.
#pragma once

#include <string>
#include <string_view>

namespace rift::ast {

/// "global_edge" -> "GlobalEdge" (runs of underscores are kept after the first).
inline std::string camel_case(std::string_view name) {
  std::string out;
  bool upper = true;
  for (char c : name) {
    if (c == '_') {
      if (upper) out += '_';  // keep runs of underscores: names stay distinct
      upper = true;
      continue;
    }
    out += upper && c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
    upper = false;
  }
  return out;
}

}  // namespace rift::ast
