// The city model's CRS as its file names it, and the photos' GPS projected into it: EPSG codes from
// every form of name the real samples use, and projections checked against values worked out without
// PROJ (UTM on its central meridian: the meridian arc, scaled).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <random>
#include <string>

#include "citymodel/city_model.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "georef/crs_name.h"
#include "georef/gps_footprint.h"
#include "georef/proj_crs.h"
#include "georef/robust_similarity.h"

using namespace cls;

namespace {

void expect_crs(const std::string& name, int horizontal, int vertical) {
  const std::optional<CrsName> crs = parse_crs_name(name);
  ASSERT_TRUE(crs.has_value()) << name;
  EXPECT_EQ(crs->horizontal_epsg, horizontal) << name;
  EXPECT_EQ(crs->vertical_epsg, vertical) << name;
}

// The GRS80 meridian arc from the equator to `latitude` (degrees), by Simpson's rule over the
// meridian's radius of curvature a (1 - e^2) / (1 - e^2 sin^2 phi)^(3/2).
double meridian_arc(double latitude) {
  const double a = 6378137.0, f = 1 / 298.257222101, e2 = f * (2 - f);
  const double phi = latitude * M_PI / 180;
  const int n = 2000;
  double sum = 0;
  for (int k = 0; k <= n; ++k) {
    const double p = phi * k / n, s = std::sin(p);
    const double rho = a * (1 - e2) / std::pow(1 - e2 * s * s, 1.5);
    sum += rho * (k == 0 || k == n ? 1 : k % 2 ? 4 : 2);
  }
  return sum * phi / (3 * n);
}

}  // namespace

TEST(CrsName, EveryFormTheSamplesAndStandardsUse) {
  expect_crs("EPSG:25832", 25832, 0);
  expect_crs("urn:ogc:def:crs:EPSG::25832", 25832, 0);
  expect_crs("urn:ogc:def:crs:EPSG:6.12:25833", 25833, 0);
  expect_crs("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837", 25832, 7837);
  expect_crs("https://www.opengis.net/def/crs/EPSG/0/7415", 7415, 0);  // compound: RD New + NAP
  expect_crs("urn:adv:crs:ETRS89_UTM33", 25833, 0);
  for (const std::string bad : {"", "local", "urn:adv:crs:DE_DHDN_3GK3", "urn:adv:crs:ETRS89_UTM32*NOPE", "EPSG:5783",
                                "EPSG:99999999", "EPSG:25832 EPSG:25833"})
    EXPECT_FALSE(parse_crs_name(bad).has_value()) << bad;
  // The names as the real samples write them (read from the files).
  const Taxonomy tax = Taxonomy::builtin();
  const std::string data = std::string(CLS_TEST_DATA) + "/citygml/";
  const auto crs_of = [&](const std::string& file) { return load_city_model(data + file, tax, 0).crs; };
  expect_crs(crs_of("fzk-haus/fzk_haus_lod3_v2.gml"), 25832, 5783);        // urn:adv:..._UTM32*DE_DHHN92_NH
  expect_crs(crs_of("nrw/LoD2_32_329_5730_1_NW.gml"), 25832, 7837);         // ...*DE_DHHN2016_NH*GCG2016
  expect_crs(crs_of("citygml4j/lod3_building_v2.gml"), 3068, 5783);         // urn:ogc:def:crs,crs:EPSG:6.12:...
  expect_crs(crs_of("cityjson/texture4.city.json"), 3068, 0);               // http://.../EPSG/0/3068
  expect_crs(crs_of("citygml4j/lod2_buildings_v2.json"), 3068, 0);          // http://.../EPSG/6.12/3068
}

TEST(GpsProjection, UtmOnItsCentralMeridianIsTheScaledMeridianArc) {
  const GpsProjection utm32(25832);  // ETRS89 / UTM 32N: central meridian 9 E, k0 = 0.9996
  for (const double latitude : {0.0, 30.0, 51.0, 54.5}) {
    const auto en = utm32.project(latitude, 9.0);
    EXPECT_NEAR(en[0], 500000.0, 1e-6) << latitude;
    EXPECT_NEAR(en[1], 0.9996 * meridian_arc(latitude), 1e-3) << latitude;
  }
  // East of the meridian the easting grows; the same latitude keeps nearly the same northing.
  const auto east = utm32.project(51.0, 10.0), centre = utm32.project(51.0, 9.0);
  EXPECT_NEAR(east[0] - centre[0], 70000, 1000);  // one degree of longitude at 51 N: about 70 km
}

TEST(GpsProjection, ACompoundCrsProjectsWithItsHorizontalPart) {
  // EPSG:5555 is ETRS89 / UTM 32N + DHHN92 height: the same eastings and northings as EPSG:25832.
  const GpsProjection compound(5555), utm32(25832);
  const auto a = compound.project(51.5, 7.25), b = utm32.project(51.5, 7.25);
  EXPECT_DOUBLE_EQ(a[0], b[0]);
  EXPECT_DOUBLE_EQ(a[1], b[1]);
  EXPECT_NEAR(compound.project(48.0, 9.0)[0], 500000.0, 1e-6);
}

TEST(GpsProjection, CodesItCannotUseAreErrorsNamingThem) {
  EXPECT_EQ(is_vertical_crs(7837), std::optional<bool>(true));
  EXPECT_EQ(is_vertical_crs(25832), std::optional<bool>(false));
  EXPECT_FALSE(is_vertical_crs(99999999).has_value());
  for (const int code : {5783, 99999999}) {
    try {
      GpsProjection p(code);
      ADD_FAILURE() << code;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("EPSG:" + std::to_string(code)), std::string::npos) << e.what();
    }
  }
}

// A project's CRS into a city model's: the OPF specification's example frame (WGS 84 / UTM 16N written as
// WKT, as Pix4D writes it) is EPSG:32616 itself; across a zone boundary the symmetry of transverse
// Mercator: 12 E lies 3 degrees east of zone 32's meridian and 3 degrees west of zone 33's, so its
// eastings mirror about 500 km and its northings agree.
TEST(CrsTransform, AProjectsWktAndANeighbouringZone) {
  const std::string frame = nlohmann::json::parse(read_text_file(CLS_TEST_DATA "/opf/spec-examples/scene-reference-frame.json"))
                                ["crs"]["definition"];
  const CrsTransform same("EPSG:32616", frame, "a test");
  const auto p = same.forward(746308.123, 3714810.973);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR((*p)[0], 746308.123, 1e-6);
  EXPECT_NEAR((*p)[1], 3714810.973, 1e-6);

  const auto in32 = GpsProjection(25832).project(51.0, 12.0);
  const CrsTransform zones("EPSG:25832", "EPSG:25833", "a test");
  const auto in33 = zones.forward(in32[0], in32[1]);
  ASSERT_TRUE(in33.has_value());
  EXPECT_NEAR((*in33)[0] - 500000, -(in32[0] - 500000), 1e-3);
  EXPECT_NEAR((*in33)[1], in32[1], 1e-3);
  const auto back = zones.inverse((*in33)[0], (*in33)[1]);
  EXPECT_NEAR((*back)[0], in32[0], 1e-6);

  try {
    CrsTransform("EPSG:25832", "PROJCRS[\"not a crs", "a test");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not know this coordinate reference system"), std::string::npos) << e.what();
  }
}

// The distance of each fix from the model's bounding box, worked out by hand from the projected
// position: inside 0, beside it the gap on one axis, off a corner the hypotenuse.
TEST(GpsFootprint, DistancesFromTheModelsBoxInItsCrs) {
  const GpsProjection utm32(25832);
  SemanticMesh mesh;
  mesh.origin = {500000, 5650000, 100};
  mesh.vertices = {{-50, -50, 0}, {50, 50, 12}};  // a 100 m box around (500000, 5650000), 100..112 high
  // Positions on the central meridian project to easting 500000 exactly; find latitudes by bisection.
  const auto latitude_at = [&](double northing) {
    double lo = 50, hi = 52;
    for (int k = 0; k < 60; ++k) (utm32.project(0.5 * (lo + hi), 9)[1] < northing ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  };
  GpsFix inside{latitude_at(5650000), 9, 150.0, ""};
  GpsFix north{latitude_at(5650000 + 80), 9, std::nullopt, ""};   // 30 m beyond the box's north side
  GpsFix far_north{latitude_at(5650000 + 250), 9, 90.0, ""};      // 200 m beyond it
  const GpsFootprint f = gps_footprint({inside, north, far_north}, mesh, utm32);
  EXPECT_EQ(f.fixes, 3u);
  EXPECT_NEAR(f.median_distance, 30, 1e-3);
  EXPECT_NEAR(f.max_distance, 200, 1e-3);
  EXPECT_DOUBLE_EQ(f.box[0], 499950);
  EXPECT_DOUBLE_EQ(f.box[3], 5650050);
  EXPECT_DOUBLE_EQ(f.model_heights[1], 112);
  // East of the box by one degree of longitude's share at the box's latitude: the easting gap.
  GpsFix east{latitude_at(5650000), 9.01, std::nullopt, ""};
  const double gap = utm32.project(east.latitude, east.longitude)[0] - 500050;
  EXPECT_NEAR(gps_footprint({east}, mesh, utm32).median_distance, std::hypot(gap, std::max(0.0,
              utm32.project(east.latitude, east.longitude)[1] - 5650050)), 1e-6);
  EXPECT_EQ(gps_footprint({}, mesh, utm32).fixes, 0u);
}

// --- robust_similarity: LMedS + Umeyama against a similarity chosen by hand ---

namespace {

// Points spread in 3D (a camera orbit and its rings), mapped by a known similarity, with noise and
// outliers added to the targets.
struct KnownSimilarity {
  std::vector<Vec3d> source, target;
  std::vector<bool> outlier;
  CityTransform truth = similarity_transform(2.5, axis_angle_to_rotation(Vec3d{0.3, -0.2, 1.1}), {412000, 5621000, 95});
  KnownSimilarity(int n, double noise, double outlier_share, double outlier_metres) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> gauss(0, noise);
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      const Vec3d p{8 * std::cos(a), 8 * std::sin(a), 2.0 + (i % 3)};
      Vec3d q = truth.apply(p) + Vec3d{gauss(rng), gauss(rng), gauss(rng)};
      const bool out = i < static_cast<int>(std::lround(outlier_share * n));
      if (out) q = q + Vec3d{outlier_metres * std::cos(3.0 * i), outlier_metres * std::sin(3.0 * i), 0};
      source.push_back(p);
      target.push_back(q);
      outlier.push_back(out);
    }
  }
};

}  // namespace

TEST(RobustSimilarity, ExactPairsGiveTheSimilarityBack) {
  const KnownSimilarity k(12, 0, 0, 0);
  const SimilarityFit fit = robust_similarity(k.source, k.target);
  EXPECT_NEAR(fit.transform.scale(), 2.5, 1e-9);
  for (const Vec3d& p : k.source) EXPECT_LT(norm(fit.transform.apply(p) - k.truth.apply(p)), 1e-6);
  EXPECT_EQ(fit.inliers, k.source.size());
}

TEST(RobustSimilarity, RejectsPhoneOutliersAndFitsTheRest) {
  // GPS-like: 3 m noise on an orbit 20 m across (in target units), a fifth of the positions 40 m off.
  const KnownSimilarity k(40, 3.0, 0.2, 40);
  const SimilarityFit fit = robust_similarity(k.source, k.target);
  for (size_t i = 0; i < k.source.size(); ++i)
    if (k.outlier[i]) EXPECT_FALSE(fit.inlier[i]) << "outlier " << i << " kept, residual " << fit.residuals[i];
  EXPECT_GE(fit.inliers, k.source.size() * 7 / 10);
  // The fit is as good as the noise allows (Umeyama on 32 inliers with 3 m noise: ~1 m at the points).
  for (const Vec3d& p : k.source) EXPECT_LT(norm(fit.transform.apply(p) - k.truth.apply(p)), 3.0);
  EXPECT_NEAR(fit.transform.scale(), 2.5, 0.25);
}

TEST(RobustSimilarity, RefusesPositionsOnALine) {
  std::vector<Vec3d> source, target;
  for (int i = 0; i < 10; ++i) {
    source.push_back({double(i), 0, 0});
    target.push_back({2.0 * i, 1, 0});
  }
  try {
    robust_similarity(source, target);
    FAIL() << "expected a cls::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("line"), std::string::npos) << e.what();
  }
  EXPECT_THROW(robust_similarity({{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}}), Error);
}

TEST(GpsProjection, UnprojectInvertsProject) {
  const GpsProjection utm(25832);
  for (const auto& [lat, lon] : std::vector<std::pair<double, double>>{{49.1, 8.4}, {51.7, 7.1}, {47.5, 10.9}}) {
    const std::array<double, 2> xy = utm.project(lat, lon);
    const std::array<double, 2> back = utm.unproject(xy[0], xy[1]);
    EXPECT_NEAR(back[0], lat, 1e-9);
    EXPECT_NEAR(back[1], lon, 1e-9);
  }
}

TEST(Egm96Geoid, UndulationsAtPublishedPlaces) {
  const Egm96Geoid geoid;
  if (!geoid.available()) GTEST_SKIP() << "proj-data's egm96_15.gtx is not installed";
  // NGA's EGM96 calculator (15' grid): N = 17.16 m at 0 N 0 E, -106.2 m near the Indian Ocean low
  // (4.75 N 78.75 E lies at about -106 m), about +48 m over Karlsruhe.
  EXPECT_NEAR(*geoid.undulation(0, 0), 17.16, 0.1);
  EXPECT_LT(*geoid.undulation(4.75, 78.75), -100);
  EXPECT_NEAR(*geoid.undulation(49.01, 8.40), 48.2, 1.0);
}

// A vertical CRS's heights through PROJ's geoid transformation where its grid is installed. EGM96 height
// (EPSG:5773) is one whose grid proj-data installs: its heights must be the ellipsoidal ones less the
// undulation Egm96Geoid reads from the same grid by another path (vgridshift). DHHN2016 (EPSG:7837) needs
// GCG2016, which no Debian package holds: where it is not installed, nothing is claimed.
TEST(GeoidHeights, AVerticalCRSThroughItsInstalledGrid) {
  const Egm96Geoid egm96;
  if (!egm96.available()) GTEST_SKIP() << "proj-data's egm96_15.gtx is not installed";
  const GeoidHeights heights(25832, 5773);
  ASSERT_TRUE(heights.available());
  EXPECT_NE(heights.operation().find("EGM96"), std::string::npos) << heights.operation();
  for (const auto& [lat, lon] : std::vector<std::pair<double, double>>{{49.01, 8.40}, {51.7, 7.1}, {47.5, 10.9}}) {
    const std::optional<double> h = heights.height(lat, lon, 200.0);
    ASSERT_TRUE(h.has_value());
    EXPECT_NEAR(*h, 200.0 - *egm96.undulation(lat, lon), 0.01) << lat << " " << lon;
  }
  const GeoidHeights dhhn2016(25832, 7837);
  if (dhhn2016.available()) EXPECT_NEAR(*dhhn2016.height(49.01, 8.40, 200.0), 200.0 - 48.0, 2.0) << dhhn2016.operation();
}
