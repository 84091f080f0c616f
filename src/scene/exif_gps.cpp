#include "scene/exif_gps.h"

#include <exiv2/exiv2.hpp>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

// libexiv2 prints its own warnings to stderr; our errors name the file and the tag instead.
void mute_exiv2() {
  static std::once_flag once;
  std::call_once(once, [] { Exiv2::LogMsg::setLevel(Exiv2::LogMsg::mute); });
}

const Exiv2::Exifdatum* find(const Exiv2::ExifData& exif, const char* key) {
  const auto it = exif.findKey(Exiv2::ExifKey(key));
  return it == exif.end() ? nullptr : &*it;
}

// The rationals of a tag as doubles; nullopt when every one is 0/0, which cameras without a fix write.
// EXIF defines the GPS tags as URational; a tag of another type (an ASCII "48" read as rationals would
// give character codes) is an error.
std::optional<std::vector<double>> rationals(const std::string& path, const Exiv2::Exifdatum& d) {
  if (d.typeId() != Exiv2::unsignedRational && d.typeId() != Exiv2::signedRational)
    fail(path, cat("EXIF ", d.key(), " is of type ", d.typeName() ? d.typeName() : "unknown", ", not rational: ",
                   d.toString()));
  // URational read as such: numerators beyond int32 stay right.
  const auto* u = dynamic_cast<const Exiv2::URationalValue*>(&d.value());
  std::vector<std::pair<double, double>> parts;
  for (long k = 0; k < d.count(); ++k) {
    const Exiv2::Rational r = u ? Exiv2::Rational(0, 0) : d.toRational(k);
    parts.emplace_back(u ? u->value_[k].first : r.first, u ? u->value_[k].second : r.second);
  }
  if (std::all_of(parts.begin(), parts.end(), [](const auto& p) { return p.first == 0 && p.second == 0; }))
    return std::nullopt;
  std::vector<double> out;
  for (const auto& [num, den] : parts) {
    if (den == 0) fail(path, cat("EXIF ", d.key(), " has a zero denominator: ", d.toString()));
    out.push_back(num / den);
  }
  return out;
}

// Degrees, minutes, seconds (EXIF: three rationals; fewer are read as the leading parts) to degrees.
std::optional<double> degrees(const std::string& path, const Exiv2::Exifdatum& d, double limit) {
  const std::optional<std::vector<double>> parts = rationals(path, d);
  if (!parts) return std::nullopt;
  const std::vector<double>& dms = *parts;
  if (dms.empty() || dms.size() > 3) fail(path, cat("EXIF ", d.key(), " has ", dms.size(), " values, expected 3"));
  for (size_t k = 0; k < dms.size(); ++k) {
    if (!std::isfinite(dms[k]) || dms[k] < 0) fail(path, cat("EXIF ", d.key(), " has a negative part: ", d.toString()));
    if (k > 0 && dms[k] >= 60)
      fail(path, cat("EXIF ", d.key(), " has ", k == 1 ? "minutes" : "seconds", " of 60 or more: ", d.toString()));
  }
  const double value = dms[0] + (dms.size() > 1 ? dms[1] / 60 : 0) + (dms.size() > 2 ? dms[2] / 3600 : 0);
  if (value > limit) fail(path, cat("EXIF ", d.key(), " is ", value, " degrees, more than ", limit, ": ", d.toString()));
  return value;
}

// +1 or -1 from a reference tag ("N"/"S", "E"/"W"); cls::Error for a missing or unknown one.
double sign(const std::string& path, const Exiv2::ExifData& exif, const char* key, char positive, char negative) {
  const Exiv2::Exifdatum* ref = find(exif, key);
  const std::string value = ref ? ref->toString() : "";
  if (value.empty()) fail(path, cat("EXIF ", key, " is missing: the GPS position has no hemisphere"));
  if (value[0] == positive) return 1;
  if (value[0] == negative) return -1;
  fail(path, cat("EXIF ", key, " is \"", value, "\", expected ", positive, " or ", negative));
}

}  // namespace

GpsExtent gps_extent(const std::vector<GpsFix>& fixes) {
  GpsExtent e;
  const auto widen = [](std::array<double, 2>& range, double v, bool first) {
    range = first ? std::array<double, 2>{v, v} : std::array<double, 2>{std::min(range[0], v), std::max(range[1], v)};
  };
  for (const GpsFix& fix : fixes) {
    widen(e.latitude, fix.latitude, e.fixes == 0);
    widen(e.longitude, fix.longitude, e.fixes == 0);
    ++e.fixes;
    if (fix.altitude) widen(e.altitude, *fix.altitude, e.with_altitude++ == 0);
    if (!fix.map_datum.empty()) ++e.datums[fix.map_datum];
  }
  return e;
}

namespace {

// The EXIF of an image libexiv2 opens from `source` (a path, or bytes and their size), nullopt for a
// format it does not know (PPM, EXR, ...: no EXIF it could read); its errors name `name`.
template <class... Source>
std::optional<Exiv2::ExifData> exif_of(const std::string& name, const Source&... source) {
  mute_exiv2();
  try {
    if (Exiv2::ImageFactory::getType(source...) == Exiv2::ImageType::none) return std::nullopt;
    auto image = Exiv2::ImageFactory::open(source...);
    image->readMetadata();
    return image->exifData();
  } catch (const Exiv2::Error& e) {
    fail(name, std::string("cannot read the image's metadata (libexiv2): ") + e.what());
  } catch (const std::exception& e) {  // libexiv2 throws std:: exceptions too on damaged files
    fail(name, std::string("cannot read the image's metadata (libexiv2): ") + e.what());
  }
}

std::optional<GpsFix> gps_of(const std::string& path, const std::optional<Exiv2::ExifData>& data) {
  if (!data) return std::nullopt;
  const Exiv2::ExifData& exif = *data;
  const Exiv2::Exifdatum* lat = find(exif, "Exif.GPSInfo.GPSLatitude");
  const Exiv2::Exifdatum* lon = find(exif, "Exif.GPSInfo.GPSLongitude");
  if (!lat && !lon) return std::nullopt;
  if (!lat || !lon) fail(path, cat("EXIF has GPS", lat ? "Latitude" : "Longitude", " without GPS", lat ? "Longitude" : "Latitude"));
  const std::optional<double> latitude = degrees(path, *lat, 90), longitude = degrees(path, *lon, 180);
  if (!latitude && !longitude) return std::nullopt;  // 0/0 in both: a camera that had no fix
  if (!latitude || !longitude) fail(path, "EXIF GPS has one of latitude and longitude unset (0/0)");
  GpsFix fix;
  fix.latitude = sign(path, exif, "Exif.GPSInfo.GPSLatitudeRef", 'N', 'S') * *latitude;
  fix.longitude = sign(path, exif, "Exif.GPSInfo.GPSLongitudeRef", 'E', 'W') * *longitude;
  if (const Exiv2::Exifdatum* alt = find(exif, "Exif.GPSInfo.GPSAltitude")) {
    const std::optional<std::vector<double>> a = rationals(path, *alt);
    if (a && (a->size() != 1 || !std::isfinite((*a)[0])))
      fail(path, cat("EXIF GPSAltitude is not one number: ", alt->toString()));
    // GPSAltitudeRef: a BYTE 0 (above) or 1 (below sea level); some writers store the digit as text.
    const Exiv2::Exifdatum* ref = find(exif, "Exif.GPSInfo.GPSAltitudeRef");
    const std::string below = ref ? ref->toString() : "0";
    if (below != "0" && below != "1")
      fail(path, cat("EXIF GPSAltitudeRef is ", below, ", expected 0 (above) or 1 (below sea level)"));
    if (a) fix.altitude = below == "1" ? -(*a)[0] : (*a)[0];
  }
  if (const Exiv2::Exifdatum* datum = find(exif, "Exif.GPSInfo.GPSMapDatum")) {
    fix.map_datum = datum->toString();  // cameras pad it ("WGS-84   ")
    fix.map_datum.erase(fix.map_datum.find_last_not_of(std::string(" \0", 2)) + 1);
  }
  return fix;
}

}  // namespace

std::optional<GpsFix> read_exif_gps(const std::string& path) { return gps_of(path, exif_of(path, path)); }

std::optional<GpsFix> parse_exif_gps(std::string_view bytes, const std::string& name) {
  return gps_of(name, exif_of(name, reinterpret_cast<const Exiv2::byte*>(bytes.data()), static_cast<long>(bytes.size())));
}

namespace {

// d/1 m/1 s*10000/10000, as receivers write degrees.
std::string dms(double degrees) {
  long long tenth_millis = std::llround(std::abs(degrees) * 3600 * 10000);  // 1e-4 arc seconds
  const long long d = tenth_millis / (3600LL * 10000), m = tenth_millis / (60LL * 10000) % 60;
  const long long s = tenth_millis % (60LL * 10000);
  return cat(d, "/1 ", m, "/1 ", s, "/10000");
}

}  // namespace

void write_exif_gps(const std::string& path, const GpsFix& fix) {
  mute_exiv2();
  try {
    auto image = Exiv2::ImageFactory::open(path);
    image->readMetadata();
    Exiv2::ExifData exif = image->exifData();
    exif["Exif.GPSInfo.GPSVersionID"] = "2 3 0 0";
    exif["Exif.GPSInfo.GPSLatitudeRef"] = fix.latitude < 0 ? "S" : "N";
    exif["Exif.GPSInfo.GPSLatitude"] = dms(fix.latitude);
    exif["Exif.GPSInfo.GPSLongitudeRef"] = fix.longitude < 0 ? "W" : "E";
    exif["Exif.GPSInfo.GPSLongitude"] = dms(fix.longitude);
    if (fix.altitude) {
      exif["Exif.GPSInfo.GPSAltitudeRef"] = *fix.altitude < 0 ? "1" : "0";  // BYTE, the tag's own type
      exif["Exif.GPSInfo.GPSAltitude"] = cat(std::llround(std::abs(*fix.altitude) * 1000), "/1000");
    }
    if (!fix.map_datum.empty()) exif["Exif.GPSInfo.GPSMapDatum"] = fix.map_datum;
    image->setExifData(exif);
    image->writeMetadata();
  } catch (const Exiv2::Error& e) {
    fail(path, std::string("cannot write the GPS position (libexiv2): ") + e.what());
  } catch (const std::exception& e) {
    fail(path, std::string("cannot write the GPS position (libexiv2): ") + e.what());
  }
}

}  // namespace cls
