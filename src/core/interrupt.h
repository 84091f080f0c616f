#pragma once
// SIGINT / SIGTERM as a request to stop: long jobs (training) poll interrupt_requested() at a safe
// point, write a checkpoint and exit with kInterruptedExit. A second signal while the first is being
// handled restores the default action, so a user can always force-quit with another Ctrl-C.
#include "core/exit_codes.h"

namespace cls {

// Installs the handlers (idempotent; async-signal-safe: the handler only sets a flag).
void install_interrupt_handlers();
bool interrupt_requested();
// Tests: clear or set the flag without a signal.
void reset_interrupt();
void request_interrupt();

}  // namespace cls
