// libFuzzer target for the LAS reader (scene/las.h): the buffer parser with a stride from the first
// byte, and the streaming file reader on the same bytes, which must agree; where the header describes
// extra-bytes fields, both read the one the first byte picks, and must agree on it too. Malformed input must end
// in a cls::Error; anything else (or a disagreement) is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/las.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const uint64_t stride = 1 + data[0] % 4;
  const std::string_view input(reinterpret_cast<const char*>(data) + 1, size - 1);
  static const std::string file = "/tmp/fuzz_las_" + std::to_string(::getpid()) + ".las";
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(input.data(), static_cast<std::streamsize>(input.size()));
  bool parsed = false, streamed = false;
  cls::LasPoints a, b;
  try {
    a = cls::parse_las(input, "fuzz.las", stride);
    parsed = true;
  } catch (const cls::Error&) {
  }
  try {
    b = cls::read_las(file, stride);
    streamed = true;
  } catch (const cls::Error&) {
  }
  if (parsed && !a.header.extra_fields.empty()) {
    const std::string field = a.header.extra_fields[data[0] / 4 % a.header.extra_fields.size()].name;
    parsed = streamed = false;
    try {
      a = cls::parse_las(input, "fuzz.las", stride, field);
      parsed = true;
    } catch (const cls::Error&) {
    }
    try {
      b = cls::read_las(file, stride, field);
      streamed = true;
    } catch (const cls::Error&) {
    }
    if (parsed != streamed) std::abort();
    if (parsed && (a.field.size() != a.xyz.size() || b.field.size() != a.field.size() ||
                   (!a.field.empty() &&
                    std::memcmp(a.field.data(), b.field.data(), a.field.size() * sizeof(double)) != 0)))
      std::abort();
  }
  if (parsed != streamed || a.xyz.size() != b.xyz.size() || a.rgb != b.rgb || a.classification != b.classification)
    std::abort();
  for (size_t i = 0; i < a.xyz.size(); ++i)
    if (std::memcmp(&a.xyz[i], &b.xyz[i], sizeof a.xyz[i]) != 0) std::abort();
  return 0;
}
