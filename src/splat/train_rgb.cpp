#include "splat/train_rgb.h"

#include <torch/torch.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <random>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "core/metrics_log.h"
#include "core/progress.h"
#include "core/run_layout.h"
#include "scene/image_loader.h"
#include "scene/view_selection.h"
#include "splat/adam.h"
#include "splat/checkpoint.h"
#include "splat/compute_device.h"
#include "splat/densify.h"
#include "splat/image_tensor.h"
#include "splat/model_layout.h"
#include "splat/ply_gaussians.h"
#include "splat/rasterize.h"
#include "splat/sh.h"
#include "splat/ssim.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

constexpr int kCheckpointVersion = 1;

// A view's photo is held as 8-bit RGB (a quarter of float's memory: 200 photos of 1600x1200 take 1.2 GB,
// not 4.6) and converted when it is compared.
struct View {
  const SceneView* view = nullptr;
  at::Tensor stored;  // H x W x 3 uint8 RGB
  at::Tensor image() const { return stored.to(at::kFloat).div_(255.0f); }  // H x W x 3 float in [0, 1]
};

// getNerfppNorm: 1.1 x the largest distance of a camera centre from the centres' mean.
double scene_extent(const std::vector<View>& views) {
  Vec3d mean{0, 0, 0};
  for (const View& v : views) mean = mean + v.view->pose.center();
  mean = (1.0 / double(views.size())) * mean;
  double diagonal = 0;
  for (const View& v : views) diagonal = std::max(diagonal, norm(v.view->pose.center() - mean));
  return 1.1 * diagonal;
}

// Mean squared distance to the 3 nearest other points (simple-knn's distCUDA2), clamped at 1e-7.
at::Tensor mean_knn_sq_distance(const at::Tensor& points) {
  const int64_t n = points.size(0);
  const int64_t k = std::min<int64_t>(3, n - 1);
  if (k <= 0) return torch::ones({n});
  at::Tensor out = torch::empty({n});
  constexpr int64_t kChunk = 1024;
  for (int64_t start = 0; start < n; start += kChunk) {
    const int64_t end = std::min(n, start + kChunk);
    at::Tensor d2 = torch::cdist(points.slice(0, start, end), points).pow(2);
    // Exclude each point itself (not its duplicates, which count as neighbours at distance 0).
    d2.index_put_({torch::arange(end - start), torch::arange(start, end)}, INFINITY);
    const at::Tensor nearest = std::get<0>(d2.topk(k, 1, /*largest=*/false));
    out.slice(0, start, end).copy_(nearest.mean(1));
  }
  return out.clamp_min(1e-7);
}

// create_from_pcd: positions and colours of the SfM points, isotropic scales from the neighbours,
// identity rotations, opacity 0.1.
GaussianModel init_from_points(const std::vector<SparsePoint>& points, int sh_degree) {
  const int64_t n = int64_t(points.size());
  GaussianModel g = make_gaussians(n, sh_degree);
  auto means = g.means.accessor<float, 2>();
  auto dc = g.sh_dc.accessor<float, 3>();
  for (int64_t i = 0; i < n; ++i) {
    const SparsePoint& p = points[size_t(i)];
    means[i][0] = float(p.xyz.x);
    means[i][1] = float(p.xyz.y);
    means[i][2] = float(p.xyz.z);
    for (int c = 0; c < 3; ++c) dc[i][0][c] = float((p.rgb[size_t(c)] / 255.0 - 0.5) / kShC0);
  }
  const at::Tensor scale = mean_knn_sq_distance(g.means.to(torch::kFloat64)).sqrt().log().to(torch::kFloat32);
  g.log_scales = scale.unsqueeze(1).repeat({1, 3}).contiguous();
  g.opacity_logits.fill_(std::log(0.1 / 0.9));  // inverse_sigmoid(0.1)
  return g;
}

// get_expon_lr_func without delay: log-linear from init to final over max_steps.
double exponential_lr(int step, double lr_init, double lr_final, int max_steps) {
  if (lr_init == 0 && lr_final == 0) return 0;
  const double t = max_steps > 0 ? std::clamp(double(step) / max_steps, 0.0, 1.0) : 1.0;
  return std::exp(std::log(lr_init) * (1 - t) + std::log(lr_final) * t);
}

const char* const kGroups[] = {"means", "log_scales", "quats", "opacity_logits", "sh_dc", "sh_rest"};

nlohmann::json options_json(const RgbTrainOptions& o) {
  return {{"iterations", o.iterations},
          {"sh_degree", o.sh_degree},
          {"position_lr_init", o.position_lr_init},
          {"position_lr_final", o.position_lr_final},
          {"feature_lr", o.feature_lr},
          {"opacity_lr", o.opacity_lr},
          {"scaling_lr", o.scaling_lr},
          {"rotation_lr", o.rotation_lr},
          {"lambda_dssim", o.lambda_dssim},
          {"densify_from", o.densify_from},
          {"densify_until", o.densify_until},
          {"densify_every", o.densify_every},
          {"densify_grad_threshold", o.densify_grad_threshold},
          {"percent_dense", o.percent_dense},
          {"opacity_reset_every", o.opacity_reset_every},
          {"sh_increase_every", o.sh_increase_every},
          {"max_gaussians", o.max_gaussians},
          {"random_background", o.random_background},
          {"white_background", o.white_background},
          {"test_every", o.test_every},
          {"checkpoint_every", o.checkpoint_every},
          {"seed", o.seed}};
}

// Everything a resumed run needs to continue exactly where the checkpoint was taken.
struct TrainState {
  int iteration = 0;  // completed iterations
  int active_sh_degree = 0;
  std::mt19937_64 rng;
  std::vector<int> view_stack;  // training views not yet used in this epoch (3DGS viewpoint_stack)
  double ema_loss = 0;
  double seconds = 0;  // training time of earlier sessions
};


void save_checkpoint(const std::string& path, const Adam& adam, const DensifyStats& stats, const TrainState& s,
                     const RgbTrainOptions& options) {
  Checkpoint c;
  for (const auto& g : adam.groups()) c.tensors["param." + g.name] = g.param.detach();
  for (const auto& [name, t] : adam.state_tensors()) c.tensors[name] = t;
  c.tensors["stats.grad_accum"] = stats.grad_accum;
  c.tensors["stats.count"] = stats.count;
  c.tensors["stats.max_radii"] = stats.max_radii;
  std::ostringstream rng;
  rng << s.rng;
  c.info = {{"format", "citylangsplat-rgb-checkpoint"},
            {"version", kCheckpointVersion},
            {"iteration", s.iteration},
            {"active_sh_degree", s.active_sh_degree},
            {"rng", rng.str()},
            {"view_stack", s.view_stack},
            {"ema_loss", s.ema_loss},
            {"seconds", s.seconds},
            {"adam", adam.state_scalars()},
            {"options", options_json(options)}};
  write_checkpoint(path, c);
}

void load_checkpoint(const std::string& path, Adam& adam, DensifyStats& stats, TrainState& s, const at::Device& device) {
  const Checkpoint c = read_checkpoint(path);
  if (c.info.value("format", "") != "citylangsplat-rgb-checkpoint")
    fail(path, "not a photometric training checkpoint");
  auto tensor = [&](const std::string& name) -> at::Tensor {
    auto it = c.tensors.find(name);
    if (it == c.tensors.end()) fail(path, "no tensor '" + name + "'");
    return it->second;
  };
  try {
    int64_t n = -1;
    for (const char* name : kGroups) {
      const at::Tensor p = tensor(std::string("param.") + name);
      AdamGroup& g = adam.group(name);
      if (p.dim() != g.param.dim() || p.sizes().slice(1) != g.param.sizes().slice(1) || p.scalar_type() != torch::kFloat)
        fail(path, std::string("tensor 'param.") + name + "' has the wrong shape or type");
      if (n >= 0 && p.size(0) != n) fail(path, std::string("tensor 'param.") + name + "' has a different row count");
      n = p.size(0);
      g.param = p.to(device).clone().set_requires_grad(true);
    }
    adam.restore(c.tensors, c.info.at("adam").get<std::map<std::string, double>>(), path);
    stats.grad_accum = tensor("stats.grad_accum").to(device).clone();
    stats.count = tensor("stats.count").to(device).clone();
    stats.max_radii = tensor("stats.max_radii").to(device).clone();
    if (stats.size() != n || stats.count.size(0) != n || stats.max_radii.size(0) != n)
      fail(path, "densification statistics do not match the Gaussian count");
    s.iteration = c.info.at("iteration").get<int>();
    s.active_sh_degree = c.info.at("active_sh_degree").get<int>();
    std::istringstream rng(c.info.at("rng").get<std::string>());
    rng >> s.rng;
    if (rng.fail()) fail(path, "unreadable random generator state");
    s.view_stack = c.info.at("view_stack").get<std::vector<int>>();
    s.ema_loss = c.info.at("ema_loss").get<double>();
    s.seconds = c.info.at("seconds").get<double>();
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("checkpoint metadata incomplete: ") + e.what());
  }
}

at::Tensor background_for(const RgbTrainOptions& o, const at::Device& device) {
  return torch::full({3}, o.white_background ? 1.0f : 0.0f, torch::TensorOptions().device(device));
}

RasterizeSettings settings_for(const SceneView& v, const at::Tensor& background) {
  RasterizeSettings s;
  s.camera = v.camera;
  s.pose = v.pose;
  s.background = background;
  return s;
}

at::Tensor render(const GaussianModel& g, int sh_degree, const SceneView& v, const at::Tensor& background,
                  const at::Tensor& means2d, at::Tensor* radii = nullptr) {
  RasterizeOutput out = rasterize_sh(g.means, g.scales(), g.quats, g.opacities(), g.sh(), sh_degree, means2d,
                                     settings_for(v, background));
  if (radii) *radii = out.radii;
  return out.image;
}

struct ImageScores {
  double psnr = 0, ssim = 0;
};

// Mean PSNR and SSIM of the renders of `views`, clamped to [0, 1].
ImageScores mean_scores(const GaussianModel& g, int sh_degree, const std::vector<View>& views,
                        const at::Tensor& background) {
  ImageScores sum;
  for (const View& v : views) {
    const at::Tensor image = render(g, sh_degree, *v.view, background, {}).clamp(0, 1);
    const at::Tensor truth = v.image();
    sum.psnr += psnr(image, truth);
    sum.ssim += ssim(image, truth).item<double>();
  }
  return {sum.psnr / double(views.size()), sum.ssim / double(views.size())};
}

void check_options(const RgbTrainOptions& o) {
  auto bad = [](const std::string& what) { throw Error("train-rgb: " + what); };
  if (o.out_dir.empty()) bad("no output directory");
  if (o.iterations < 0) bad("iterations must be >= 0");
  if (o.sh_degree < 0 || o.sh_degree > 3) bad("SH degree must be 0..3");
  if (o.densify_every <= 0 || o.opacity_reset_every <= 0 || o.sh_increase_every <= 0)
    bad("densify_every, opacity_reset_every and sh_increase_every must be positive");
  if (o.test_every < 0 || o.checkpoint_every < 0 || o.max_gaussians < 0) bad("negative interval or cap");
  if (o.lambda_dssim < 0 || o.lambda_dssim > 1) bad("lambda_dssim must be in [0, 1]");
  if (o.random_background && o.white_background) bad("random and white background exclude each other");
}

}  // namespace

std::filesystem::path rgb_checkpoint(const std::filesystem::path& out_dir) {
  return RunLayout::checkpoints(out_dir) / "checkpoint.safetensors";
}

int auto_densify_until(int iterations) { return std::min(RgbTrainOptions{}.densify_until, iterations / 2); }

const OptionList<RgbTrainOptions>& rgb_train_options() {
  using O = RgbTrainOptions;
  using R = OptionRole;
  static const OptionList<O> list = [] {
    Codec<int> densify_until = default_codec<int>();
    densify_until.text = [](const int& v) { return v < 0 ? std::string("auto") : std::to_string(v); };
    densify_until.parse = [parse = densify_until.parse](const std::string& s) { return s == "auto" ? -1 : parse(s); };
    OptionList<O> o;
    o.add("out", &O::out_dir, "output directory", R::Location).required()
        .add("iterations", &O::iterations, "training iterations")
        .add("sh-degree", &O::sh_degree, "maximal spherical-harmonics degree (0-3)")
        .add("position-lr-init", &O::position_lr_init, "position learning rate at the start (x scene extent)")
        .add("position-lr-final", &O::position_lr_final, "position learning rate at the end (x scene extent)")
        .add("feature-lr", &O::feature_lr, "SH DC learning rate (higher orders: /20)")
        .add("opacity-lr", &O::opacity_lr, "opacity learning rate")
        .add("scaling-lr", &O::scaling_lr, "log-scale learning rate")
        .add("rotation-lr", &O::rotation_lr, "rotation learning rate")
        .add("lambda-dssim", &O::lambda_dssim, "weight of D-SSIM in the loss (L1 gets 1 - it)")
        .add("densify-from", &O::densify_from, "first densification after this iteration")
        .add("densify-until", &O::densify_until,
             "no densification from this iteration on (auto: " + std::to_string(O{}.densify_until) +
                 ", at most half the iterations, as 3DGS's 15000 of 30000)",
             R::Setting, densify_until)
        .add("densify-every", &O::densify_every, "densification interval (iterations)")
        .add("densify-grad-threshold", &O::densify_grad_threshold, "view-space gradient threshold (NDC units)")
        .add("percent-dense", &O::percent_dense, "clone below / split above this fraction of the scene extent")
        .add("opacity-reset-every", &O::opacity_reset_every, "opacity reset interval (iterations)")
        .add("sh-increase-every", &O::sh_increase_every, "raise the SH degree every this many iterations")
        .add("max-gaussians", &O::max_gaussians, "cap on the number of Gaussians (0 = none)")
        .add("test-every", &O::test_every, "hold out every this-th view for testing (0 = none)")
        .add("checkpoint-every", &O::checkpoint_every,
             "checkpoint interval (iterations, 0 = only at the end / on interrupt)", R::Control)
        .add("seed", &O::seed, "random seed (view order, backgrounds, split samples)")
        .add("device", &O::device, "auto (CUDA where this build and machine have it), cpu or cuda", R::Control)
        .add("random-background", &O::random_background, "a random background colour every iteration")
        .add("white-background", &O::white_background, "white instead of black background")
        .add("resume", &O::resume, "continue from OUT/checkpoints/checkpoint.safetensors", R::Control);
    return o;
  }();
  return list;
}

RgbTrainReport train_rgb(const Scene& scene, const RgbTrainOptions& options) {
  check_options(options);
  const at::Device device = compute_device(options.device);
  torch::NoGradGuard outer_no_grad;  // re-enabled for the forward/backward only
  const auto wall_start = std::chrono::steady_clock::now();
  if (scene.views.empty()) throw Error(scene.root + ": the scene has no views");
  if (scene.points.empty()) throw Error(scene.root + ": the scene has no sparse points to start from");

  const ViewSplit split = split_views(scene, options.test_every);
  std::vector<View> train, test;
  {
    ImageLoader loader;
    Progress progress("load images", scene.views.size(), "images");
    for (const auto& [from, to] : {std::pair(&split.train, &train), std::pair(&split.test, &test)})
      for (const SceneView* sv : *from) {
        to->push_back(View{sv, image_to_tensor_u8(loader.load(*sv)).to(device)});
        progress.advance();
      }
  }
  if (train.empty()) throw Error(scene.root + ": no training views left after holding out every " +
                                 std::to_string(options.test_every) + "th view");
  const double extent = scene_extent(train);
  log_info("train-rgb: " + std::to_string(train.size()) + " training views, " + std::to_string(test.size()) +
           " test views, scene extent " + std::to_string(extent) + ", " + std::to_string(scene.points.size()) +
           " initial Gaussians, on " + device.str());

  // Parameters and their learning rates (3DGS training_setup).
  const GaussianModel init = init_from_points(scene.points, options.sh_degree);
  Adam adam(0.9, 0.999, 1e-15);
  auto leaf = [&](const at::Tensor& t) { return t.to(device).clone().set_requires_grad(true); };
  adam.add("means", leaf(init.means), options.position_lr_init * extent);
  adam.add("log_scales", leaf(init.log_scales), options.scaling_lr);
  adam.add("quats", leaf(init.quats), options.rotation_lr);
  adam.add("opacity_logits", leaf(init.opacity_logits), options.opacity_lr);
  adam.add("sh_dc", leaf(init.sh_dc), options.feature_lr);
  adam.add("sh_rest", leaf(init.sh_rest), options.feature_lr / 20.0);
  DensifyStats stats;
  stats.reset(init.size(), device);
  TrainState state;
  state.rng.seed(options.seed);

  const std::string ckpt = rgb_checkpoint(options.out_dir).string();
  fs::create_directories(options.out_dir);
  if (options.resume) {
    if (!fs::exists(ckpt)) throw Error(ckpt + ": no checkpoint to resume from");
    load_checkpoint(ckpt, adam, stats, state, device);
    log_info("train-rgb: resuming at iteration " + std::to_string(state.iteration) + " with " +
             std::to_string(adam.group("means").param.size(0)) + " Gaussians");
  }

  RgbTrainReport report;
  struct {
    double render = 0, loss = 0, backward = 0;
    int iterations = 0;
  } timing;
  const auto loop_start = std::chrono::steady_clock::now();
  install_interrupt_handlers();
  const at::Tensor fixed_background = background_for(options, device);
  const int start_iteration = state.iteration;
  auto session_seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  };
  auto checkpoint_now = [&](int done) {
    state.iteration = done;
    TrainState snapshot = state;
    snapshot.seconds = state.seconds + session_seconds();
    save_checkpoint(ckpt, adam, stats, snapshot, options);
  };
  // The curves: a row every metrics_every iterations and at the last; the held-out views are rendered
  // on every 10th row and the last. A resume drops the rows a killed run wrote after its checkpoint.
  const fs::path metrics_path = fs::path(options.out_dir) / "metrics.jsonl";
  auto up_to_checkpoint = [&](const nlohmann::json& row) { return row.value("iteration", 0) <= start_iteration; };
  MetricsLog metrics =
      options.resume ? MetricsLog::resume(metrics_path, up_to_checkpoint) : MetricsLog::start(metrics_path);
  const int metrics_every = int(metrics_interval(options.iterations));
  {
    Progress progress("train-rgb", uint64_t(std::max(0, options.iterations - start_iteration)), "it");
    for (int it = start_iteration + 1; it <= options.iterations; ++it) {
      if (interrupt_requested()) {
        checkpoint_now(it - 1);
        report.interrupted = true;
        report.iterations = it - 1;
        break;
      }
      adam.group("means").lr = exponential_lr(it, options.position_lr_init * extent,
                                              options.position_lr_final * extent, options.iterations);
      if (it % options.sh_increase_every == 0 && state.active_sh_degree < options.sh_degree) ++state.active_sh_degree;

      if (state.view_stack.empty()) {
        state.view_stack.resize(train.size());
        std::iota(state.view_stack.begin(), state.view_stack.end(), 0);
      }
      const size_t pick = std::uniform_int_distribution<size_t>(0, state.view_stack.size() - 1)(state.rng);
      const View& view = train[size_t(state.view_stack[pick])];
      state.view_stack.erase(state.view_stack.begin() + std::ptrdiff_t(pick));
      at::Tensor background = fixed_background;
      if (options.random_background) {
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        background = torch::tensor({u(state.rng), u(state.rng), u(state.rng)}).to(device);
      }

      const GaussianModel g = model_from_adam(adam);
      const int64_t n = g.size();
      at::Tensor means2d = torch::zeros({n, 2}, g.means.options()).set_requires_grad(true);
      at::Tensor radii;
      at::Tensor loss_value, l1_value, image;
      const at::Tensor truth = view.image();
      {
        torch::AutoGradMode grad_mode(true);
        const auto t0 = std::chrono::steady_clock::now();
        image = render(g, state.active_sh_degree, *view.view, background, means2d, &radii);
        const auto t1 = std::chrono::steady_clock::now();
        const at::Tensor l1 = (image - truth).abs().mean();
        const at::Tensor loss = (1.0 - options.lambda_dssim) * l1 + options.lambda_dssim * dssim_loss(image, truth);
        const auto t2 = std::chrono::steady_clock::now();
        loss.backward();
        const auto t3 = std::chrono::steady_clock::now();
        loss_value = loss.detach();
        l1_value = l1.detach();
        timing.render += std::chrono::duration<double>(t1 - t0).count();
        timing.loss += std::chrono::duration<double>(t2 - t1).count();
        timing.backward += std::chrono::duration<double>(t3 - t2).count();
      }
      const double loss_d = loss_value.item<double>();
      state.ema_loss = it == 1 ? loss_d : 0.4 * loss_d + 0.6 * state.ema_loss;

      // Not at the last iteration: no step follows to train what a densification adds, and an opacity
      // reset there would be the written model (3,000 iterations on an H100 ended at 9.6 dB PSNR with
      // the reset at 3,000). A later run continuing from this checkpoint does not repeat them.
      if (it < options.densify_until && it < options.iterations) {
        // The original's screen-space gradient is w.r.t. NDC: pixel gradient x (W/2, H/2).
        const double half_w = 0.5 * view.view->camera.width, half_h = 0.5 * view.view->camera.height;
        const at::Tensor grad_px = means2d.grad().defined() ? means2d.grad() : torch::zeros_like(means2d);
        // (columns scaled by scalars: no small tensor copied to the device every iteration)
        const at::Tensor grad_ndc = torch::stack({grad_px.select(1, 0) * half_w, grad_px.select(1, 1) * half_h}, 1);
        add_densification_stats(stats, grad_ndc, radii);
        if (it > options.densify_from && it % options.densify_every == 0) {
          DensifyOptions d;
          d.grad_threshold = options.densify_grad_threshold;
          d.percent_dense = options.percent_dense;
          d.extent = extent;
          d.prune_large = it > options.opacity_reset_every;  // train.py's size_threshold gate
          d.max_gaussians = options.max_gaussians;
          const DensifyResult r = densify_and_prune(adam, stats, d, state.rng);
          log_verbose("train-rgb: iteration " + std::to_string(it) + ": cloned " + std::to_string(r.cloned) +
                      ", split " + std::to_string(r.split) + ", pruned " + std::to_string(r.pruned) + " -> " +
                      std::to_string(adam.group("means").param.size(0)) + " Gaussians");
        }
        if (it % options.opacity_reset_every == 0 || (options.white_background && it == options.densify_from))
          reset_opacity(adam);
      }
      if (it < options.iterations) adam.step();  // densified groups have no gradient: skipped
      adam.zero_grad();
      timing.iterations += 1;

      const double train_psnr = psnr(image.detach().clamp(0, 1), truth);
      const int64_t gaussians = adam.group("means").param.size(0);
      if (it % metrics_every == 0 || it == options.iterations) {
        nlohmann::json row = {{"iteration", it}, {"loss", loss_d}, {"l1", l1_value.item<double>()},
                              {"psnr", train_psnr}, {"gaussians", gaussians}, {"sh_degree", state.active_sh_degree},
                              {"seconds", state.seconds + session_seconds()}};
        if (!test.empty() && (it % (10 * metrics_every) == 0 || it == options.iterations)) {
          const ImageScores s = mean_scores(model_from_adam(adam), state.active_sh_degree, test, fixed_background);
          row["test_psnr"] = s.psnr;
          row["test_ssim"] = s.ssim;
        }
        metrics.append(row);
      }
      char detail[160];
      std::snprintf(detail, sizeof detail, "it %d loss %.4f PSNR %.2f dB %lld Gaussians", it, state.ema_loss,
                    train_psnr, static_cast<long long>(gaussians));
      progress.set_detail(detail);
      progress.advance();
      report.iterations = it;
      if (options.checkpoint_every > 0 && it % options.checkpoint_every == 0 && it < options.iterations)
        checkpoint_now(it);
    }
    if (options.iterations <= start_iteration) report.iterations = start_iteration;
  }
  const double loop_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count();
  const double ms_per_iteration = timing.iterations > 0 ? 1000.0 * loop_seconds / timing.iterations : 0.0;
  if (timing.iterations > 0) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "train-rgb: %.1f ms/iteration (render %.1f, loss %.1f, backward %.1f, rest %.1f)",
                  ms_per_iteration, 1000 * timing.render / timing.iterations, 1000 * timing.loss / timing.iterations,
                  1000 * timing.backward / timing.iterations,
                  ms_per_iteration - 1000 * (timing.render + timing.loss + timing.backward) / timing.iterations);
    log_info(buf);
  }
  const double seconds = state.seconds + session_seconds();
  report.seconds = seconds;
  report.gaussians = adam.group("means").param.size(0);
  if (report.interrupted) {
    log_info("train-rgb: interrupted; checkpoint at iteration " + std::to_string(report.iterations) + " in " + ckpt);
    return report;
  }

  // Held-out evaluation (train views when nothing is held out), renders clamped to [0, 1].
  const GaussianModel g = model_from_adam(adam);
  const ImageScores scores = mean_scores(g, state.active_sh_degree, test.empty() ? train : test, fixed_background);
  report.test_views = int(test.size());
  report.test_psnr = scores.psnr;
  report.test_ssim = scores.ssim;

  GaussianModel out;
  out.means = g.means.detach();
  out.log_scales = g.log_scales.detach();
  out.quats = g.quats.detach();
  out.opacity_logits = g.opacity_logits.detach();
  out.sh_dc = g.sh_dc.detach();
  out.sh_rest = g.sh_rest.detach();
  const fs::path ply = fs::path(options.out_dir) / "point_cloud.ply";
  write_gaussians_ply(ply.string(), out);
  write_model_layout(options.out_dir, ply, scene,
                     {report.iterations, options.sh_degree, options.test_every, options.white_background});
  const nlohmann::json summary = {{"iterations", report.iterations},
                                  {"gaussians", report.gaussians},
                                  {"test_psnr", report.test_psnr},
                                  {"test_ssim", report.test_ssim},
                                  {"test_views", report.test_views},
                                  {"evaluated_on", test.empty() ? "train" : "test"},
                                  {"seconds", report.seconds},
                                  {"ms_per_iteration", ms_per_iteration},
                                  {"scene", scene.root},
                                  {"extent", extent},
                                  {"device", device.str()},
                                  {"options", options_json(options)}};
  write_text_atomic(fs::path(options.out_dir) / "summary.json", summary.dump(2) + "\n");
  // The final state, so that a later run with more iterations can continue from it.
  checkpoint_now(report.iterations);
  return report;
}

}  // namespace cls
