#include "rift/generated/scratch.hpp"

namespace rift::generated {

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

}  // namespace rift::generated
