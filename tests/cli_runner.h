#pragma once
// Runs the citylangsplat executable (CLS_BINARY) from a test and captures its exit status, stdout
// and stderr.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/atomic_file.h"

namespace cls::test {

struct CliResult {
  int status = -1;  // exit status, -1 if the process did not exit normally
  std::string out, err;
};

inline CliResult run_cli(const std::string& args) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path base = fs::temp_directory_path() /
                        ("cls_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const fs::path out = base.string() + ".out", err = base.string() + ".err";
  const std::string cmd = "'" + std::string(CLS_BINARY) + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text_file(out);
  r.err = read_text_file(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

}  // namespace cls::test
