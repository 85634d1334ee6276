// How riftc writes an orbit in messages and generated comments: "<0,2>", and
// a node reached through links: "a@1@0".
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

/// Node `node` followed through the links `hops`: "a@1@0".
inline std::string path_text(const std::string& node, const std::vector<int>& hops) {
  std::string out = node;
  for (int h : hops) {
    out += '@';
    out += std::to_string(h);
  }
  return out;
}

}  // namespace rift::ast
