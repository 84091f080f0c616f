#include "export/finite_values.h"

#include <ATen/ATen.h>

#include <cmath>

#include "core/error.h"
#include "core/log.h"

namespace cls {

void check_finite(const std::vector<float>& v, const std::string& what) {
  for (size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw Error(cat("export: the model's ", what, " holds a value that is not finite (", v[i], ", element ", i,
                      "): a glTF accessor cannot carry it"));
}

std::vector<float> finite_floats(const at::Tensor& t, const std::string& what) {
  const at::Tensor c = t.to(at::kFloat).contiguous().cpu();
  std::vector<float> v(c.data_ptr<float>(), c.data_ptr<float>() + c.numel());
  check_finite(v, what);
  return v;
}

}  // namespace cls
