// City-object provenance per Gaussian (language/provenance.h) on hand-written label maps: three views
// of 2 x 2 pixels with the same camera, so every vote is known by hand.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <filesystem>

#include "core/error.h"
#include "core/npy.h"
#include "language/provenance.h"
#include "raycast/label_map_io.h"

namespace cls {
namespace {
namespace fs = std::filesystem;

struct HandViews {
  fs::path labels;
  Scene scene;

  // objects[v] is view v's object map (row-major 2 x 2); every pixel's surface lies at depth 5.
  explicit HandViews(const std::vector<std::vector<int32_t>>& objects) {
    labels = fs::temp_directory_path() /
             ("cls_provenance_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(labels);
    for (size_t v = 0; v < objects.size(); ++v) {
      SceneView view;
      view.name = "v" + std::to_string(v) + ".png";
      view.camera = PinholeCamera{1, 1, 1, 1, 2, 2};  // pixel u = floor(x / z + 1)
      scene.views.push_back(view);
      const fs::path dir = labels / ("v" + std::to_string(v));
      fs::create_directories(dir);
      write_pfm(dir / "depth.pfm", {5, 5, 5, 5}, 2, 2);
      write_npy(dir / "object.npy", make_npy<int32_t>({2, 2}, objects[v]));
    }
  }
  ~HandViews() { fs::remove_all(labels); }
};

GaussianModel gaussians_at(const std::vector<std::array<float, 3>>& centres) {
  GaussianModel g = make_gaussians(static_cast<int64_t>(centres.size()), 0);
  for (size_t i = 0; i < centres.size(); ++i)
    for (int d = 0; d < 3; ++d) g.means[i][d] = centres[i][d];
  g.log_scales.fill_(std::log(0.01));  // tolerance max(0.02 * 5, 3 * 0.01) = 0.1 at depth 5
  return g;
}

TEST(Provenance, MajorityOverTheViewsWhereTheCentreLiesOnTheSurface) {
  // Pixels: (0,0) top left, (1,0) top right, (0,1) bottom left, (1,1) bottom right.
  const HandViews views({{1, -1, 4, 7}, {1, -1, 2, 7}, {0, 3, -1, 7}});
  const GaussianModel g = gaussians_at({
      {-2.5, -2.5, 5},   // (0,0): votes 1, 1, 0 -> 1 with 2 of 3
      {2.5, -2.5, 5},    // (1,0): none, none, 3 -> none (more votes than any object)
      {-2.5, 2.5, 5},    // (0,1): 4, 2, none -> a tie of one vote each: the lower index, 2
      {2.5, 2.5, 5.5},   // (1,1) half a metre behind the surface: hidden, no vote
      {2.5, 2.5, 5.05},  // (1,1) within the tolerance: 7
      {20, 0, 5},        // outside every image
      {0, 0, -5},        // behind the camera
  });
  const GaussianProvenance p = assign_provenance(g, views.scene, views.labels);
  EXPECT_EQ(p.object, (std::vector<int32_t>{1, -1, 2, -1, 7, -1, -1}));
  ASSERT_EQ(p.support.size(), 7u);
  EXPECT_FLOAT_EQ(p.support[0], 2.0f / 3);
  EXPECT_FLOAT_EQ(p.support[1], 2.0f / 3);  // the share of the "none" votes
  EXPECT_FLOAT_EQ(p.support[2], 1.0f / 3);
  EXPECT_FLOAT_EQ(p.support[3], 0.0f);
  EXPECT_FLOAT_EQ(p.support[4], 1.0f);
  EXPECT_FLOAT_EQ(p.support[5], 0.0f);
  EXPECT_EQ(p.assigned, 3);
  EXPECT_EQ(p.views, 3u);

  // A larger Gaussian reaches further: scale 0.5 gives a tolerance of 1.5, so the hidden one votes.
  GaussianModel big = g;
  big.log_scales.fill_(std::log(0.5));
  EXPECT_EQ(assign_provenance(big, views.scene, views.labels).object[3], 7);

  GaussianModel attached = g;
  attach_provenance(attached, p);
  attach_provenance(attached, p);  // replaces, never duplicates
  ASSERT_EQ(attached.extras.size(), 2u);
  EXPECT_EQ(attached.extra(kObjectProperty)->values.scalar_type(), torch::kInt32);
  EXPECT_EQ(attached.extra(kObjectProperty)->values[2].item<int32_t>(), 2);
}

TEST(Provenance, MissingOrMisfitObjectMapsNameTheFile) {
  const HandViews views({{1, 1, 1, 1}});
  const GaussianModel g = gaussians_at({{0, 0, 5}});
  fs::remove(views.labels / "v0" / "object.npy");
  try {
    assign_provenance(g, views.scene, views.labels);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("object.npy"), std::string::npos) << e.what();
  }
  write_npy(views.labels / "v0" / "object.npy", make_npy<int32_t>({1, 4}, {1, 1, 1, 1}));
  EXPECT_THROW(assign_provenance(g, views.scene, views.labels), Error);
}

}  // namespace
}  // namespace cls
