#include "rift/generated/scratch.hpp"

namespace rift::generated {

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

DartList::DartList() {
  Scratch& s = scratch();
  if (s.dart_lists_open == s.dart_lists.size())
    s.dart_lists.push_back(std::make_unique<std::vector<Dart>>());
  darts_ = s.dart_lists[s.dart_lists_open++].get();
}

DartList::~DartList() {
  // Lists close in the reverse order they opened (scopes nest): this one is
  // the last open.
  darts_->clear();
  --scratch().dart_lists_open;
}

}  // namespace rift::generated
