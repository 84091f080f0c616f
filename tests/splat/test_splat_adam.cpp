// Adam against torch::optim::Adam, row pruning/appending with aligned moments, and the checkpoint
// file (bit-exact round trip, clear errors for missing/truncated/foreign files).
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "models/weights/safetensors.h"
#include "splat/adam.h"
#include "splat/checkpoint.h"

namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  TempDir() {
    static int counter = 0;
    path = fs::temp_directory_path() / ("cls_adam_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

// A loss with varied gradients: sum(w * p^2) + sum(sin(p)).
at::Tensor loss_of(const at::Tensor& p, const at::Tensor& w) { return (w * p * p).sum() + p.sin().sum(); }

TEST(Adam, MatchesTorchOptimAdamBitwise) {
  torch::manual_seed(3);
  const at::Tensor init = torch::randn({7, 3});
  const at::Tensor w = torch::rand({7, 3}) * 10;
  at::Tensor ours = init.clone().set_requires_grad(true);
  at::Tensor theirs = init.clone().set_requires_grad(true);
  cls::Adam adam(0.9, 0.999, 1e-15);
  adam.add("x", ours, 0.01);
  torch::optim::Adam reference({theirs}, torch::optim::AdamOptions(0.01).betas({0.9, 0.999}).eps(1e-15));
  for (int step = 0; step < 25; ++step) {
    adam.zero_grad();
    loss_of(adam.group("x").param, w).backward();
    adam.step();
    reference.zero_grad();
    loss_of(theirs, w).backward();
    reference.step();
    ASSERT_TRUE(torch::equal(adam.group("x").param, theirs)) << "step " << step;
  }
  EXPECT_EQ(adam.group("x").step, 25);
  // The update moved the parameter: the comparison is not between two unchanged tensors.
  EXPECT_GT((theirs - init).abs().max().item<float>(), 0.05f);
}

TEST(Adam, SkipsParametersWithoutGradient) {
  at::Tensor a = torch::ones({2}).set_requires_grad(true), b = torch::ones({2}).set_requires_grad(true);
  cls::Adam adam;
  adam.add("a", a, 0.1);
  adam.add("b", b, 0.1);
  (adam.group("a").param * 2).sum().backward();
  adam.step();
  EXPECT_EQ(adam.group("a").step, 1);
  EXPECT_EQ(adam.group("b").step, 0);
  EXPECT_TRUE(torch::equal(adam.group("b").param, torch::ones({2})));
  EXPECT_NEAR(adam.group("a").param[0].item<float>(), 0.9f, 1e-6);  // first Adam step: lr * sign(g)
  EXPECT_THROW(adam.group("c"), cls::Error);
  EXPECT_THROW(adam.add("a", a, 0.1), cls::Error);
}

TEST(Adam, KeepAndAppendRowsKeepMomentsAligned) {
  torch::manual_seed(5);
  cls::Adam adam;
  adam.add("m", torch::randn({5, 3}).set_requires_grad(true), 0.01);
  adam.add("o", torch::randn({5, 1}).set_requires_grad(true), 0.05);
  for (int i = 0; i < 3; ++i) {
    adam.zero_grad();
    ((adam.group("m").param.pow(2)).sum() + adam.group("o").param.exp().sum()).backward();
    adam.step();
  }
  const at::Tensor m_before = adam.group("m").param.detach().clone();
  const at::Tensor avg_before = adam.group("m").exp_avg.clone(), sq_before = adam.group("o").exp_avg_sq.clone();
  const at::Tensor mask = torch::tensor({true, false, true, true, false});
  adam.keep_rows(mask);
  ASSERT_EQ(adam.group("m").param.size(0), 3);
  EXPECT_TRUE(adam.group("m").param.requires_grad());
  EXPECT_TRUE(adam.group("m").param.is_leaf());
  const at::Tensor rows = torch::tensor({0, 2, 3});
  EXPECT_TRUE(torch::equal(adam.group("m").param, m_before.index_select(0, rows)));
  EXPECT_TRUE(torch::equal(adam.group("m").exp_avg, avg_before.index_select(0, rows)));
  EXPECT_TRUE(torch::equal(adam.group("o").exp_avg_sq, sq_before.index_select(0, rows)));

  adam.append_rows({{"m", torch::full({2, 3}, 7.0f)}, {"o", torch::full({2, 1}, -1.0f)}});
  ASSERT_EQ(adam.group("m").param.size(0), 5);
  ASSERT_EQ(adam.group("o").exp_avg.size(0), 5);
  EXPECT_TRUE(torch::equal(adam.group("m").param.slice(0, 3), torch::full({2, 3}, 7.0f)));
  EXPECT_TRUE(torch::equal(adam.group("m").exp_avg.slice(0, 0, 3), avg_before.index_select(0, rows)));
  EXPECT_EQ(adam.group("m").exp_avg.slice(0, 3).abs().sum().item<float>(), 0.0f);
  EXPECT_EQ(adam.group("o").exp_avg_sq.slice(0, 3).abs().sum().item<float>(), 0.0f);
  EXPECT_GT(adam.group("o").exp_avg_sq.slice(0, 0, 3).abs().sum().item<float>(), 0.0f);

  // Training continues on the new tensors.
  adam.zero_grad();
  adam.group("m").param.sum().backward();
  adam.step();
  EXPECT_EQ(adam.group("m").step, 4);

  adam.replace("o", torch::zeros({5, 1}));
  EXPECT_EQ(adam.group("o").exp_avg.abs().sum().item<float>(), 0.0f);
  EXPECT_EQ(adam.group("o").exp_avg_sq.abs().sum().item<float>(), 0.0f);
  EXPECT_THROW(adam.keep_rows(torch::ones({4}, torch::kBool)), cls::Error);
  EXPECT_THROW(adam.append_rows({{"m", torch::zeros({1, 2})}}), cls::Error);
}

TEST(Adam, StateRestoreContinuesIdentically) {
  torch::manual_seed(7);
  const at::Tensor w = torch::rand({4, 2});
  auto make = [&](const at::Tensor& init) {
    cls::Adam a;
    a.add("p", init.clone().set_requires_grad(true), 0.02);
    return a;
  };
  auto run = [&](cls::Adam& a, int steps) {
    for (int i = 0; i < steps; ++i) {
      a.zero_grad();
      loss_of(a.group("p").param, w).backward();
      a.step();
    }
  };
  const at::Tensor init = torch::randn({4, 2});
  cls::Adam straight = make(init);
  run(straight, 10);
  cls::Adam first = make(init);
  run(first, 4);
  cls::Adam second = make(first.group("p").param.detach());
  second.restore(first.state_tensors(), first.state_scalars(), "test");
  run(second, 6);
  EXPECT_TRUE(torch::equal(straight.group("p").param, second.group("p").param));
  EXPECT_THROW(second.restore({}, first.state_scalars(), "test"), cls::Error);
}

TEST(Checkpoint, RoundTripIsBitExact) {
  TempDir dir;
  torch::manual_seed(11);
  cls::Checkpoint c;
  c.tensors["means"] = torch::randn({13, 3});
  c.tensors["radii"] = torch::randint(0, 100, {13}, torch::kInt32);
  c.tensors["big"] = torch::randn({3, 5, 7}, torch::kFloat64);
  c.tensors["empty"] = torch::zeros({0, 3});
  c.info = {{"iteration", 1234}, {"rng", "12345678901234567890 1 2"}, {"lr", 1.0 / 3.0}};
  const std::string path = (dir.path / "sub" / "ckpt.safetensors").string();
  cls::write_checkpoint(path, c);
  const cls::Checkpoint r = cls::read_checkpoint(path);
  ASSERT_EQ(r.tensors.size(), c.tensors.size());
  for (const auto& [name, t] : c.tensors) {
    ASSERT_TRUE(r.tensors.count(name)) << name;
    EXPECT_EQ(r.tensors.at(name).scalar_type(), t.scalar_type()) << name;
    EXPECT_TRUE(torch::equal(r.tensors.at(name), t)) << name;
  }
  EXPECT_EQ(r.info, c.info);
  EXPECT_EQ(r.info["lr"].get<double>(), 1.0 / 3.0);
}

void expect_error_naming(const std::string& path, const std::string& what) {
  try {
    cls::read_checkpoint(path);
    ADD_FAILURE() << "no error for " << what;
  } catch (const cls::Error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << what << ": " << e.what();
  }
}

TEST(Checkpoint, MissingTruncatedAndForeignFilesAreErrors) {
  TempDir dir;
  const std::string path = (dir.path / "c.safetensors").string();
  expect_error_naming(path, "missing");
  cls::Checkpoint c;
  c.tensors["x"] = torch::randn({100, 3});
  c.info = {{"iteration", 1}};
  cls::write_checkpoint(path, c);
  const auto size = fs::file_size(path);
  fs::resize_file(path, size - 10);
  expect_error_naming(path, "truncated data");
  fs::resize_file(path, 12);
  expect_error_naming(path, "truncated header");
  std::ofstream(path, std::ios::binary | std::ios::trunc) << "hello, this is not a checkpoint at all";
  expect_error_naming(path, "garbage");
  // A valid safetensors file that is not a checkpoint (no metadata).
  cls::write_safetensors(path, {{"x", at::kFloat, {2}, torch::zeros({2})}});
  expect_error_naming(path, "plain safetensors");
}

}  // namespace
