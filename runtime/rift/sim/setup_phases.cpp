#include "rift/sim/setup_phases.hpp"

#include <unistd.h>

#include <fstream>
#include <utility>

namespace rift {

void SetupPhases::end(std::string name) {
  const auto now = std::chrono::steady_clock::now();
  phases_.push_back({std::move(name),
                     std::chrono::duration<double, std::milli>(now - last_).count(),
                     resident_mb()});
  // The memory read is not part of the next phase.
  last_ = std::chrono::steady_clock::now();
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
