#include "rift/core/interrupt.hpp"

#include <csignal>

namespace rift {

namespace {

void on_sigint(int) {
  request_interrupt();
}

}  // namespace

InterruptHandler::InterruptHandler() {
  clear_interrupt();
  previous_ = std::signal(SIGINT, on_sigint);
}

InterruptHandler::~InterruptHandler() {
  std::signal(SIGINT, previous_ == SIG_ERR ? SIG_DFL : previous_);
}

}  // namespace rift
