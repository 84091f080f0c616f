#pragma once
// Adam (Kingma & Ba; torch.optim.Adam's update, eps outside the square root) over named parameter
// tensors, with its state kept as plain tensors so that densification can prune and append rows
// of a parameter together with its moments (3DGS's _prune_optimizer / cat_tensors_to_optimizer),
// and so that a checkpoint holds the exact state (resume continues bit-for-bit).
#include <ATen/core/Tensor.h>

#include <map>
#include <string>
#include <vector>

namespace cls {

struct AdamGroup {
  std::string name;    // "means", "sh_dc", "latents_l1", ...
  at::Tensor param;    // a leaf tensor with requires_grad; updated in place
  double lr = 1e-3;
  at::Tensor exp_avg, exp_avg_sq;  // same shape as param
  int64_t step = 0;
};

class Adam {
 public:
  Adam(double beta1 = 0.9, double beta2 = 0.999, double eps = 1e-15);  // 3DGS uses eps 1e-15

  // Adds a parameter (its grad is read at step()); moments start at zero.
  void add(const std::string& name, const at::Tensor& param, double lr);
  AdamGroup& group(const std::string& name);  // cls::Error if absent
  const std::vector<AdamGroup>& groups() const { return groups_; }
  std::vector<AdamGroup>& groups() { return groups_; }

  // One update of every parameter that has a gradient; gradients are left untouched.
  void step();
  void zero_grad();

  // Rows (dim 0) of every parameter and its moments: keep where `mask` (N bool) is true.
  // Parameters become new leaf tensors with requires_grad; the caller re-reads them from group().
  void keep_rows(const at::Tensor& mask);
  // Appends rows to each named parameter (moments zero for the new rows), as cat_tensors_to_optimizer.
  void append_rows(const std::map<std::string, at::Tensor>& rows);
  // Replaces a parameter's values and zeroes its moments (3DGS's replace_tensor_to_optimizer).
  void replace(const std::string& name, const at::Tensor& values);

  // Checkpoint: "adam.<name>.exp_avg", "adam.<name>.exp_avg_sq" tensors and per-group step/lr in
  // the returned JSON-able map; restore() expects the same groups, already added.
  std::map<std::string, at::Tensor> state_tensors() const;
  std::map<std::string, double> state_scalars() const;  // "<name>.step", "<name>.lr"
  void restore(const std::map<std::string, at::Tensor>& tensors, const std::map<std::string, double>& scalars,
               const std::string& source);

 private:
  double beta1_, beta2_, eps_;
  std::vector<AdamGroup> groups_;
};

}  // namespace cls
