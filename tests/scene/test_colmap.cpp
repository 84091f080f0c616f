#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include "core/atomic_file.h"
#include "core/error.h"
#include "scene/colmap.h"
#include "scene_test_util.h"

namespace fs = std::filesystem;
using namespace cls;
using cls::test::expect_error;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// Field-by-field equality; doubles must match bit for bit.
void expect_same_model(const ColmapModel& a, const ColmapModel& b) {
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (const auto& [id, c] : a.cameras) {
    const Camera& d = b.cameras.at(id);
    EXPECT_EQ(c.id, d.id);
    EXPECT_EQ(c.model, d.model);
    EXPECT_EQ(c.width, d.width);
    EXPECT_EQ(c.height, d.height);
    ASSERT_EQ(c.params.size(), d.params.size());
    for (size_t i = 0; i < c.params.size(); ++i) EXPECT_TRUE(same_bits(c.params[i], d.params[i])) << i;
  }
  ASSERT_EQ(a.images.size(), b.images.size());
  for (const auto& [id, im] : a.images) {
    const ColmapImage& jm = b.images.at(id);
    EXPECT_EQ(im.id, jm.id);
    EXPECT_EQ(im.camera_id, jm.camera_id);
    EXPECT_EQ(im.name, jm.name);
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(same_bits(im.qvec[i], jm.qvec[i]));
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(same_bits(im.tvec[i], jm.tvec[i]));
    ASSERT_EQ(im.points2d.size(), jm.points2d.size());
    for (size_t i = 0; i < im.points2d.size(); ++i) {
      EXPECT_TRUE(same_bits(im.points2d[i].x, jm.points2d[i].x));
      EXPECT_TRUE(same_bits(im.points2d[i].y, jm.points2d[i].y));
      EXPECT_EQ(im.points2d[i].point3d_id, jm.points2d[i].point3d_id);
    }
  }
  ASSERT_EQ(a.points.size(), b.points.size());
  for (const auto& [id, p] : a.points) {
    const ColmapPoint3D& q = b.points.at(id);
    EXPECT_EQ(p.id, q.id);
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(same_bits(p.xyz[i], q.xyz[i]));
    EXPECT_EQ(p.rgb, q.rgb);
    EXPECT_TRUE(same_bits(p.error, q.error));
    EXPECT_EQ(p.track, q.track);
  }
}

// A model with awkward doubles (tiny, huge, many digits) in every field, one camera per model.
ColmapModel random_model(uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  auto awkward = [&] { return u(rng) * std::pow(10.0, int(rng() % 30) - 15); };
  ColmapModel m;
  const CameraModel models[] = {CameraModel::SimplePinhole, CameraModel::Pinhole, CameraModel::SimpleRadial,
                                CameraModel::Radial, CameraModel::OpenCV};
  uint32_t cam_id = 3;
  for (CameraModel model : models) {
    Camera c{cam_id, model, 4000 + int(rng() % 100), 3000 + int(rng() % 100), {}};
    for (int i = 0; i < camera_model_num_params(model); ++i) c.params.push_back(i < 2 ? 1000 + u(rng) : awkward());
    m.cameras[cam_id] = c;
    cam_id += 7;
  }
  for (uint32_t i = 1; i <= 6; ++i) {
    ColmapImage im;
    im.id = i * 11;
    im.qvec = {u(rng), u(rng), u(rng), u(rng)};
    im.tvec = {awkward(), awkward(), awkward()};
    im.camera_id = 3 + 7 * (i % 5);
    im.name = i == 2 ? "sub dir/with space " + std::to_string(i) + ".jpg" : "IMG_" + std::to_string(i) + ".JPG";
    for (uint32_t k = 0; k < i * 3; ++k)
      im.points2d.push_back({awkward(), awkward(), k % 3 == 0 ? std::numeric_limits<uint64_t>::max() : rng() % 1000});
    m.images[im.id] = im;
  }
  // image 44 has no 2D points at all: the text writer emits an empty points line for it
  m.images[44] = ColmapImage{44, {1, 0, 0, 0}, {0, 0, 0}, 3, "empty.png", {}};
  for (uint64_t k = 0; k < 20; ++k) {
    ColmapPoint3D p;
    p.id = k * 1000003ull + (k == 19 ? (1ull << 40) : 0);
    p.xyz = {awkward(), awkward(), awkward()};
    p.rgb = {uint8_t(rng()), uint8_t(rng()), 255};
    p.error = std::abs(awkward());
    for (uint32_t t = 0; t < k % 4; ++t) p.track.emplace_back(uint32_t(rng()), uint32_t(rng()));
    m.points[p.id] = p;
  }
  return m;
}

const char* kCamerasTxt =
    "# Camera list with one line of data per camera:\n"
    "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
    "\n"
    "1 SIMPLE_RADIAL 3072 2304 2559.81 1536 1152 -0.0204\n"
    "2 PINHOLE 640 480 500 510.5 320 240\n";
const char* kImagesTxt =
    "# Image list with two lines of data per image:\n"
    "1 0.851773 0.0165051 0.503764 -0.142941 -0.737434 1.02973 3.74354 1 P1180141.JPG\n"
    "2362.39 248.498 58396 1784.7 268.254 -1\n"
    "2 1 0 0 0 1 2 3 2 dir/P1180142.JPG\n"
    "\n";
const char* kPointsTxt =
    "# 3D point list with one line of data per point:\n"
    "58396 1.67241 0.292931 0.609726 115 121 122 1.33927 1 0 2 5\n"
    "7 -1 -2 -3 0 0 255 0.5\n";

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("cls_test_colmap_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(Colmap, HandWrittenTextModelParsesToKnownValues) {
  const auto cams = parse_cameras_text(kCamerasTxt, "cameras.txt");
  ASSERT_EQ(cams.size(), 2u);
  const Camera& c1 = cams.at(1);
  EXPECT_EQ(c1.model, CameraModel::SimpleRadial);
  EXPECT_EQ(c1.width, 3072);
  EXPECT_EQ(c1.height, 2304);
  EXPECT_EQ(c1.params, (std::vector<double>{2559.81, 1536, 1152, -0.0204}));
  EXPECT_EQ(cams.at(2).model, CameraModel::Pinhole);
  EXPECT_EQ(cams.at(2).params, (std::vector<double>{500, 510.5, 320, 240}));

  const auto ims = parse_images_text(kImagesTxt, "images.txt");
  ASSERT_EQ(ims.size(), 2u);
  const ColmapImage& i1 = ims.at(1);
  EXPECT_EQ(i1.qvec, (std::array<double, 4>{0.851773, 0.0165051, 0.503764, -0.142941}));
  EXPECT_EQ(i1.tvec, (std::array<double, 3>{-0.737434, 1.02973, 3.74354}));
  EXPECT_EQ(i1.camera_id, 1u);
  EXPECT_EQ(i1.name, "P1180141.JPG");
  ASSERT_EQ(i1.points2d.size(), 2u);
  EXPECT_EQ(i1.points2d[0].x, 2362.39);
  EXPECT_EQ(i1.points2d[0].point3d_id, 58396u);
  EXPECT_EQ(i1.points2d[1].y, 268.254);
  EXPECT_EQ(i1.points2d[1].point3d_id, std::numeric_limits<uint64_t>::max());
  EXPECT_EQ(ims.at(2).name, "dir/P1180142.JPG");
  EXPECT_TRUE(ims.at(2).points2d.empty());
  // pose(): identity quaternion, t = (1, 2, 3) -> camera centre (-1, -2, -3)
  const Vec3d c = ims.at(2).pose().center();
  EXPECT_DOUBLE_EQ(c.x, -1);
  EXPECT_DOUBLE_EQ(c.y, -2);
  EXPECT_DOUBLE_EQ(c.z, -3);

  const auto pts = parse_points3d_text(kPointsTxt, "points3D.txt");
  ASSERT_EQ(pts.size(), 2u);
  const ColmapPoint3D& p = pts.at(58396);
  EXPECT_EQ(p.xyz, (std::array<double, 3>{1.67241, 0.292931, 0.609726}));
  EXPECT_EQ(p.rgb, (std::array<uint8_t, 3>{115, 121, 122}));
  EXPECT_EQ(p.error, 1.33927);
  EXPECT_EQ(p.track, (std::vector<std::pair<uint32_t, uint32_t>>{{1, 0}, {2, 5}}));
  EXPECT_TRUE(pts.at(7).track.empty());
}

TEST(Colmap, RotationOfAKnownQuaternion) {
  // 90 degrees about z: q = (cos 45, 0, 0, sin 45) maps x to y.
  ColmapImage im;
  im.qvec = {std::sqrt(0.5), 0, 0, std::sqrt(0.5)};
  const Vec3d y = im.pose().R * Vec3d{1, 0, 0};
  EXPECT_NEAR(y.x, 0, 1e-15);
  EXPECT_NEAR(y.y, 1, 1e-15);
  EXPECT_NEAR(y.z, 0, 1e-15);
}

TEST(Colmap, BinaryLayoutOfOneCameraByHand) {
  std::map<uint32_t, Camera> cams;
  cams[7] = Camera{7, CameraModel::Pinhole, 640, 480, {500, 510, 320, 240}};
  const std::string bytes = encode_cameras_binary(cams);
  // u64 count | u32 id | i32 model | u64 w | u64 h | 4 x f64
  ASSERT_EQ(bytes.size(), 8u + 4 + 4 + 8 + 8 + 4 * 8);
  const unsigned char head[] = {1, 0, 0, 0, 0, 0, 0, 0, 7, 0, 0, 0, 1, 0, 0, 0, 0x80, 2, 0, 0, 0, 0, 0, 0,
                                0xe0, 1, 0, 0, 0, 0, 0, 0};
  EXPECT_EQ(std::memcmp(bytes.data(), head, sizeof(head)), 0);
  double fy;
  std::memcpy(&fy, bytes.data() + 32 + 8, 8);
  EXPECT_EQ(fy, 510.0);
}

TEST(Colmap, BinaryRoundTripIsBitExact) {
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    const ColmapModel m = random_model(seed);
    ColmapModel r;
    const std::string cb = encode_cameras_binary(m.cameras), ib = encode_images_binary(m.images),
                      pb = encode_points3d_binary(m.points);
    r.cameras = parse_cameras_binary(cb, "c");
    r.images = parse_images_binary(ib, "i");
    r.points = parse_points3d_binary(pb, "p");
    expect_same_model(m, r);
    EXPECT_EQ(encode_cameras_binary(r.cameras), cb);
    EXPECT_EQ(encode_images_binary(r.images), ib);
    EXPECT_EQ(encode_points3d_binary(r.points), pb);
  }
}

// The text writer prints each double with std::to_chars' shortest representation, which by
// definition parses back to the identical double, so the text round trip is exact too.
TEST(Colmap, TextRoundTripIsExact) {
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    const ColmapModel m = random_model(seed);
    ColmapModel r;
    r.cameras = parse_cameras_text(encode_cameras_text(m.cameras), "c");
    r.images = parse_images_text(encode_images_text(m.images), "i");
    r.points = parse_points3d_text(encode_points3d_text(m.points), "p");
    expect_same_model(m, r);
  }
}

TEST(Colmap, FilesRoundTripAndBinaryIsPreferred) {
  const fs::path d = fresh_dir("files");
  const ColmapModel m = random_model(9);
  write_colmap_text(d.string(), m);
  expect_same_model(m, read_colmap(d.string()));  // text only
  ColmapModel other = m;
  other.points.clear();
  write_colmap_binary(d.string(), other);
  const ColmapModel r = read_colmap(d.string());  // both present: binary wins
  EXPECT_TRUE(r.points.empty());
  expect_same_model(other, r);
  expect_same_model(m, read_colmap_text(d.string()));
  fs::remove_all(d);
}

TEST(Colmap, WriterRejectsInvalidModelAndWritesNothing) {
  const fs::path d = fresh_dir("invalid_write");
  ColmapModel m = random_model(2);
  m.images.begin()->second.camera_id = 999;
  expect_error([&] { write_colmap_binary(d.string(), m); }, {"camera 999"});
  m = random_model(2);
  m.cameras.begin()->second.params.pop_back();
  expect_error([&] { write_colmap_text(d.string(), m); }, {"parameters"});
  EXPECT_TRUE(fs::is_empty(d));
  fs::remove_all(d);
}

TEST(Colmap, UnsupportedModelsAreNamed) {
  expect_error([] { parse_cameras_text("1 OPENCV_FISHEYE 10 10 1 1 5 5 0 0 0 0\n", "cams.txt"); },
               {"cams.txt", "OPENCV_FISHEYE", "SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV"});
  expect_error([] { parse_cameras_text("1 BROWN 10 10 1 1 5 5\n", "cams.txt"); }, {"cams.txt", "BROWN", "OPENCV"});
  std::map<uint32_t, Camera> cams;
  cams[1] = Camera{1, CameraModel::OpenCV, 10, 10, {1, 1, 5, 5, 0, 0, 0, 0}};
  std::string bytes = encode_cameras_binary(cams);
  const std::pair<int32_t, const char*> bad[] = {{5, "OPENCV_FISHEYE"}, {6, "FULL_OPENCV"}, {7, "FOV"}, {42, "id 42"}};
  for (const auto& [id, name] : bad) {
    std::memcpy(&bytes[12], &id, 4);
    expect_error([&] { parse_cameras_binary(bytes, "cameras.bin"); }, {"cameras.bin", name, "supported: SIMPLE_PINHOLE"});
  }
}

TEST(Colmap, TruncatedBinaryIsAnErrorAtEveryLength) {
  const ColmapModel m = random_model(3);
  const std::string files[3] = {encode_cameras_binary(m.cameras), encode_images_binary(m.images),
                                encode_points3d_binary(m.points)};
  for (int f = 0; f < 3; ++f)
    for (size_t n = 0; n < files[f].size(); ++n) {
      const std::string_view cut(files[f].data(), n);
      try {
        if (f == 0) parse_cameras_binary(cut, "model.bin");
        if (f == 1) parse_images_binary(cut, "model.bin");
        if (f == 2) parse_points3d_binary(cut, "model.bin");
        ADD_FAILURE() << "file " << f << " cut at " << n << " parsed";
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("model.bin"), std::string::npos);
      }
    }
}

TEST(Colmap, HugeCountsAreRejectedBeforeAllocating) {
  std::string bytes(8, '\xff');  // 2^64-1 cameras in an 8-byte file
  expect_error([&] { parse_points3d_binary(bytes, "points3D.bin"); }, {"points3D.bin", "truncated or corrupt"});
  // an image announcing 2^60 2D points
  std::map<uint32_t, ColmapImage> ims;
  ims[1] = ColmapImage{1, {1, 0, 0, 0}, {0, 0, 0}, 1, "a.png", {}};
  std::string ib = encode_images_binary(ims);
  const uint64_t huge = 1ull << 60;
  std::memcpy(&ib[ib.size() - 8], &huge, 8);
  expect_error([&] { parse_images_binary(ib, "images.bin"); }, {"images.bin", "2D points"});
}

TEST(Colmap, NaNAndInconsistentValuesAreErrors) {
  std::map<uint32_t, ColmapImage> ims;
  ims[1] = ColmapImage{1, {1, 0, 0, 0}, {0, NAN, 0}, 1, "a.png", {}};
  expect_error([&] { parse_images_binary(encode_images_binary(ims), "images.bin"); }, {"images.bin", "translation"});
  expect_error([] { parse_images_text("1 nan 0 0 0 0 0 0 1 a.png\n\n", "images.txt"); }, {"images.txt", "quaternion"});
  expect_error([] { parse_images_text("1 0 0 0 0 0 0 0 1 a.png\n\n", "images.txt"); }, {"images.txt", "zero rotation"});
  expect_error([] { parse_points3d_text("1 0 inf 0 1 2 3 0\n", "points3D.txt"); }, {"points3D.txt", "non-finite"});
  expect_error([] { parse_cameras_text("1 PINHOLE 10 10 1 1 5\n", "cameras.txt"); },
               {"cameras.txt", "PINHOLE needs 4 parameters, got 3"});
  expect_error([] { parse_cameras_text("1 PINHOLE 10 10 -1 1 5 5\n", "cameras.txt"); }, {"cameras.txt", "focal"});
  expect_error([] { parse_cameras_text("1 PINHOLE 0 10 1 1 5 5\n", "cameras.txt"); }, {"cameras.txt", "size"});
  expect_error([] { parse_cameras_text("1 PINHOLE 10 10 1 1 5 5\n1 PINHOLE 10 10 1 1 5 5\n", "cameras.txt"); },
               {"cameras.txt", "duplicate camera id 1"});
  expect_error([] { parse_cameras_text("1 PINHOLE 10 10 1 1 5 x5\n", "cameras.txt"); }, {"cameras.txt", "line 1", "x5"});
  expect_error([] { parse_images_text("1 1 0 0 0 0 0 0 1 a.png\n1 2\n", "images.txt"); },
               {"images.txt", "line 2", "triples"});
  expect_error([] { parse_points3d_text("1 0 0 0 1 2 300 0\n", "points3D.txt"); }, {"points3D.txt", "300"});
  std::map<uint64_t, ColmapPoint3D> pts;
  pts[5] = ColmapPoint3D{5, {0, 0, 0}, {0, 0, 0}, 0, {}};
  std::string pb = encode_points3d_binary(pts);
  expect_error([&] { parse_points3d_binary(pb + pb.substr(8), "points3D.bin"); }, {"points3D.bin", "trailing"});
  pb[0] = 2;
  expect_error([&] { parse_points3d_binary(pb + pb.substr(8), "points3D.bin"); }, {"points3D.bin", "duplicate point3D id 5"});
}

TEST(Colmap, MissingFilesAndDanglingCameraReferences) {
  const fs::path d = fresh_dir("missing");
  expect_error([&] { read_colmap(d.string()); }, {d.string(), "no COLMAP model"});
  write_text_atomic(d / "cameras.txt", kCamerasTxt);
  expect_error([&] { read_colmap(d.string()); }, {(d / "images.txt").string(), "not found"});
  write_text_atomic(d / "images.txt", "1 1 0 0 0 0 0 0 9 a.png\n\n");
  write_text_atomic(d / "points3D.txt", kPointsTxt);
  expect_error([&] { read_colmap(d.string()); }, {"images", "camera 9"});
  fs::remove_all(d);
}

TEST(Colmap, QvecFromRotationInvertsQuatToRotation) {
  std::mt19937 rng(4);
  std::normal_distribution<double> n(0, 1);
  std::vector<std::array<double, 4>> qs = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}, {1e-9, 0.6, 0.8, 0}};
  for (int i = 0; i < 200; ++i) qs.push_back({n(rng), n(rng), n(rng), n(rng)});
  for (auto q : qs) {
    const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    const double sign = q[0] < 0 ? -1 : 1;
    for (double& c : q) c *= sign / len;
    const auto r = rotation_to_qvec(quat_to_rotation(q[0], q[1], q[2], q[3]));
    // q and -q are the same rotation; w >= 0 picks one unless w is ~0
    const double s = (r[0] * q[0] + r[1] * q[1] + r[2] * q[2] + r[3] * q[3]) < 0 ? -1 : 1;
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(s * r[k], q[k], 1e-12);
    EXPECT_GE(r[0], 0);
  }
}
