// How riftc writes an orbit in messages and generated comments: "<0,2>".
#pragma once

#include <string>
#include <vector>

namespace rift::ast {

inline std::string orbit_text(const std::vector<int>& dims) {
  std::string out = "<";
  for (std::size_t k = 0; k < dims.size(); ++k) {
    if (k) out += ',';
    out += std::to_string(dims[k]);
  }
  return out + ">";
}

}  // namespace rift::ast
