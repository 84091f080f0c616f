#pragma once
// Child processes without a shell (posix_spawn: arguments are passed as they are, never re-parsed):
// run-tiles' local executor starts its tasks with them and its Slurm executor calls sbatch and squeue.
#include <filesystem>
#include <string>
#include <sys/types.h>
#include <vector>

namespace cls {

struct CommandOutput {
  int exit_code = -1;  // 128 + signal for a signalled child; 127 when the program was not found
  std::string out;     // stdout (stderr goes to ours)
};

// Runs argv[0] (looked up in PATH) to completion and captures its stdout.
CommandOutput run_capture(const std::vector<std::string>& argv);

// Starts argv[0] with stdout and stderr appended to `log` and `env` ("NAME=value") added to ours.
// cls::Error when it cannot be started.
pid_t spawn_logged(const std::vector<std::string>& argv, const std::filesystem::path& log,
                   const std::vector<std::string>& env = {});

// Waits for any child; returns its pid and sets exit_code (as in CommandOutput); -1 when none is left.
pid_t wait_any_child(int& exit_code);

// Whether `program` is found in PATH (or is an executable path).
bool program_exists(const std::string& program);

}  // namespace cls
