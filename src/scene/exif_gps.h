#pragma once
// The GPS position a photo's EXIF carries (phones and most UAV cameras write one), read with libexiv2
// (Debian's libexiv2-dev): what `scene info` reports and what georeferencing starts from (issue 34).
#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cls {

struct GpsFix {
  double latitude = 0;   // degrees, north positive (GPSLatitude with GPSLatitudeRef)
  double longitude = 0;  // degrees, east positive
  // Metres as written (GPSAltitude, negative for GPSAltitudeRef 1). EXIF means sea level; phones often
  // write ellipsoidal heights instead, so the vertical datum is for the georeferencing to resolve.
  std::optional<double> altitude;
  std::string map_datum;  // GPSMapDatum as written ("WGS-84", ...), "" when absent
};

// Where a set of fixes lies: the ranges (min, max) of latitude, longitude and, over the fixes that carry
// one, altitude; how often each map datum is named. Ranges are {0, 0} where nothing counts.
struct GpsExtent {
  size_t fixes = 0, with_altitude = 0;
  std::array<double, 2> latitude{}, longitude{}, altitude{};
  std::map<std::string, int> datums;
};
GpsExtent gps_extent(const std::vector<GpsFix>& fixes);

// The image's GPS position; nullopt when its EXIF has no GPSLatitude / GPSLongitude (or no EXIF).
// cls::Error naming the file for an image libexiv2 cannot read, and for GPS tags that are malformed
// or out of range: a missing or unknown N/S/E/W reference, a zero denominator, minutes or seconds of
// 60 and more, a latitude over 90 or a longitude over 180 degrees.
std::optional<GpsFix> read_exif_gps(const std::string& path);
// The same from an image file held in memory; `name` (the file) prefixes every error.
std::optional<GpsFix> parse_exif_gps(std::string_view bytes, const std::string& name);

// Writes `fix` into the image's EXIF as a GPS receiver does (degrees, minutes and seconds to 1e-4",
// about 3 mm; altitude to the millimetre with its reference; GPSMapDatum when set), keeping its other
// tags: what `synth --gps` gives its photos. cls::Error naming the file when libexiv2 cannot write it.
void write_exif_gps(const std::string& path, const GpsFix& fix);

}  // namespace cls
