#pragma once
#include <stdexcept>
#include <string>

namespace cls {

// Every user-facing failure (bad input, missing file, unsupported format) is a cls::Error.
// Its message names the file and what is wrong; the CLI prints it and exits non-zero.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "path: what" — the one format for errors about a file.
[[noreturn]] void fail(const std::string& path, const std::string& what);

// Usage errors (unknown option, missing argument): the CLI exits with status 2 for these.
class UsageError : public Error {
 public:
  using Error::Error;
};

}  // namespace cls
