#include "core/interrupt.h"

#include <csignal>

namespace cls {
namespace {

volatile std::sig_atomic_t g_requested = 0;

extern "C" void on_interrupt_signal(int sig) {
  if (g_requested) {
    // Second signal: the user insists. Restore the default action and re-raise it.
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_requested = 1;
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // blocking reads/writes continue; the loop polls the flag
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool interrupt_requested() { return g_requested != 0; }
void reset_interrupt() { g_requested = 0; }
void request_interrupt() { g_requested = 1; }

}  // namespace cls
