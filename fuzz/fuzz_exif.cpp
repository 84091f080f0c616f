// libFuzzer target for the photos' EXIF GPS (scene/exif_gps.h, through libexiv2 from memory): any
// image bytes. Malformed input must end in a cls::Error or no position; anything else is a finding.
// (libexiv2 itself is not instrumented: the fuzzer sees crashes inside it, not subtler errors there.)
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/error.h"
#include "scene/exif_gps.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto fix = cls::parse_exif_gps(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.jpg");
    // What is returned is a position on the earth.
    if (fix && (!(std::fabs(fix->latitude) <= 90) || !(std::fabs(fix->longitude) <= 180) ||
                (fix->altitude && !std::isfinite(*fix->altitude))))
      std::abort();
  } catch (const cls::Error&) {
    // expected for malformed input
  }
  return 0;
}
