#pragma once
// Where training runs, from a command-line name: "auto" (the first CUDA device where the build links
// the CUDA backend and the machine has one, else the CPU), "cpu" or "cuda". train-rgb and
// train-language both take it.
#include <c10/core/Device.h>

#include <string>

namespace cls {

// Throws UsageError for an unknown name, and for "cuda" where this build or machine has no CUDA device.
c10::Device compute_device(const std::string& name);

}  // namespace cls
