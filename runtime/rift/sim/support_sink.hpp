// Where a generated kernel's inits hand each match they find.
//
// A kernel's inits walk every support orbit, choose the dart it is matched
// from (an untagged kernel by its vertices, rift::generated::
// smallest_support_match, which matches every dart of the orbit) and find the
// pattern's darts from it. The simulator's match cache, right after them,
// made the same choices and found the same darts again, for the same orbits
// in the same order: a sixth of a 10^6-vertex cloth's set-up was the
// choices, and a tenth of a 10^6-vertex hexahedral block's was finding the
// 48-dart volume shear pattern twice. A kernel with inits takes a
// SupportSink and calls it with each orbit's support dart and the darts
// found, in the order of GMap::for_each_cell; CachedInteraction takes the
// match from them right there (Kernel::match_found), instead of walking the
// orbits a second time.
#pragma once

#include "rift/core/types.hpp"

namespace rift {

/// A plain function pointer and its context: no allocation, one indirect
/// call per support orbit. Empty (the default) when nobody listens.
class SupportSink {
 public:
  SupportSink() = default;
  /// Calls f(d, darts) for each support dart d and the pattern's darts
  /// found from it; f must outlive the sink.
  template <class F>
  static SupportSink to(F& f) {
    SupportSink s;
    s.context_ = &f;
    s.call_ = [](void* context, Dart d, const Dart* darts) {
      (*static_cast<F*>(context))(d, darts);
    };
    return s;
  }
  explicit operator bool() const { return call_ != nullptr; }
  void operator()(Dart d, const Dart* darts) const { call_(context_, d, darts); }

 private:
  void (*call_)(void*, Dart, const Dart*) = nullptr;
  void* context_ = nullptr;
};

}  // namespace rift
