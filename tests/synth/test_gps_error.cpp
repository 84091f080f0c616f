// synth --gps: its error model as text, and the positions it writes checked against the true camera
// centres through PROJ's forward projection.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "synth/gps_error.h"

using namespace cls;

TEST(SynthGps, OnGivesThePhoneModelAndKeysOverrideIt) {
  const synth::GpsError on = synth::parse_gps_error("on");
  EXPECT_TRUE(on.enabled);
  EXPECT_EQ(on.horizontal, 3);
  EXPECT_EQ(on.datum, 50);
  EXPECT_EQ(on.outliers, 0.1);
  const synth::GpsError some = synth::parse_gps_error("h=1.5, outliers=0.25,datum=-20");
  EXPECT_EQ(some.horizontal, 1.5);
  EXPECT_EQ(some.outliers, 0.25);
  EXPECT_EQ(some.datum, -20);
  EXPECT_EQ(some.vertical, 3);
  EXPECT_EQ(synth::parse_gps_error(synth::gps_error_text(some)).outlier_metres, some.outlier_metres);
  for (const char* bad : {"", "h=-1", "outliers=1.5", "x=1", "h=abc", "h"})
    EXPECT_THROW(synth::parse_gps_error(bad), UsageError) << bad;
}

TEST(SynthGps, PositionsAreTheCentresSpoiltAsAsked) {
  const GpsProjection utm(25832);
  std::vector<Vec3d> centres;
  for (int i = 0; i < 20; ++i) centres.push_back({456100.0 + 3 * i, 5427600.0 - 2 * i, 130.0 + i});
  // No noise: each fix projects back onto its centre, its height the centre's plus the datum offset;
  // exactly a quarter of the photos lie outlier-m away.
  synth::GpsError e = synth::parse_gps_error("h=0,v=0,datum=47.5,outliers=0.25,outlier-m=30");
  const std::vector<GpsFix> fixes = synth::spoilt_gps(centres, utm, e, 5);
  ASSERT_EQ(fixes.size(), centres.size());
  int outliers = 0;
  for (size_t i = 0; i < fixes.size(); ++i) {
    const std::array<double, 2> xy = utm.project(fixes[i].latitude, fixes[i].longitude);
    const double off = std::hypot(xy[0] - centres[i].x, xy[1] - centres[i].y);
    if (off > 1e-6) {
      EXPECT_NEAR(off, 30, 1e-6);
      ++outliers;
    }
    EXPECT_NEAR(*fixes[i].altitude, centres[i].z + 47.5, 1e-9);
    EXPECT_EQ(fixes[i].map_datum, "WGS-84");
  }
  EXPECT_EQ(outliers, 5);
  // With noise the same seed gives the same positions; the spread is the one asked for.
  e = synth::parse_gps_error("h=3,v=0,outliers=0");
  std::vector<Vec3d> many(2000, centres[0]);
  const std::vector<GpsFix> noisy = synth::spoilt_gps(many, utm, e, 9), again = synth::spoilt_gps(many, utm, e, 9);
  double sum = 0;
  for (size_t i = 0; i < noisy.size(); ++i) {
    EXPECT_EQ(noisy[i].latitude, again[i].latitude);
    const std::array<double, 2> xy = utm.project(noisy[i].latitude, noisy[i].longitude);
    sum += std::pow(xy[0] - many[i].x, 2);
  }
  EXPECT_NEAR(std::sqrt(sum / noisy.size()), 3.0, 0.15);  // easting's standard deviation, 2000 draws
}
