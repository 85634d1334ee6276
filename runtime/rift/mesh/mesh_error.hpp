// The error of mesh input: names the file, the line and the problem.
#pragma once

#include "rift/core/input_error.hpp"

namespace rift {

class MeshError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace rift
