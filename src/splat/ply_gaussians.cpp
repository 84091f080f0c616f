#include "splat/ply_gaussians.h"

#include <torch/types.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/atomic_file.h"
#include "core/endian.h"
#include "core/error.h"

namespace cls {
namespace {

struct PlyProperty {
  std::string name, type;
  int size = 0, offset = 0;
  bool is_int = false;
};

int type_size(const std::string& t, bool& is_int) {
  is_int = true;
  if (t == "char" || t == "int8" || t == "uchar" || t == "uint8") return 1;
  if (t == "short" || t == "int16" || t == "ushort" || t == "uint16") return 2;
  if (t == "int" || t == "int32" || t == "uint" || t == "uint32") return 4;
  is_int = false;
  if (t == "float" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

double read_value(const char* p, const PlyProperty& prop) {
  const std::string& t = prop.type;
  auto get = [p](auto v) {
    std::memcpy(&v, p, sizeof(v));
    return static_cast<double>(v);
  };
  if (t == "char" || t == "int8") return get(int8_t{});
  if (t == "uchar" || t == "uint8") return get(uint8_t{});
  if (t == "short" || t == "int16") return get(int16_t{});
  if (t == "ushort" || t == "uint16") return get(uint16_t{});
  if (t == "int" || t == "int32") return get(int32_t{});
  if (t == "uint" || t == "uint32") return get(uint32_t{});
  if (t == "double" || t == "float64") return get(double{});
  return get(float{});
}

// Columns of the file as float32 (or int32 for integer extras), one per property.
struct PlyColumns {
  int64_t n = 0;
  std::vector<PlyProperty> props;
  std::string data;  // the vertex rows
  size_t stride = 0;
  const PlyProperty* find(const std::string& name) const {
    for (const auto& p : props)
      if (p.name == name) return &p;
    return nullptr;
  }
  float value(int64_t row, const PlyProperty& p) const {
    const char* at = data.data() + row * stride + p.offset;
    if (p.type == "float" || p.type == "float32") {
      float v;
      std::memcpy(&v, at, 4);
      return v;
    }
    return static_cast<float>(read_value(at, p));
  }
};

PlyColumns read_ply_vertices(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) fail(path, "cannot open Gaussian PLY");
  std::string line;
  auto next_line = [&]() {
    if (!std::getline(f, line)) fail(path, "PLY header ends before end_header");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return line;
  };
  if (next_line() != "ply") fail(path, "not a PLY file (no 'ply' magic)");
  PlyColumns cols;
  bool in_vertex = false, seen_vertex = false, format_ok = false;
  int offset = 0;
  while (next_line() != "end_header") {
    std::istringstream ls(line);
    std::string kw;
    ls >> kw;
    if (kw == "format") {
      std::string fmt;
      ls >> fmt;
      if (fmt != "binary_little_endian") fail(path, "PLY format '" + fmt + "' is not supported (binary_little_endian only)");
      format_ok = true;
    } else if (kw == "element") {
      std::string name;
      int64_t count = -1;
      ls >> name >> count;
      if (count < 0) fail(path, "malformed PLY element line: " + line);
      if (name == "vertex") {
        if (seen_vertex) fail(path, "PLY has two vertex elements");
        in_vertex = seen_vertex = true;
        cols.n = count;
      } else {
        if (!seen_vertex && count > 0) fail(path, "PLY element '" + name + "' before the vertices is not supported");
        in_vertex = false;
      }
    } else if (kw == "property" && in_vertex) {
      PlyProperty p;
      ls >> p.type >> p.name;
      if (p.type == "list") fail(path, "list property in the vertex element is not supported");
      p.size = type_size(p.type, p.is_int);
      if (p.size == 0 || p.name.empty()) fail(path, "unknown PLY property type in: " + line);
      p.offset = offset;
      offset += p.size;
      cols.props.push_back(p);
    }
  }
  if (!format_ok) fail(path, "PLY header has no format line");
  if (!seen_vertex) fail(path, "PLY has no vertex element");
  cols.stride = offset;
  if (cols.n > 0 && cols.stride == 0) fail(path, "PLY vertex element has no properties");
  // Compare the header's promise with the file before allocating it: a count of 10^11 is a damaged
  // header, not a reason to run out of memory.
  const std::streamoff header_end = f.tellg();
  std::error_code ec;
  const uintmax_t file_bytes = std::filesystem::file_size(path, ec);
  const uintmax_t available = ec || header_end < 0 ? 0 : file_bytes - static_cast<uintmax_t>(header_end);
  if (cols.stride > 0 && static_cast<uintmax_t>(cols.n) > available / cols.stride)
    fail(path, "truncated PLY: the header promises " + std::to_string(cols.n) + " vertices of " +
                   std::to_string(cols.stride) + " bytes, the file holds " + std::to_string(available) +
                   " bytes after the header");
  const size_t bytes = static_cast<size_t>(cols.n) * cols.stride;
  cols.data.resize(bytes);
  f.read(cols.data.data(), static_cast<std::streamsize>(bytes));
  if (static_cast<size_t>(f.gcount()) != bytes)
    fail(path, "truncated PLY: " + std::to_string(cols.n) + " vertices need " + std::to_string(bytes) + " bytes, found " +
                   std::to_string(f.gcount()));
  return cols;
}

// Number of properties prefix_0, prefix_1, ... present without a gap.
int count_indexed(const PlyColumns& c, const std::string& prefix) {
  int k = 0;
  while (c.find(prefix + std::to_string(k))) ++k;
  return k;
}

}  // namespace

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
  const PlyColumns c = read_ply_vertices(path);
  const int64_t n = c.n;
  const int n_rest = count_indexed(c, "f_rest_");
  if (n_rest != 0 && n_rest != 9 && n_rest != 24 && n_rest != 45)
    fail(path, std::to_string(n_rest) + " f_rest properties: expected 0, 9, 24 or 45 (SH degree 0-3)");
  const int rest = n_rest / 3;
  const int F = count_indexed(c, "latent_");
  auto column = [&](const std::string& name) -> const PlyProperty& {
    const PlyProperty* p = c.find(name);
    if (!p) fail(path, "PLY has no vertex property '" + name + "'");
    return *p;
  };
  // Fills a float32 tensor of shape {n, names.size()} from the named columns.
  auto gather = [&](const std::vector<std::string>& names) {
    std::vector<const PlyProperty*> props;
    for (const auto& nm : names) props.push_back(&column(nm));
    at::Tensor t = torch::empty({n, static_cast<int64_t>(names.size())}, torch::kFloat32);
    float* out = t.data_ptr<float>();
    const int64_t m = static_cast<int64_t>(names.size());
    for (int64_t i = 0; i < n; ++i)
      for (int64_t k = 0; k < m; ++k) {
        out[i * m + k] = c.value(i, *props[k]);
        // NaN or infinity in a Gaussian renders as nothing, or poisons every pixel it touches.
        if (!std::isfinite(out[i * m + k]))
          fail(path, "vertex " + std::to_string(i) + " has " + names[k] + " = " + std::to_string(out[i * m + k]) +
                         ": a Gaussian PLY holds finite numbers only");
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
  for (const auto& p : c.props) {
    if (p.name == "x" || p.name == "y" || p.name == "z" || p.name == "nx" || p.name == "ny" || p.name == "nz" ||
        p.name == "opacity" || p.name.rfind("f_dc_", 0) == 0 || p.name.rfind("scale_", 0) == 0 ||
        p.name.rfind("rot_", 0) == 0)
      continue;
    bool known = false;
    for (const auto& pre : kKnownPrefixes) {
      if (p.name.rfind(pre, 0) != 0) continue;
      const std::string idx = p.name.substr(pre.size());
      const int limit = pre == "f_rest_" ? n_rest : F;
      known = !idx.empty() && idx.find_first_not_of("0123456789") == std::string::npos && std::stoi(idx) < limit;
    }
    if (known) continue;
    GaussianExtra e{p.name, at::Tensor()};
    if (p.is_int) {
      e.values = torch::empty({n}, torch::kInt32);
      int32_t* out = e.values.data_ptr<int32_t>();
      for (int64_t i = 0; i < n; ++i) out[i] = static_cast<int32_t>(read_value(c.data.data() + i * c.stride + p.offset, p));
    } else {
      e.values = torch::empty({n}, torch::kFloat32);
      float* out = e.values.data_ptr<float>();
      for (int64_t i = 0; i < n; ++i) out[i] = c.value(i, p);
    }
    g.extras.push_back(std::move(e));
  }
  g.validate(path);
  return g;
}

}  // namespace cls
