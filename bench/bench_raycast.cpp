// Raycast throughput at 1920x1080 (cast only, and cast + all three label levels), and the parse
// time of the largest sample city model. Usage: bench_raycast [--threads N] [--repeats N]
// Figures go to docs/benchmarks.md.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "citymodel/citygml_reader.h"
#include "bench_timer.h"
#include "core/args.h"
#include "core/error.h"
#include "core/heap_reuse.h"
#include "raycast/label_maps.h"
#include "raycast/look_at.h"
#include "raycast/raycaster.h"

namespace cls {
namespace {

using bench::Clock;
using bench::cpu_seconds;
using bench::seconds_since;
std::vector<Vec3f> local_vertices(const SemanticMesh& mesh) {
  std::vector<Vec3f> v;
  v.reserve(mesh.vertices.size());
  for (const auto& p : mesh.vertices) v.push_back(Vec3f{float(p[0]), float(p[1]), float(p[2])});
  return v;
}

// Oblique views from four sides (elevation 35 degrees), each moved closer (the box enlarged by
// 10% steps, at most 3x) until the model covers at least 70% of a 1/10-size test image.
std::vector<Pose> oblique_views(const Raycaster& rc, const std::vector<Vec3f>& v, const PinholeCamera& cam) {
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const auto& p : v)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], double(p[k])), hi[k] = std::max(hi[k], double(p[k]));
  const PinholeCamera small{cam.fx / 10, cam.fy / 10, cam.cx / 10, cam.cy / 10, cam.width / 10, cam.height / 10};
  std::vector<Pose> poses;
  std::vector<RayHit> hits;
  for (int side = 0; side < 4; ++side) {
    Pose pose;
    for (double fill = 1.0; fill < 3.0; fill *= 1.1) {
      pose = frame_box(lo, hi, cam, M_PI / 4 + side * M_PI / 2, 35 * M_PI / 180, fill);
      rc.cast_view(small, pose, hits);
      const auto hit = std::count_if(hits.begin(), hits.end(), [](const RayHit& h) { return h.prim != kNoHit; });
      if (hit >= 0.7 * hits.size()) break;
    }
    poses.push_back(pose);
  }
  return poses;
}

void bench_model(const std::string& label, const std::string& path, int repeats) {
  const Taxonomy taxonomy = Taxonomy::builtin();
  const SemanticMesh mesh = read_citygml(path, taxonomy, 0);
  const std::vector<Vec3f> vertices = local_vertices(mesh);
  const auto t_build = Clock::now();
  const Raycaster rc(vertices, mesh.triangles, opening_priority(mesh));
  const double build_s = seconds_since(t_build);
  const LabelTable table(mesh);
  const PinholeCamera cam{1600, 1600, 960, 540, 1920, 1080};
  const std::vector<Pose> poses = oblique_views(rc, vertices, cam);

  std::vector<RayHit> hits;
  LabelMaps maps;
  rc.cast_view(cam, poses[0], hits);  // warm-up: page in the output buffers
  table.fill(hits, cam.width, cam.height, maps);
  double cast_s = 0, label_s = 0, cast_cpu = 0, label_cpu = 0;
  size_t hit_pixels = 0, rays = 0;
  for (int r = 0; r < repeats; ++r)
    for (const Pose& pose : poses) {
      const auto t0 = Clock::now();
      const double c0 = cpu_seconds();
      rc.cast_view(cam, pose, hits);
      const auto t1 = Clock::now();
      const double c1 = cpu_seconds();
      table.fill(hits, cam.width, cam.height, maps);
      cast_s += std::chrono::duration<double>(t1 - t0).count();
      label_s += seconds_since(t1);
      cast_cpu += c1 - c0;
      label_cpu += cpu_seconds() - c1;
      rays += hits.size();
      if (r == 0)
        for (const auto& h : hits) hit_pixels += h.prim != kNoHit;
    }
  const double hit_fraction = double(hit_pixels) / (poses.size() * hits.size());
  const int threads = omp_get_max_threads();
  std::printf("| %s | %zu | %.0f ms | %.1f%% | %.1f | %.1f | %.1f | %.1f |\n", label.c_str(), mesh.num_triangles(),
              1e3 * build_s, 100 * hit_fraction, rays / cast_s / 1e6, rays / (cast_s + label_s) / 1e6,
              threads * rays / cast_cpu / 1e6, threads * rays / (cast_cpu + label_cpu) / 1e6);
}

void bench_parse(const std::string& path, int repeats) {
  const Taxonomy taxonomy = Taxonomy::builtin();
  std::vector<double> times;
  size_t triangles = 0;
  for (int r = 0; r < std::max(3, repeats); ++r) {
    const auto t0 = Clock::now();
    triangles = read_citygml(path, taxonomy, 0).num_triangles();
    times.push_back(seconds_since(t0));
  }
  std::sort(times.begin(), times.end());
  std::printf("parse %s: median %.1f ms over %zu runs (min %.1f ms), %zu triangles\n", path.c_str(),
              1e3 * times[times.size() / 2], times.size(), 1e3 * times.front(), triangles);
}

}  // namespace
}  // namespace cls

int main(int argc, char** argv) {
  cls::reuse_freed_memory();  // as the CLI does
  cls::Args args("bench_raycast",
                 "Raycast throughput (Mrays/s) at 1920x1080 with and without the label maps, for FZK-Haus LoD3, "
                 "the 100 LoD2 buildings and the citygml4j LoD3 building, and the parse time of the largest "
                 "sample file. Prints Markdown rows for docs/benchmarks.md.",
                 "");
  int threads = 2, repeats = 5;
  args.bind("threads", threads, "OpenMP threads").bind("repeats", repeats, "repeats of the 4 views");
  try {
    if (!args.parse(argc, argv)) return 0;
    if (threads < 1 || repeats < 1) throw cls::UsageError("bench_raycast: --threads and --repeats must be positive");
  } catch (const cls::UsageError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  omp_set_num_threads(threads);
  const std::string data = CLS_DATA_DIR;
  try {
    std::printf("raycast at 1920x1080, %d threads, 4 oblique views x %d repeats\n\n", threads, repeats);
    std::printf("| model | triangles | BVH build | hit pixels | cast Mrays/s | cast + labels Mrays/s "
                "| cast, CPU-normalised | cast + labels, CPU-normalised |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    cls::bench_model("FZK-Haus LoD3", data + "/citygml/fzk-haus/fzk_haus_lod3_v2.gml", repeats);
    cls::bench_model("100 LoD2 buildings", data + "/citygml/citygml4j/lod2_buildings_v3.gml", repeats);
    cls::bench_model("citygml4j LoD3 building", data + "/citygml/citygml4j/lod3_building_v2.gml", repeats);
    std::printf("\n");
    cls::bench_parse(data + "/citygml/citygml4j/lod3_building_v2.gml", repeats);
  } catch (const cls::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
