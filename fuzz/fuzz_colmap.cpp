// libFuzzer target for the COLMAP readers (binary and text) and the Pix4D calibration reader.
// The first byte picks the parser, the rest is the file content. Malformed input must end in a
// cls::Error; anything else (a crash, a sanitizer report, another exception) is a finding.
// A model that parses must also survive an encode -> parse round trip unchanged.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/colmap.h"
#include "scene/pix4d.h"

namespace {

template <class Parse, class Encode>
void round_trip(std::string_view input, Parse parse, Encode encode) {
  const std::string once = encode(parse(input, "fuzz"));  // a cls::Error here is fine
  try {
    if (encode(parse(once, "fuzz")) != once) std::abort();
  } catch (const cls::Error&) {
    std::abort();  // what we wrote must read back
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string_view input(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 7) {
      case 0: round_trip(input, cls::parse_cameras_binary, cls::encode_cameras_binary); break;
      case 1: round_trip(input, cls::parse_images_binary, cls::encode_images_binary); break;
      case 2: round_trip(input, cls::parse_points3d_binary, cls::encode_points3d_binary); break;
      case 3: round_trip(input, cls::parse_cameras_text, cls::encode_cameras_text); break;
      case 4: round_trip(input, cls::parse_images_text, cls::encode_images_text); break;
      case 5: round_trip(input, cls::parse_points3d_text, cls::encode_points3d_text); break;
      case 6: cls::parse_pix4d_calibrated_cameras(input, "fuzz"); break;
    }
  } catch (const cls::Error&) {
    // expected for malformed input
  }
  return 0;
}
