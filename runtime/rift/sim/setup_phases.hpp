// The phases of a simulation's set-up, timed: where a large mesh's set-up
// spends its time and memory (`rift bench --json` reports them as
// setup_phases). Measuring the set-up of a 10^6-vertex hexahedral block
// phase by phase (issue 12) showed work done for nothing in two phases of
// eight; a user who brings a large mesh can see the same.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace rift {

struct SetupPhase {
  std::string name;
  double ms = 0;      ///< wall time of the phase
  double rss_mb = 0;  ///< the process's resident memory when it ended (MiB; 0 if unknown)
};

/// Phases in order, each from the end of the one before (or from the
/// construction) to its own end.
class SetupPhases {
 public:
  SetupPhases() : last_(std::chrono::steady_clock::now()) {}
  /// Ends the phase running since the last end, named `name`.
  void end(std::string name);
  const std::vector<SetupPhase>& phases() const { return phases_; }

 private:
  std::chrono::steady_clock::time_point last_;
  std::vector<SetupPhase> phases_;
};

/// The process's resident memory now, in MiB (Linux's /proc/self/statm; 0
/// where it cannot be read).
double resident_mb();

}  // namespace rift
