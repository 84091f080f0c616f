// The viewer's query latency (issue 12): one text query over N Gaussians answered by `citylangsplat
// view` (ViewerModel::answer: text -> latent, cosine at all three levels for LangSplat's choice of
// level, the city-object ranking) in process and over HTTP on loopback (GET /api/query, and
// /api/scores, the N floats the page recolours with). A model of N Gaussians with random 128-d
// latents, a 512 -> 128 autoencoder, the synthetic text provider (CLIP's text encoder would add its own
// time per new text: bench_clip) and every Gaussian on one of --objects city objects.
// Usage: bench_viewer [--threads 2] [--gaussians 1000000] [--objects 20000] [--queries 10]
// Figures go to docs/benchmarks.md.
#include <ATen/Parallel.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <omp.h>
#include <sys/socket.h>
#include <torch/torch.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <vector>

#include "bench_timer.h"
#include "core/args.h"
#include "core/error.h"
#include "core/heap_reuse.h"
#include "language/language_model.h"
#include "language/provenance.h"
#include "viewer/viewer_model.h"
#include "viewer/viewer_server.h"

namespace cls {
namespace {
namespace fs = std::filesystem;
using bench::Clock;
using bench::seconds_since;

// One GET on a fresh loopback connection; returns the bytes of the reply.
size_t http_get(int port, const std::string& target) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) throw Error("bench_viewer: connect failed");
  const std::string request = "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
  ::send(fd, request.data(), request.size(), MSG_NOSIGNAL);
  std::vector<char> buf(1 << 20);
  size_t total = 0;
  for (ssize_t n; (n = ::recv(fd, buf.data(), buf.size(), 0)) > 0;) total += static_cast<size_t>(n);
  ::close(fd);
  return total;
}

struct Stats {
  std::vector<double> ms;
  void print(const char* what) {
    std::sort(ms.begin(), ms.end());
    std::printf("  %-44s median %7.1f ms  min %7.1f  max %7.1f  (%zu runs)\n", what, ms[ms.size() / 2], ms.front(),
                ms.back(), ms.size());
  }
};

int bench_main(int argc, char** argv) {
  Args args("bench_viewer", "latency of a viewer text query over N Gaussians (in process and over HTTP)", "");
  int threads = 2, objects = 20000, queries = 10;
  int64_t n = 1000000;
  args.bind("threads", threads, "threads (LibTorch)")
      .bind("gaussians", n, "number of Gaussians")
      .bind("objects", objects, "city objects the Gaussians belong to")
      .bind("queries", queries, "distinct query texts (each timed cold, i.e. with its text encoding, and warm)");
  if (!args.parse(argc, argv)) return 0;
  omp_set_num_threads(threads);
  at::set_num_threads(threads);

  const fs::path dir = fs::temp_directory_path() / ("cls_bench_viewer_" + std::to_string(::getpid()));
  {
    torch::manual_seed(1);
    GaussianModel g = make_gaussians(n, 0);
    g.means = torch::randn({n, 3}) * 20;
    g.log_scales = torch::full({n, 3}, -3.0f);
    LanguageModel m{g, {}, Autoencoder(AutoencoderConfig{}, 3), {}, {}};
    for (int l = 0; l < 3; ++l) m.latents[l] = torch::randn({n, 128});
    m.info = {{"method", "citylangsplat"}, {"provider", {{"provider", "synthetic"}, {"seed", 1}, {"dim", 512}}}};
    m.objects.class_names = {"window", "wall", "building"};
    // Buildings of one wall with eight windows each.
    for (int k = 0; k < objects; ++k) {
      const int b = k / 10 * 10;
      const int kind = k % 10;
      m.objects.objects.push_back({"obj" + std::to_string(k), kind == 0 ? 3 : kind == 1 ? 2 : 1,
                                   kind == 0 ? 2 : kind == 1 ? 1 : 0, kind == 0 ? -1 : kind == 1 ? b : b + 1});
    }
    GaussianProvenance p;
    for (int64_t i = 0; i < n; ++i) p.object.push_back(static_cast<int32_t>(i % objects)), p.support.push_back(1.0f);
    attach_provenance(m.gaussians, p);
    save_language_model(dir.string(), m);
  }
  const auto t_load = Clock::now();
  ViewerModel model(dir);
  std::printf("bench_viewer: %lld Gaussians, %d city objects, %d threads; model loaded and prepared in %.1f s\n",
              static_cast<long long>(n), objects, threads, seconds_since(t_load));

  ViewerServerOptions options;
  options.out = dir;
  options.assets = dir;
  options.vendor = dir;
  options.port = 0;
  ViewerServer server(model, options);
  const int port = server.bind();
  std::thread serving([&] { server.listen(); });

  Stats cold, warm, fixed, relevancy, http_query, http_scores;
  for (int k = 0; k < queries; ++k) {
    const std::string text = "query text " + std::to_string(k);
    ViewerQuery q;
    q.text = text;
    auto t0 = Clock::now();
    model.answer(q);
    cold.ms.push_back(1e3 * seconds_since(t0));
    t0 = Clock::now();
    model.answer(q);
    warm.ms.push_back(1e3 * seconds_since(t0));
    q.level = "1";
    t0 = Clock::now();
    model.answer(q);
    fixed.ms.push_back(1e3 * seconds_since(t0));
    q.level = "best";
    q.mode = "relevancy";
    t0 = Clock::now();
    model.answer(q);
    relevancy.ms.push_back(1e3 * seconds_since(t0));
    const std::string target = "query%20text%20" + std::to_string(k);
    t0 = Clock::now();
    http_get(port, "/api/query?q=" + target);
    http_query.ms.push_back(1e3 * seconds_since(t0));
    t0 = Clock::now();
    const size_t bytes = http_get(port, "/api/scores?q=" + target);
    http_scores.ms.push_back(1e3 * seconds_since(t0));
    if (bytes < static_cast<size_t>(n) * 4) throw Error("bench_viewer: /api/scores returned too few bytes");
  }
  cold.print("answer, new text (best level, cosine)");
  warm.print("answer, same text again");
  fixed.print("answer, level 1 given");
  relevancy.print("answer, LangSplat relevancy, best level");
  http_query.print("GET /api/query (JSON, top 20 objects)");
  http_scores.print("GET /api/scores (N float32)");
  server.stop();
  serving.join();
  fs::remove_all(dir);
  return 0;
}

}  // namespace
}  // namespace cls

int main(int argc, char** argv) {
  cls::reuse_freed_memory();  // as the CLI does
  try {
    return cls::bench_main(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_viewer: %s\n", e.what());
    return 1;
  }
}
