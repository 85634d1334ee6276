// Which matches a re-match around touched darts must look at (issue 12: a
// tear costs what it touches).
//
// A match reads the darts of its pattern: each a word of links from its
// support dart (a node, or a node's dart read through hops). A match whose
// darts were touched (created, deleted, relinked or given another slot) must
// be matched again, and so must a new match that reads a touched dart. Both
// are found from the touched darts alone: on the path of links from the
// support dart s to a dart the match reads, take the first touched dart x;
// the links before it did not change, so x is word(s) for a prefix `word` of
// that path, and walking the word's links backwards from x (they are
// involutions) gives s. The prefixes of the paths to the darts a match reads
// are the paths to other darts it reads (the pattern reaches each node from
// an earlier one), so the words of those darts suffice.
//
// The re-match walks each support orbit it reaches whole, so a word's first
// links that stay in the support orbit (links of its dimensions) need not be
// walked: riftc leaves them out, and a pattern inside its support orbit
// keeps the empty word alone (the quad's shear spring: 8 words, 16 links
// from each touched dart, before).
//
// riftc emits each generated kernel's words (kReach). A kernel without them
// is re-matched over every dart within kRadius links of the touched ones:
// the same matches, from a neighbourhood that grows as (dimension + 1) to the
// power kRadius (the shear spring of a quad reads five links away: a few
// hundred darts around each tear where its eight words give eight).
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace rift {

/// A word of links from a match's support dart to a dart it reads.
struct ReachWord {
  /// Links a word holds at most (riftc emits no words for a longer one).
  static constexpr int kMaxLinks = 15;
  std::uint8_t length = 0;
  std::array<std::uint8_t, kMaxLinks> links{};  ///< links[0] is taken first from the support
};

/// Where the supports of the matches reading a touched dart are: walked
/// back along `words` when a kernel gives them, else every dart within
/// `radius` links.
struct Reach {
  int radius = 0;
  std::span<const ReachWord> words;
};

}  // namespace rift
