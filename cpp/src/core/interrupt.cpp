#include "hinf/core/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace hinf {

namespace {

std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only store a lock-free atomic");

extern "C" void on_sigint(int) {
  if (requested.load(std::memory_order_relaxed)) {
    std::signal(SIGINT, SIG_DFL);  // the second Ctrl-C: the default action
    std::raise(SIGINT);
    return;
  }
  requested.store(true, std::memory_order_relaxed);
}

}  // namespace

void request_interrupt() noexcept { requested.store(true, std::memory_order_relaxed); }
void clear_interrupt() noexcept { requested.store(false, std::memory_order_relaxed); }
bool interrupt_requested() noexcept { return requested.load(std::memory_order_relaxed); }

void throw_if_interrupted() {
  if (interrupt_requested()) throw Interrupted();
}

void install_interrupt_handler() { std::signal(SIGINT, on_sigint); }

}  // namespace hinf
