// Where a generated kernel's inits hand each support dart they choose.
//
// An untagged kernel chooses the dart each support orbit is matched from by
// its vertices (rift::generated::smallest_support_dart), which matches every
// dart of the orbit. Its inits make that choice for every orbit, and so did
// the simulator's match cache right after them, the same choice for the same
// orbits in the same order: a sixth of a 10^6-vertex cloth's set-up was
// these searches. A kernel whose inits choose takes a SupportSink and calls
// it with each orbit's support dart, in the order of GMap::for_each_cell;
// CachedInteraction matches the orbit from it right there, instead of
// walking the orbits a second time (and without keeping a dart per orbit).
#pragma once

#include "rift/core/types.hpp"

namespace rift {

/// A plain function pointer and its context: no allocation, one indirect
/// call per support orbit. Empty (the default) when nobody listens.
class SupportSink {
 public:
  SupportSink() = default;
  /// Calls f(d) for each support dart; f must outlive the sink.
  template <class F>
  static SupportSink to(F& f) {
    SupportSink s;
    s.context_ = &f;
    s.call_ = [](void* context, Dart d) { (*static_cast<F*>(context))(d); };
    return s;
  }
  explicit operator bool() const { return call_ != nullptr; }
  void operator()(Dart d) const { call_(context_, d); }

 private:
  void (*call_)(void*, Dart) = nullptr;
  void* context_ = nullptr;
};

}  // namespace rift
