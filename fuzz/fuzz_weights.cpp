// libFuzzer target for the weight containers a user brings (models/weights): with the first byte
// even, the bytes as a file through load_weight_file (safetensors, zip torch.save / TorchScript
// archives, chosen by content) and every tensor materialised; odd, the bytes as a pickle program
// (pickle_reader.h, the data.pkl inside the archives). Malformed input must end in a cls::Error;
// anything else is a finding. (LibTorch, whose zip reader the archives go through, is not
// instrumented: the fuzzer sees crashes there, not subtler errors.)
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.h"
#include "models/weights/pickle_reader.h"
#include "models/weights/weight_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string input(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] % 2 == 0) {
      static const std::string file = "/tmp/fuzz_weights_" + std::to_string(::getpid());
      std::ofstream(file, std::ios::binary | std::ios::trunc).write(input.data(), static_cast<std::streamsize>(input.size()));
      const cls::WeightFile w = cls::load_weight_file(file);
      for (const std::string& name : w.names()) w.get(name);
    } else {
      cls::read_pickle(input, "fuzz.pkl");
    }
  } catch (const cls::Error&) {
    // expected for malformed input
  }
  return 0;
}
