#pragma once
// A model's tensor as the floats an exporter writes, refused when one is not finite: glTF accessors and
// SPZ's bytes cannot carry NaN or infinity.
#include <ATen/core/Tensor.h>

#include <string>
#include <vector>

namespace cls {

// cls::Error naming `what` and the first element that is not finite.
void check_finite(const std::vector<float>& values, const std::string& what);
// The tensor's elements as float32 (row-major), checked as above.
std::vector<float> finite_floats(const at::Tensor& t, const std::string& what);

}  // namespace cls
