// Minimal safetensors reading for the CLIP tests only (F32/F16/I64, whole file in memory).
// TEMPORARY: replaced by models/weights/safetensors.h once the weights branch lands.
#include "test_clip_fixture.h"

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace cls::clip::testing {

std::map<std::string, at::Tensor> load_state(const std::string& path, int64_t vocab_size) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string bytes = ss.str();
  uint64_t n = 0;
  std::memcpy(&n, bytes.data(), 8);
  const nlohmann::json header = nlohmann::json::parse(bytes.substr(8, n));
  const char* data = bytes.data() + 8 + n;
  std::map<std::string, at::Tensor> state;
  for (const auto& [name, info] : header.items()) {
    if (name == "__metadata__") continue;
    const std::string dt = info["dtype"];
    const at::ScalarType t = dt == "F32" ? at::kFloat : dt == "F16" ? at::kHalf : at::kLong;
    const std::vector<int64_t> shape = info["shape"];
    const uint64_t b = info["data_offsets"][0];
    state[name] = at::from_blob(const_cast<char*>(data + b), shape, at::TensorOptions().dtype(t)).clone();
  }
  if (state.count("token_embedding.weight.rows")) {
    const at::Tensor rows = state["token_embedding.weight.rows"], ids = state["token_embedding.weight.ids"];
    at::Tensor full = at::zeros({vocab_size, rows.size(1)}, rows.options());
    full.index_copy_(0, ids, rows);
    state["token_embedding.weight"] = full;
    state.erase("token_embedding.weight.rows");
    state.erase("token_embedding.weight.ids");
  }
  return state;
}

}  // namespace cls::clip::testing
