#pragma once
// Where the model parity tests run: CLS_TEST_DEVICE (cpu by default; "cuda" on a GPU machine, as
// scripts/device/gpu_checks.sh runs them) places the CLIP parity models and the tiny SAM there; the
// references and tolerances stay the same, results are compared on the CPU. On CUDA, TF32 is off
// (LibTorch's default lets cuDNN convolutions use it): the fixtures are float32 references.
#include <ATen/Context.h>
#include <c10/core/Device.h>

#include <cstdlib>
#include <string>

namespace cls::testing {

inline c10::Device test_device() {
  const char* name = std::getenv("CLS_TEST_DEVICE");
  const c10::Device device(name && *name ? std::string(name) : std::string("cpu"));
  if (device.is_cuda()) {
    at::globalContext().setAllowTF32CuDNN(false);
    at::globalContext().setAllowTF32CuBLAS(false);
  }
  return device;
}

}  // namespace cls::testing
