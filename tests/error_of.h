#pragma once
// The message of the cls::Error that `f` throws, or "(no cls::Error)" when it returns normally, so a
// test can assert both that an input is refused and what the message names.
#include <functional>
#include <string>

#include "core/error.h"

namespace cls::test {

inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no cls::Error)";
}

}  // namespace cls::test
