#include "splat/compute_device.h"

#include <ATen/Context.h>

#include "core/error.h"

namespace cls {

c10::Device compute_device(const std::string& name) {
  if (name == "cpu") return c10::kCPU;
  if (name == "cuda" || name == "auto") {
#ifdef CLS_WITH_CUDA
    if (at::hasCUDA()) return c10::Device(c10::kCUDA, 0);
#endif
    if (name == "cuda") throw UsageError("--device cuda: this build or machine has no CUDA device");
    return c10::kCPU;
  }
  throw UsageError("unknown device '" + name + "' (auto, cpu or cuda)");
}

}  // namespace cls
