// The one error type of the output writers: names the path and the OS error.
#pragma once

#include <cerrno>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace rift {

/// An output file or folder could not be created, written or renamed.
/// what(): "cannot write 'out/frame_000003.vtu': No space left on device".
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& action, std::filesystem::path path, std::error_code error)
      : std::runtime_error(format(action, path, error)), path_(std::move(path)), error_(error) {}

  const std::filesystem::path& path() const { return path_; }
  std::error_code error() const { return error_; }

 private:
  static std::string format(const std::string& action, const std::filesystem::path& path,
                            std::error_code error) {
    std::string text = "cannot " + action + " '" + path.string() + "'";
    if (error) text += ": " + error.message();
    return text;
  }
  std::filesystem::path path_;
  std::error_code error_;
};

/// The error of the C library call that just failed, as errno tells it (EIO
/// when errno was left 0, so that a failure never reads as success).
inline std::error_code last_os_error() {
  return std::error_code(errno != 0 ? errno : EIO, std::generic_category());
}

}  // namespace rift
