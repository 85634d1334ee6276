#include "rift/sim/setup_phases.hpp"

#include <unistd.h>

#include <fstream>
#include <utility>

namespace rift {

void SetupPhases::end(std::string name) {
  // The memory is read first, inside the phase it ends, so that the phases
  // tile the set-up with no gap: a read outside every phase (one per phase,
  // each opening /proc) left up to 4 ms of a 5 ms set-up on no phase when
  // the machine was loaded (Cli.BenchJson under CI's parallel tests).
  const double rss = resident_mb();
  const auto now = std::chrono::steady_clock::now();
  phases_.push_back(
      {std::move(name), std::chrono::duration<double, std::milli>(now - last_).count(), rss});
  last_ = now;
}

double resident_mb() {
  std::ifstream statm("/proc/self/statm");
  long total = 0, resident = 0;
  if (!(statm >> total >> resident)) return 0;
  const long page = sysconf(_SC_PAGESIZE);
  return static_cast<double>(resident) * static_cast<double>(page > 0 ? page : 4096) /
         (1024.0 * 1024.0);
}

}  // namespace rift
