// libFuzzer target for the NumPy .npy reader (core/npy.h): LangSplat feature files and fixtures a
// user brings. Whatever parses is converted to double and must re-encode and parse back to the same
// bytes. Malformed input must end in a cls::Error; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "core/npy.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  cls::NpyArray a;
  try {
    a = cls::parse_npy(input, "fuzz.npy");
  } catch (const cls::Error&) {
    return 0;  // expected for malformed input
  }
  a.to_double();
  try {
    const cls::NpyArray b = cls::parse_npy(cls::encode_npy(a), "fuzz.npy");
    if (b.dtype != a.dtype || b.shape != a.shape || b.data != a.data) std::abort();
  } catch (const cls::Error&) {
    std::abort();  // what we wrote must read back
  }
  return 0;
}
