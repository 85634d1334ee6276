#include "check/alpha_word.hpp"

#include <cstddef>
#include <cstdlib>
#include <utility>

namespace rift::check {

namespace {

bool commute(int i, int j) {
  return std::abs(i - j) >= 2;
}

}  // namespace

std::vector<int> reduced_word(std::vector<int> word) {
  for (bool cancelled = true; cancelled;) {
    cancelled = false;
    for (std::size_t i = 0; i < word.size() && !cancelled; ++i) {
      for (std::size_t j = i + 1; j < word.size(); ++j) {
        if (word[j] == word[i]) {
          word.erase(word.begin() + static_cast<std::ptrdiff_t>(j));
          word.erase(word.begin() + static_cast<std::ptrdiff_t>(i));
          cancelled = true;
          break;
        }
        if (!commute(word[j], word[i])) break;  // stop looking past a letter it does not pass
      }
    }
  }
  return word;
}

std::vector<int> normal_form(std::vector<int> word) {
  word = reduced_word(std::move(word));
  std::vector<int> out;
  while (!word.empty()) {
    // The least letter that commutes with every letter before it comes first.
    std::size_t best = 0;
    for (std::size_t p = 1; p < word.size(); ++p) {
      bool movable = true;
      for (std::size_t q = 0; q < p && movable; ++q)
        movable = commute(word[q], word[p]);
      if (movable && word[p] < word[best]) best = p;
    }
    out.push_back(word[best]);
    word.erase(word.begin() + static_cast<std::ptrdiff_t>(best));
  }
  return out;
}

}  // namespace rift::check
