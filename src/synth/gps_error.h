#pragma once
// The GPS positions synth --gps writes into its photos' EXIF: the true camera centres in the city
// model's CRS, spoilt as phones spoil them (issue 34): horizontal and vertical noise, heights in another
// vertical datum (a constant offset: phones write ellipsoidal heights where EXIF means sea level), and
// a share of outliers tens of metres off (multipath between buildings).
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"
#include "georef/proj_crs.h"
#include "scene/exif_gps.h"

namespace cls::synth {

struct GpsError {
  bool enabled = false;
  double horizontal = 3;       // standard deviation of easting and northing each (metres)
  double vertical = 3;         // standard deviation of the height (metres)
  double datum = 50;           // added to every height (metres)
  double outliers = 0.1;       // share of photos displaced by outlier_metres (rounded to whole photos)
  double outlier_metres = 30;  // horizontal displacement of an outlier, in a seeded direction
};

// "on" (the defaults above) or any of h=,v=,datum=,outliers=,outlier-m= (the rest default);
// cls::UsageError naming the bad part.
GpsError parse_gps_error(const std::string& text);
// The text parse_gps_error reads back ("" when not enabled).
std::string gps_error_text(const GpsError& e);

// One fix per camera centre (`centres` in the CRS, heights orthometric as the city model's), drawn
// from `seed`; datum "WGS-84".
std::vector<GpsFix> spoilt_gps(const std::vector<Vec3d>& centres, const GpsProjection& projection, const GpsError& e,
                               uint64_t seed);

}  // namespace cls::synth
