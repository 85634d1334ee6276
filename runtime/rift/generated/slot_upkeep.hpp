// Embedding slots after a rule's rewrite (§4.1 of the paper): once a rewrite
// has set its links, every embedding orbit touching the rewritten darts gets
// one slot. Orbits that merged combine their values with the column's merge
// policy, an orbit split from another keeps a copy of the value, a new orbit
// gets the defaults. GMap::sew and GMap::unsew keep slots the same way for a
// single link; a rule changes many links at once, then calls this.
#pragma once

#include <cstddef>
#include <vector>

#include "rift/generated/scratch.hpp"
#include "rift/gmap/gmap.hpp"

namespace rift::generated {

/// What a rewrite changed, as riftc knows it from the rule: the dimensions
/// whose links it set or removed, and whether it created or deleted darts.
/// An attachment whose orbit has none of those dimensions keeps every orbit
/// as it was (the same darts, hence one slot each) unless darts came or went:
/// the upkeep skips it. The default assumes everything changed.
struct RewriteChanges {
  Orbit relinked = Orbit::from_mask(0xFF);
  bool darts_created_or_deleted = true;
  bool may_change(Orbit o) const {
    return darts_created_or_deleted || (o.mask() & relinked.mask()) != 0;
  }
};

/// Gives every embedding orbit of every attachment that contains one of
/// darts[0 .. count) one slot. Darts whose slot changes are appended to
/// `touched` when given (the region to re-match).
void update_embedding_slots(GMap& g, const Dart* darts, std::size_t count, Scratch& s,
                            std::vector<Dart>* touched, RewriteChanges changes = {});

}  // namespace rift::generated
