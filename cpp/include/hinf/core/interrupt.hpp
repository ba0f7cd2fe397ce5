// Ctrl-C for long computations. A process-wide request that a signal handler may set (a
// lock-free atomic store: async-signal-safe) and that every integrator reads after each step:
// a request ends the computation with Interrupted within one step. hinf-sim installs a SIGINT
// handler that sets it; the Python module chains one before Python's own, so that a Ctrl-C
// stops a C++ call that runs without the GIL and Python then raises KeyboardInterrupt.
#pragma once

#include <stdexcept>

namespace hinf {

// Thrown by throw_if_interrupted(): not an InputError or a HinfError, so that no handler of
// bad input or numerical failure takes it for one (a study does not record it as a failed run).
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

// Requests that the running computations stop at their next step (as Ctrl-C does); safe in a
// signal handler.
void request_interrupt() noexcept;
// Withdraws a request (a computation's front end does, before it starts, for one that was
// already answered).
void clear_interrupt() noexcept;
// Whether an interrupt is requested.
bool interrupt_requested() noexcept;
// Throws Interrupted when an interrupt is requested (and leaves the request set, so that every
// loop on the way out stops too).
void throw_if_interrupted();

// For programs without Python (hinf-sim): SIGINT requests an interrupt; a second SIGINT while
// the first is pending ends the process as SIGINT does by default.
void install_interrupt_handler();

}  // namespace hinf
