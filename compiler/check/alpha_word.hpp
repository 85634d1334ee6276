// Words of alpha links (alpha indices, applied left to right) as elements of
// the group the alpha_i generate on every G-map: a right-angled Coxeter group
// (alpha_i^2 = 1, and alpha_i alpha_j = alpha_j alpha_i when |i - j| >= 2, the
// G-map condition). Used to tell whether two paths from one dart reach the
// same dart on every map (criterion nodes) and which orbit a path stays in
// (interaction force ownership).
#pragma once

#include <vector>

namespace rift::check {

/// `word` with every cancellable pair removed: two equal letters separated
/// only by letters that commute with them cancel. The result is reduced
/// (Tits): no shorter word is equal to it.
std::vector<int> reduced_word(std::vector<int> word);

/// The normal form of `word`: reduced, then the lexicographically least of
/// its reorderings by commutations. Two words reach the same dart from the
/// same start on every G-map iff their normal forms are equal (reduced words
/// of one element differ by commutations only).
std::vector<int> normal_form(std::vector<int> word);

}  // namespace rift::check
