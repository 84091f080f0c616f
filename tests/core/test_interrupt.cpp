// The interrupt flag: SIGINT/SIGTERM set it; a second signal restores the default action.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include "core/interrupt.h"

namespace {

TEST(Interrupt, FlagSetAndReset) {
  cls::reset_interrupt();
  EXPECT_FALSE(cls::interrupt_requested());
  cls::request_interrupt();
  EXPECT_TRUE(cls::interrupt_requested());
  cls::reset_interrupt();
  EXPECT_FALSE(cls::interrupt_requested());
}

TEST(Interrupt, SignalSetsFlagSecondSignalKills) {
  // In a child, so the default action of the second signal does not end the test process.
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    cls::install_interrupt_handlers();
    cls::install_interrupt_handlers();  // idempotent
    ::raise(SIGTERM);
    if (!cls::interrupt_requested()) ::_exit(3);
    ::raise(SIGINT);  // second signal: default action, the process dies of SIGINT
    ::_exit(4);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGINT);
}

}  // namespace
