// libFuzzer target: the CityGML reader on arbitrary bytes. Only cls::Error (a reported bad input)
// is an acceptable outcome besides success; crashes, sanitizer reports and other exceptions are bugs.
#include <cstddef>
#include <cstdint>

#include "citymodel/citygml_reader.h"
#include "core/error.h"
#include "core/log.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const cls::Taxonomy taxonomy = [] {
    cls::set_log_level(cls::LogLevel::Quiet);
    return cls::Taxonomy::builtin();
  }();
  try {
    cls::read_citygml_buffer(reinterpret_cast<const char*>(data), size, "fuzz.gml", taxonomy, 0);
  } catch (const cls::Error&) {
  }
  return 0;
}
