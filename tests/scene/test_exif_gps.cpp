// EXIF GPS of photos: tags written by libexiv2 as a camera writes them (degrees, minutes, seconds as
// rationals with N/S/E/W references), read back as signed decimal degrees worked out by hand, and
// every malformed or out-of-range tag an error that names the file and the tag.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "core/atomic_file.h"
#include "scene/exif_gps.h"
#include "scene_test_util.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

const std::map<std::string, std::string> kParis = {
    {"Exif.GPSInfo.GPSLatitudeRef", "N"},   {"Exif.GPSInfo.GPSLatitude", "48/1 51/1 296/10"},
    {"Exif.GPSInfo.GPSLongitudeRef", "E"},  {"Exif.GPSInfo.GPSLongitude", "2/1 17/1 402/10"},
    {"Exif.GPSInfo.GPSAltitudeRef", "0"},   {"Exif.GPSInfo.GPSAltitude", "71/2"},
    {"Exif.GPSInfo.GPSMapDatum", "WGS-84   "}};  // padded, as cameras write it

std::map<std::string, std::string> with(std::map<std::string, std::string> tags, const std::string& key,
                                        const std::string& value) {
  if (value.empty()) tags.erase(key);
  else tags[key] = value;
  return tags;
}

}  // namespace

TEST(ExifGps, DegreesMinutesSecondsAndReferencesGiveSignedDegrees) {
  const fs::path dir = test::fresh_dir("exif_gps");
  for (const char* name : {"paris.jpg", "paris.png"}) {  // phones write JPEG, our synth PNG
    SCOPED_TRACE(name);
    const auto fix = read_exif_gps(test::photo_with_exif(dir, name, kParis).string());
    ASSERT_TRUE(fix.has_value());
    EXPECT_NEAR(fix->latitude, 48 + 51 / 60.0 + 29.6 / 3600, 1e-12);  // 48.8582222...
    EXPECT_NEAR(fix->longitude, 2 + 17 / 60.0 + 40.2 / 3600, 1e-12);  // 2.2945
    ASSERT_TRUE(fix->altitude.has_value());
    EXPECT_DOUBLE_EQ(*fix->altitude, 35.5);
    EXPECT_EQ(fix->map_datum, "WGS-84");
    const auto from_memory = parse_exif_gps(read_text_file(dir / name), name);
    ASSERT_TRUE(from_memory.has_value());
    EXPECT_EQ(from_memory->latitude, fix->latitude);
    EXPECT_EQ(from_memory->longitude, fix->longitude);
    EXPECT_EQ(from_memory->altitude, fix->altitude);
  }
  // South, west, below sea level; a position without altitude.
  auto south = with(with(with(kParis, "Exif.GPSInfo.GPSLatitudeRef", "S"), "Exif.GPSInfo.GPSLongitudeRef", "W"),
                    "Exif.GPSInfo.GPSAltitudeRef", "1");
  const auto s = read_exif_gps(test::photo_with_exif(dir, "south.jpg", south).string());
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->latitude, -(48 + 51 / 60.0 + 29.6 / 3600), 1e-12);
  EXPECT_NEAR(s->longitude, -(2 + 17 / 60.0 + 40.2 / 3600), 1e-12);
  EXPECT_DOUBLE_EQ(*s->altitude, -35.5);
  const auto flat = read_exif_gps(test::photo_with_exif(dir, "flat.jpg", with(kParis, "Exif.GPSInfo.GPSAltitude", "")).string());
  ASSERT_TRUE(flat.has_value());
  EXPECT_FALSE(flat->altitude.has_value());
  // A camera without a fix writes 0/0: no position (or no altitude), not an error.
  const auto unset = with(with(kParis, "Exif.GPSInfo.GPSLatitude", "0/0 0/0 0/0"), "Exif.GPSInfo.GPSLongitude",
                          "0/0 0/0 0/0");
  EXPECT_FALSE(read_exif_gps(test::photo_with_exif(dir, "nofix.jpg", unset).string()).has_value());
  const auto no_altitude =
      read_exif_gps(test::photo_with_exif(dir, "noalt.jpg", with(kParis, "Exif.GPSInfo.GPSAltitude", "0/0")).string());
  ASSERT_TRUE(no_altitude.has_value());
  EXPECT_FALSE(no_altitude->altitude.has_value());
  // The altitude's reference written as the digit in text, as some tools do.
  const auto text_ref = read_exif_gps(
      test::photo_with_exif(dir, "textref.jpg", with(kParis, "Exif.GPSInfo.GPSAltitudeRef", "ascii:1")).string());
  ASSERT_TRUE(text_ref.has_value());
  EXPECT_DOUBLE_EQ(*text_ref->altitude, -35.5);
  // A format libexiv2 does not read (PPM) has no EXIF to read: no position.
  EXPECT_FALSE(read_exif_gps(test::photo_with_exif(dir, "plain.ppm", {}).string()).has_value());
  // No EXIF at all, and EXIF without GPS: no position, no error.
  EXPECT_FALSE(read_exif_gps(test::photo_with_exif(dir, "plain.jpg", {}).string()).has_value());
  EXPECT_FALSE(read_exif_gps(test::photo_with_exif(dir, "camera.jpg", {{"Exif.Image.Make", "Phone"}}).string()).has_value());
  fs::remove_all(dir);
}

TEST(ExifGps, MalformedOrOutOfRangeTagsNameTheFileAndTheTag) {
  const fs::path dir = test::fresh_dir("exif_gps_bad");
  const std::vector<std::pair<std::map<std::string, std::string>, std::string>> cases = {
      {with(kParis, "Exif.GPSInfo.GPSLatitude", "95/1 0/1 0/1"), "more than 90"},
      {with(kParis, "Exif.GPSInfo.GPSLongitude", "181/1 0/1 0/1"), "more than 180"},
      {with(kParis, "Exif.GPSInfo.GPSLatitude", "48/1 60/1 0/1"), "minutes of 60 or more"},
      {with(kParis, "Exif.GPSInfo.GPSLongitude", "2/1 17/1 61/1"), "seconds of 60 or more"},
      {with(kParis, "Exif.GPSInfo.GPSLatitude", "48/0 51/1 296/10"), "zero denominator"},
      {with(kParis, "Exif.GPSInfo.GPSLatitudeRef", ""), "GPSLatitudeRef is missing"},
      {with(kParis, "Exif.GPSInfo.GPSLongitudeRef", "X"), "expected E or W"},
      {with(kParis, "Exif.GPSInfo.GPSLongitude", ""), "GPSLatitude without GPSLongitude"},
      {with(kParis, "Exif.GPSInfo.GPSAltitudeRef", "2"), "GPSAltitudeRef is 2"},
      {with(kParis, "Exif.GPSInfo.GPSLatitude", "ascii:48"), "GPSLatitude is of type Ascii, not rational"},
      {with(kParis, "Exif.GPSInfo.GPSLongitude", "0/0 0/0 0/0"), "one of latitude and longitude unset"}};
  int k = 0;
  for (const auto& [tags, message] : cases) {
    const fs::path path = test::photo_with_exif(dir, "bad" + std::to_string(k++) + ".jpg", tags);
    test::expect_error([&] { read_exif_gps(path.string()); }, {path.string() + ": EXIF", message});
    // the same file from memory (what the fuzzer feeds)
    test::expect_error([&] { parse_exif_gps(read_text_file(path), "memory.jpg"); }, {"memory.jpg: EXIF", message});
  }
  const fs::path text = dir / "notes.jpg";
  write_text_atomic(text, "not an image");
  test::expect_error([&] { read_exif_gps(text.string()); }, {text.string() + ": cannot read the image's metadata"});
  fs::remove_all(dir);
}

// The extent of a set of fixes: ranges by hand, altitude only over the fixes that carry one.
TEST(ExifGps, TheExtentOfASetOfFixes) {
  const GpsExtent none = gps_extent({});
  EXPECT_EQ(none.fixes, 0u);
  const GpsExtent e = gps_extent({{51.5, 7.25, 150.0, "WGS-84"}, {51.75, 7.0, std::nullopt, ""},
                                  {51.6, 7.5, 90.0, "WGS-84"}});
  EXPECT_EQ(e.fixes, 3u);
  EXPECT_EQ(e.with_altitude, 2u);
  EXPECT_EQ(e.latitude, (std::array<double, 2>{51.5, 51.75}));
  EXPECT_EQ(e.longitude, (std::array<double, 2>{7.0, 7.5}));
  EXPECT_EQ(e.altitude, (std::array<double, 2>{90.0, 150.0}));
  EXPECT_EQ(e.datums, (std::map<std::string, int>{{"WGS-84", 2}}));
}

TEST(ExifGps, WhatTheWriterWritesAReceiverReadsBackAsExifSpellsIt) {
  const fs::path dir = test::fresh_dir("exif_gps_write");
  for (const char* name : {"fix.jpg", "fix.png"}) {
    SCOPED_TRACE(name);
    // Every sign: north-east above sea level, south-west below it.
    for (const GpsFix& in : {GpsFix{49.10312345678, 8.42234567891, 171.2344, "WGS-84"},
                             GpsFix{-33.85678901234, -70.64567890123, -12.3456, ""}}) {
      const fs::path path = test::photo_with_exif(dir, name, {});
      write_exif_gps(path.string(), in);
      const std::optional<GpsFix> out = read_exif_gps(path.string());
      ASSERT_TRUE(out.has_value());
      EXPECT_NEAR(out->latitude, in.latitude, 0.5e-4 / 3600);  // 1e-4 arc seconds, rounded
      EXPECT_NEAR(out->longitude, in.longitude, 0.5e-4 / 3600);
      ASSERT_TRUE(out->altitude.has_value());
      EXPECT_NEAR(*out->altitude, *in.altitude, 0.5e-3);
      EXPECT_EQ(out->map_datum, in.map_datum);
      // As EXIF spells it: unsigned degrees, minutes, seconds with a reference letter.
      auto image = Exiv2::ImageFactory::open(path.string());
      image->readMetadata();
      const Exiv2::ExifData& exif = image->exifData();
      EXPECT_EQ(exif.findKey(Exiv2::ExifKey("Exif.GPSInfo.GPSLatitudeRef"))->toString(), in.latitude < 0 ? "S" : "N");
      EXPECT_EQ(exif.findKey(Exiv2::ExifKey("Exif.GPSInfo.GPSAltitudeRef"))->toString(), *in.altitude < 0 ? "1" : "0");
    }
  }
  test::expect_error([&] { write_exif_gps((dir / "absent.png").string(), GpsFix{}); }, {"absent.png"});
}
