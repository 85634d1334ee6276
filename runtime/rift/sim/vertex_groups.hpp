// Named sets of vertices that survive tearing: a bit per group in an
// embedding on the vertex orbit, so that both halves of a split vertex stay
// in the groups of the vertex they came from. Loads use them.
#pragma once

#include <stdexcept>

#include "rift/gmap/gmap.hpp"

namespace rift {

class VertexGroups {
 public:
  static constexpr int kMaxGroups = 63;

  explicit VertexGroups(GMap& map) {
    const Orbit vertex = Orbit::cell(0, map.dimension());
    bits_ = map.embedding<std::int64_t>("groups");
    if (!bits_)
      bits_ = map.add_embedding<std::int64_t>("groups", vertex, MergePolicy::kKeepFirst, 0);
    if (bits_.orbit() != vertex) throw std::invalid_argument("'groups' must live on vertices");
  }

  /// A new, empty group; throws past kMaxGroups.
  int add_group() {
    if (count_ >= kMaxGroups) throw std::invalid_argument("too many vertex groups (at most 63)");
    return count_++;
  }
  void add(Dart d, int group) { bits_[d] |= std::int64_t(1) << group; }
  bool contains(Slot s, int group) const { return (bits_.values()[s] >> group) & 1; }
  int count() const { return count_; }

 private:
  Embedding<std::int64_t> bits_;
  int count_ = 0;
};

}  // namespace rift
