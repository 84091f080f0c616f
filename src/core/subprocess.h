#pragma once
// Child processes without a shell (posix_spawn: arguments are passed as they are, never re-parsed):
// run-tiles' local executor starts its tasks with them and its Slurm executor calls sbatch and squeue.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace cls {

struct CommandOutput {
  int exit_code = -1;  // 128 + signal for a signalled child; 127 when the program was not found
  std::string out;     // stdout
  std::string err;     // stderr
};

// Runs argv[0] (looked up in PATH) to completion and captures its stdout and stderr.
CommandOutput run_capture(const std::vector<std::string>& argv);

// Starts argv[0] in a process group of its own (kill(-pid, sig) reaches it and its children; a
// terminal's Ctrl-C does not: the caller forwards it), with stdout and stderr appended to `log` and
// `env` ("NAME=value") replacing or adding to our environment. cls::Error naming the log when it cannot be written, or the program when it
// cannot be started.
pid_t spawn_logged(const std::vector<std::string>& argv, const std::filesystem::path& log,
                   const std::vector<std::string>& env = {});

// Waits up to `timeout_s` for any child: its pid (exit_code as in CommandOutput), 0 when none ended in
// time, -1 when there is no child.
pid_t wait_any_child(int& exit_code, double timeout_s);

// Whether `program` is found in PATH (or is an executable path).
bool program_exists(const std::string& program);

}  // namespace cls
