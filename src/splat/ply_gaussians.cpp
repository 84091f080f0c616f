#include "splat/ply_gaussians.h"

#include <torch/types.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <climits>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"
#include "core/endian.h"
#include "core/error.h"
#include "core/ply.h"

namespace cls {

void write_gaussians_ply(const std::string& path, const GaussianModel& model) {
  model.validate(path);
  // What the reader refuses is never written: a training that diverged says so here, not later.
  for (const auto& [name, t] : {std::pair<const char*, const at::Tensor&>{"means", model.means},
                                {"log_scales", model.log_scales}, {"quats", model.quats},
                                {"opacity_logits", model.opacity_logits}, {"sh_dc", model.sh_dc},
                                {"sh_rest", model.sh_rest}, {"features", model.features}})
    if (t.defined() && t.numel() > 0 && !t.isfinite().all().item<bool>())
      fail(path, std::string("tensor ") + name + " holds NaN or infinity (a diverged training?); nothing written");
  if (!host_is_little_endian()) fail(path, "writing PLY on a big-endian host is not supported");
  const int64_t n = model.size();
  const int rest = static_cast<int>(model.sh_rest.size(1));
  const int F = model.feature_channels();
  auto cpu = [](const at::Tensor& t) { return t.detach().to(torch::kCPU).contiguous(); };
  const at::Tensor means = cpu(model.means), dc = cpu(model.sh_dc), opac = cpu(model.opacity_logits),
                   scales = cpu(model.log_scales), quats = cpu(model.quats);
  const at::Tensor rest_cm = cpu(model.sh_rest.transpose(1, 2));  // N x 3 x (K-1): channel-major
  const at::Tensor feats = F > 0 ? cpu(model.features) : at::Tensor();
  std::vector<at::Tensor> extras;
  for (const auto& e : model.extras) extras.push_back(cpu(e.values));

  std::ostringstream h;
  h << "ply\nformat binary_little_endian 1.0\nelement vertex " << n << "\n";
  for (const char* p : {"x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"}) h << "property float " << p << "\n";
  for (int k = 0; k < 3 * rest; ++k) h << "property float f_rest_" << k << "\n";
  h << "property float opacity\n";
  for (int k = 0; k < 3; ++k) h << "property float scale_" << k << "\n";
  for (int k = 0; k < 4; ++k) h << "property float rot_" << k << "\n";
  for (int k = 0; k < F; ++k) h << "property float latent_" << k << "\n";
  for (size_t e = 0; e < extras.size(); ++e)
    h << "property " << (extras[e].scalar_type() == torch::kInt32 ? "int " : "float ") << model.extras[e].name << "\n";
  h << "end_header\n";
  const size_t stride = 4 * (6 + 3 + 3 * rest + 1 + 3 + 4 + F + extras.size());
  std::string body(static_cast<size_t>(n) * stride, '\0');
  const float zero3[3] = {0, 0, 0};
  for (int64_t i = 0; i < n; ++i) {
    char* p = body.data() + i * stride;
    auto put = [&p](const void* src, size_t count) {
      std::memcpy(p, src, 4 * count);
      p += 4 * count;
    };
    put(means.data_ptr<float>() + 3 * i, 3);
    put(zero3, 3);
    put(dc.data_ptr<float>() + 3 * i, 3);
    put(rest_cm.data_ptr<float>() + 3 * rest * i, 3 * rest);
    put(opac.data_ptr<float>() + i, 1);
    put(scales.data_ptr<float>() + 3 * i, 3);
    put(quats.data_ptr<float>() + 4 * i, 4);
    if (F > 0) put(feats.data_ptr<float>() + F * i, F);
    for (const auto& e : extras) put(static_cast<const char*>(e.data_ptr()) + 4 * i, 1);
  }
  write_atomic(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    const std::string header = h.str();
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    out.write(body.data(), static_cast<std::streamsize>(body.size()));
    if (!out) fail(tmp.string(), "write failed");
  });
}

GaussianModel read_gaussians_ply(const std::string& path) {
  const PlyVertices c = read_ply_vertices(path);
  const int64_t n = static_cast<int64_t>(c.count);
  const int n_rest = c.count_indexed("f_rest_");
  if (n_rest != 0 && n_rest != 9 && n_rest != 24 && n_rest != 45)
    fail(path, std::to_string(n_rest) + " f_rest properties: expected 0, 9, 24 or 45 (SH degree 0-3)");
  const int rest = n_rest / 3;
  const int F = c.count_indexed("latent_");
  // Fills a float32 tensor of shape {n, names.size()} from the named columns. NaN or infinity in a
  // Gaussian renders as nothing, or poisons every pixel it touches: refused.
  auto gather = [&](const std::vector<std::string>& names) {
    std::vector<const PlyProperty*> props;
    for (const auto& nm : names) props.push_back(&c.require(nm));
    at::Tensor t = torch::empty({n, static_cast<int64_t>(names.size())}, torch::kFloat32);
    float* out = t.data_ptr<float>();
    const int64_t m = static_cast<int64_t>(names.size());
    for (int64_t i = 0; i < n; ++i)
      for (int64_t k = 0; k < m; ++k) {
        const double v = c.finite_value(i, *props[k]);
        out[i * m + k] = static_cast<float>(v);
        if (!std::isfinite(out[i * m + k]))
          fail(path, "vertex " + std::to_string(i) + " has " + names[k] + " = " + std::to_string(v) + ": beyond float");
      }
    return t;
  };
  auto indexed = [](const std::string& prefix, int count) {
    std::vector<std::string> v;
    for (int k = 0; k < count; ++k) v.push_back(prefix + std::to_string(k));
    return v;
  };
  GaussianModel g;
  g.means = gather({"x", "y", "z"});
  g.sh_dc = gather(indexed("f_dc_", 3)).reshape({n, 1, 3});
  // channel-major on disk: f_rest_(c*(K-1)+k) -> sh_rest[i][k][c]
  g.sh_rest = rest > 0 ? gather(indexed("f_rest_", n_rest)).reshape({n, 3, rest}).transpose(1, 2).contiguous()
                       : torch::zeros({n, 0, 3}, torch::kFloat32);
  g.opacity_logits = gather({"opacity"});
  g.log_scales = gather(indexed("scale_", 3));
  g.quats = gather(indexed("rot_", 4));
  if (F > 0) g.features = gather(indexed("latent_", F));
  // everything else is an extra, read back by name
  static const std::vector<std::string> kKnownPrefixes = {"f_rest_", "latent_"};
  for (const auto& p : c.properties) {
    if (p.name == "x" || p.name == "y" || p.name == "z" || p.name == "nx" || p.name == "ny" || p.name == "nz" ||
        p.name == "opacity" || p.name.rfind("f_dc_", 0) == 0 || p.name.rfind("scale_", 0) == 0 ||
        p.name.rfind("rot_", 0) == 0)
      continue;
    bool known = false;
    for (const auto& pre : kKnownPrefixes) {
      if (p.name.rfind(pre, 0) != 0) continue;
      const std::string idx = p.name.substr(pre.size());
      const int limit = pre == "f_rest_" ? n_rest : F;
      known = !idx.empty() && idx.size() < 9 && idx.find_first_not_of("0123456789") == std::string::npos &&
              std::stoi(idx) < limit;
    }
    if (known) continue;
    GaussianExtra e{p.name, at::Tensor()};
    if (p.is_int) {
      e.values = torch::empty({n}, torch::kInt32);
      int32_t* out = e.values.data_ptr<int32_t>();
      for (int64_t i = 0; i < n; ++i) {
        const double v = c.value(i, p);
        if (v > INT32_MAX) fail(path, "vertex " + std::to_string(i) + " has " + p.name + " = " + std::to_string(v) + ": beyond int32");
        out[i] = static_cast<int32_t>(v);
      }
    } else {
      e.values = torch::empty({n}, torch::kFloat32);
      float* out = e.values.data_ptr<float>();
      for (int64_t i = 0; i < n; ++i) out[i] = static_cast<float>(c.value(i, p));
    }
    g.extras.push_back(std::move(e));
  }
  g.validate(path);
  return g;
}

}  // namespace cls
