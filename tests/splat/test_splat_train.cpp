// Photometric training through the CLI on a tiny synthetic scene: the held-out PSNR rises, and a run
// interrupted by SIGINT or killed by SIGKILL and then resumed ends bit-identical to an uninterrupted
// one. The tests run the trainer with OMP_NUM_THREADS=1: the CPU backward adds per-tile gradient sums
// in thread-completion order, so with several threads two runs may differ in the last bits.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>
#include <vector>

#include "cli_runner.h"
#include "core/atomic_file.h"
#include "core/metrics_log.h"
#include "scene/scene.h"
#include "splat/ply_gaussians.h"

namespace fs = std::filesystem;
using cls::test::run_cli;

namespace {

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

fs::path temp_root() {
  static const fs::path root = [] {
    const fs::path d = fs::temp_directory_path() / ("cls_train_rgb_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
  }();
  return root;
}

// 16 views of 96x72 (every 8th held out: 2 test views), ~700 sparse points.
const fs::path& scene_dir() {
  static const fs::path dir = [] {
    const fs::path d = temp_root() / "scene";
    const auto r = run_cli("-q synth --city " + kFzk + " --out " + d.string() +
                           " --views 16 --width 96 --height 72 --gt-density 10 --points-per-view 60 --seed 3");
    EXPECT_EQ(r.status, 0) << r.err;
    return d;
  }();
  return dir;
}

// A short schedule that still densifies (clone, split, prune) and raises the SH degree.
const std::string kSchedule =
    " --densify-from 30 --densify-until 120 --densify-every 20 --sh-increase-every 40 --opacity-reset-every 60"
    " --random-background --seed 5 --device cpu";  // CPU: bit-exact (CUDA adds with atomics)

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(cls::read_text_file(p)); }

// fork/exec of the CLI with OMP_NUM_THREADS=1 and quiet output; returns the child's pid.
// stderr goes to `err_path` (or /dev/null).
pid_t spawn(const std::vector<std::string>& args, const std::string& err_path = "") {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setenv("OMP_NUM_THREADS", "1", 1);
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, 1);
    ::dup2(err_path.empty() ? devnull : ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(CLS_BINARY));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(CLS_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

std::vector<std::string> split_args(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string a; in >> a;) out.push_back(a);
  return out;
}

int wait_status(pid_t pid, bool* signalled = nullptr, int* signal = nullptr) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (signalled) *signalled = WIFSIGNALED(status);
  if (signal) *signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Starts a run, sends `sig` once its first checkpoint exists, waits for it to end.
int run_and_signal(const std::string& args, const fs::path& out, int sig, bool* signalled,
                   const std::string& err_path = "") {
  const fs::path checkpoint = out / "checkpoints" / "checkpoint.safetensors";
  const pid_t pid = spawn(split_args(args), err_path);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(checkpoint) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ::kill(pid, sig);
  return wait_status(pid, signalled);
}

std::string train_args(const fs::path& out, int iterations, int checkpoint_every) {
  return "-q train-rgb --scene " + scene_dir().string() + " --out " + out.string() + " --iterations " +
         std::to_string(iterations) + " --checkpoint-every " + std::to_string(checkpoint_every) + kSchedule;
}

// The uninterrupted reference run of the resume tests (computed once).
const fs::path& straight_run() {
  static const fs::path out = [] {
    const fs::path o = temp_root() / "straight";
    const pid_t pid = spawn(split_args(train_args(o, 160, 0)));
    EXPECT_EQ(wait_status(pid), 0);
    return o;
  }();
  return out;
}

// The training curve (metrics.jsonl): a row per iteration (the interval is 1 below 600 iterations), the
// held-out scores on every 10th row and the last; the last equal to summary.json's.
std::vector<nlohmann::json> expect_curve(const fs::path& out, int iterations) {
  const std::vector<nlohmann::json> rows = cls::read_metrics(out / "metrics.jsonl");
  EXPECT_EQ(rows.size(), size_t(iterations));
  for (size_t i = 0; i < rows.size(); ++i) {
    const int it = int(i) + 1;
    EXPECT_EQ(rows[i]["iteration"], it);
    for (const char* key : {"loss", "l1", "psnr", "gaussians", "sh_degree", "seconds"})
      EXPECT_TRUE(rows[i].contains(key)) << key << " missing at iteration " << it;
    EXPECT_EQ(rows[i].contains("test_psnr"), it % 10 == 0 || it == iterations) << "iteration " << it;
  }
  if (!rows.empty())
    EXPECT_EQ(rows.back()["test_psnr"].get<double>(), read_json(out / "summary.json")["test_psnr"].get<double>());
  return rows;
}

void expect_same_result(const fs::path& a, const fs::path& b) {
  ASSERT_TRUE(fs::exists(a / "point_cloud.ply"));
  ASSERT_TRUE(fs::exists(b / "point_cloud.ply"));
  EXPECT_EQ(cls::read_text_file(a / "point_cloud.ply"), cls::read_text_file(b / "point_cloud.ply"))
      << "the resumed model differs from the uninterrupted one";
  const auto sa = read_json(a / "summary.json"), sb = read_json(b / "summary.json");
  EXPECT_EQ(sa["test_psnr"].get<double>(), sb["test_psnr"].get<double>());
  EXPECT_EQ(sa["gaussians"], sb["gaussians"]);
  EXPECT_EQ(sa["iterations"], 160);
  EXPECT_EQ(sb["iterations"], 160);
  // The resumed curve is that of one uninterrupted run: the rows a killed run wrote after its last
  // checkpoint were dropped; values are bit-identical, only the clock differs.
  const std::vector<nlohmann::json> ra = expect_curve(a, 160), rb = expect_curve(b, 160);
  for (size_t i = 0; i < std::min(ra.size(), rb.size()); ++i) {
    nlohmann::json x = ra[i], y = rb[i];
    x.erase("seconds");
    y.erase("seconds");
    EXPECT_EQ(x, y) << "row " << i;
  }
}

}  // namespace

TEST(TrainRgbCli, HeldOutPsnrRisesAndOutputsAreWritten) {
  const fs::path untrained = temp_root() / "untrained", trained = temp_root() / "trained";
  auto r0 = run_cli("-q train-rgb --scene " + scene_dir().string() + " --out " + untrained.string() + " --iterations 0");
  ASSERT_EQ(r0.status, 0) << r0.err;
  auto r1 = run_cli("-q train-rgb --scene " + scene_dir().string() + " --out " + trained.string() +
                    " --iterations 250 --checkpoint-every 0 --densify-from 50 --densify-until 200 --densify-every 50");
  ASSERT_EQ(r1.status, 0) << r1.err;
  const auto s0 = read_json(untrained / "summary.json"), s1 = read_json(trained / "summary.json");
  EXPECT_EQ(s1["test_views"], 2);
  EXPECT_EQ(s1["iterations"], 250);
  EXPECT_EQ(s1["evaluated_on"], "test");
  const double psnr0 = s0["test_psnr"].get<double>(), psnr1 = s1["test_psnr"].get<double>();
  EXPECT_GT(psnr1, psnr0 + 4.0) << "initial " << psnr0 << " dB, trained " << psnr1 << " dB";
  EXPECT_GT(s1["test_ssim"].get<double>(), s0["test_ssim"].get<double>());
  // Densification changed the model; the PLY is the standard layout (degree-3 SH: 45 f_rest).
  EXPECT_NE(s1["gaussians"], s0["gaussians"]);
  const std::string ply = cls::read_text_file(trained / "point_cloud.ply");
  EXPECT_NE(ply.find("property float f_rest_44"), std::string::npos);
  EXPECT_NE(ply.find("element vertex " + std::to_string(s1["gaussians"].get<int64_t>())), std::string::npos);
  EXPECT_TRUE(fs::exists(trained / "checkpoints" / "checkpoint.safetensors"));
  expect_curve(trained, 250);
  expect_curve(untrained, 0);
}

// Zero iterations: the written model is the initialisation (create_from_pcd), checked against the
// scene's points with a brute-force nearest-neighbour search; the extent against getNerfppNorm.
TEST(TrainRgbCli, InitialisationFromSparsePoints) {
  const fs::path out = temp_root() / "init";
  auto r = run_cli("-q train-rgb --scene " + scene_dir().string() + " --out " + out.string() + " --iterations 0");
  ASSERT_EQ(r.status, 0) << r.err;
  const cls::Scene scene = cls::load_scene(scene_dir().string());
  const cls::GaussianModel g = cls::read_gaussians_ply((out / "point_cloud.ply").string());
  ASSERT_EQ(g.size(), int64_t(scene.points.size()));
  ASSERT_EQ(g.sh_degree(), 3);
  const double C0 = 0.28209479177387814;
  for (size_t i = 0; i < scene.points.size(); i += 37) {
    const auto& p = scene.points[i];
    std::vector<double> d2;
    for (size_t j = 0; j < scene.points.size(); ++j)
      if (j != i) {
        const auto& q = scene.points[j];
        d2.push_back((p.xyz.x - q.xyz.x) * (p.xyz.x - q.xyz.x) + (p.xyz.y - q.xyz.y) * (p.xyz.y - q.xyz.y) +
                     (p.xyz.z - q.xyz.z) * (p.xyz.z - q.xyz.z));
      }
    std::partial_sort(d2.begin(), d2.begin() + 3, d2.end());
    const double want_log_scale = 0.5 * std::log(std::max(1e-7, (d2[0] + d2[1] + d2[2]) / 3));
    const int64_t k = int64_t(i);
    EXPECT_NEAR(g.means[k][0].item<double>(), p.xyz.x, 1e-4 * (1 + std::abs(p.xyz.x)));
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(g.log_scales[k][a].item<double>(), want_log_scale, 1e-4) << i;
    EXPECT_NEAR(g.opacity_logits[k][0].item<double>(), std::log(0.1 / 0.9), 1e-6);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(g.sh_dc[k][0][c].item<double>(), (p.rgb[size_t(c)] / 255.0 - 0.5) / C0, 1e-5);
    EXPECT_EQ(g.quats[k][0].item<float>(), 1.0f);
    EXPECT_EQ(g.sh_rest[k].abs().sum().item<float>(), 0.0f);
  }
  // getNerfppNorm over the training views (sorted by name, every 8th held out).
  std::vector<const cls::SceneView*> views;
  for (const auto& v : scene.views) views.push_back(&v);
  std::sort(views.begin(), views.end(), [](auto* a, auto* b) { return a->name < b->name; });
  std::vector<cls::Vec3d> centres;
  for (size_t i = 0; i < views.size(); ++i)
    if (i % 8 != 0) centres.push_back(views[i]->pose.center());
  cls::Vec3d mean{0, 0, 0};
  for (const auto& c : centres) mean = mean + c;
  mean = (1.0 / double(centres.size())) * mean;
  double radius = 0;
  for (const auto& c : centres) radius = std::max(radius, cls::norm(c - mean));
  EXPECT_NEAR(read_json(out / "summary.json")["extent"].get<double>(), 1.1 * radius, 1e-9 * radius);
}

TEST(TrainRgbCli, SigintThenResumeEqualsUninterruptedRun) {
  const fs::path out = temp_root() / "sigint";
  bool signalled = true;
  const std::string err = (temp_root() / "sigint.err").string();
  const int status = run_and_signal(train_args(out, 160, 10), out, SIGINT, &signalled, err);
  ASSERT_FALSE(signalled);
  ASSERT_EQ(status, 130) << "the run should stop on SIGINT with a checkpoint (did it finish first?)";
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  EXPECT_NE(cls::read_text_file(err).find("--resume"), std::string::npos) << cls::read_text_file(err);
  const pid_t pid = spawn(split_args(train_args(out, 160, 10) + " --resume"));
  ASSERT_EQ(wait_status(pid), 0);
  expect_same_result(straight_run(), out);
}

TEST(TrainRgbCli, SigkillThenResumeEqualsUninterruptedRun) {
  const fs::path out = temp_root() / "sigkill";
  bool signalled = false;
  run_and_signal(train_args(out, 160, 10), out, SIGKILL, &signalled);
  ASSERT_TRUE(signalled) << "the run finished before the kill";
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  const pid_t pid = spawn(split_args(train_args(out, 160, 10) + " --resume"));
  ASSERT_EQ(wait_status(pid), 0);
  expect_same_result(straight_run(), out);
}

TEST(TrainRgbCli, UsageErrors) {
  EXPECT_EQ(run_cli("train-rgb --out /tmp/x").status, 2);
  EXPECT_EQ(run_cli("train-rgb --scene " + scene_dir().string()).status, 2);
  const auto r = run_cli("train-rgb --scene " + scene_dir().string() + " --out " + (temp_root() / "none").string() +
                         " --resume");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("no checkpoint to resume from"), std::string::npos) << r.err;
  const auto help = run_cli("train-rgb --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("(default: 30000)"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("--max-gaussians"), std::string::npos);
}

namespace {
// Each test process (ctest runs one test per process) removes its own temporary tree at exit.
class RemoveTempRoot : public ::testing::Environment {
 public:
  void TearDown() override { fs::remove_all(temp_root()); }
};
const auto* const kRemoveTempRoot = ::testing::AddGlobalTestEnvironment(new RemoveTempRoot);
}  // namespace
