#pragma once
// The GPS position a photo's EXIF carries (phones and most UAV cameras write one), read with libexiv2
// (Debian's libexiv2-dev): what `scene info` reports and what georeferencing starts from (issue 34).
#include <optional>
#include <string>

namespace cls {

struct GpsFix {
  double latitude = 0;   // degrees, north positive (GPSLatitude with GPSLatitudeRef)
  double longitude = 0;  // degrees, east positive
  // Metres as written (GPSAltitude, negative for GPSAltitudeRef 1). EXIF means sea level; phones often
  // write ellipsoidal heights instead, so the vertical datum is for the georeferencing to resolve.
  std::optional<double> altitude;
  std::string map_datum;  // GPSMapDatum as written ("WGS-84", ...), "" when absent
};

// The image's GPS position; nullopt when its EXIF has no GPSLatitude / GPSLongitude (or no EXIF).
// cls::Error naming the file for an image libexiv2 cannot read, and for GPS tags that are malformed
// or out of range: a missing or unknown N/S/E/W reference, a zero denominator, minutes or seconds of
// 60 and more, a latitude over 90 or a longitude over 180 degrees.
std::optional<GpsFix> read_exif_gps(const std::string& path);

}  // namespace cls
