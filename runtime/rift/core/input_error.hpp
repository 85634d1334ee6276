// The error of any user input (mesh file, scene file, command-line value):
// it names the file, the line and the problem, as "file:line: error: problem".
#pragma once

#include <stdexcept>
#include <string>

namespace rift {

class InputError : public std::runtime_error {
 public:
  /// line 0 means "the file as a whole" (empty file, missing section).
  InputError(std::string file, int line, const std::string& problem)
      : std::runtime_error(format(file, line, problem)),
        file_(std::move(file)),
        line_(line),
        problem_(problem) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& problem) {
    std::string text = file;
    if (line > 0) {
      text += ':';
      text += std::to_string(line);
    }
    text += ": error: ";
    text += problem;
    return text;
  }
  std::string file_;
  int line_;
  std::string problem_;
};

}  // namespace rift
