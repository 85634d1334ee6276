// A one-line progress bar with ETA on a terminal; silent when stderr is not
// a terminal (piped output stays clean).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace rift::cli {

class Progress {
 public:
  Progress(std::int64_t total, bool enabled);
  /// Redraws at most a few times per second.
  void update(std::int64_t done, const std::string& status);
  /// Clears the line.
  void finish();
  static bool stderr_is_terminal();

 private:
  std::int64_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  bool drawn_ = false;
};

std::string format_duration(double seconds);

}  // namespace rift::cli
