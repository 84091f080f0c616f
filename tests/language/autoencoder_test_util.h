#pragma once
// Synthetic CLIP-like features for the autoencoder tests: unit vectors around a few cluster centres.
#include <ATen/ATen.h>
#include <ATen/CPUGeneratorImpl.h>

#include <cmath>

namespace cls::test {

// n unit vectors in `dim` dimensions: normalize(centre_k + noise), k = i mod clusters, where the
// centres are random unit vectors and the noise has expected norm `noise_norm`.
inline at::Tensor clustered_unit_vectors(int64_t n, int64_t dim, int64_t clusters, double noise_norm,
                                         uint64_t seed) {
  at::Generator gen = at::detail::createCPUGenerator(seed);
  at::Tensor centres = at::randn({clusters, dim}, gen);
  centres = centres / centres.norm(2, {1}, true);
  const at::Tensor ids = at::arange(n, at::kLong).remainder(clusters);
  const at::Tensor noise = at::randn({n, dim}, gen) * (noise_norm / std::sqrt(static_cast<double>(dim)));
  const at::Tensor f = centres.index_select(0, ids) + noise;
  return f / f.norm(2, {1}, true);
}


}  // namespace cls::test
