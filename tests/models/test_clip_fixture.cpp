#include "test_clip_fixture.h"

#include "models/weights/safetensors.h"

namespace cls::clip::testing {

std::map<std::string, at::Tensor> load_state(const std::string& path, int64_t vocab_size) {
  const WeightFile file = read_safetensors(path);
  std::map<std::string, at::Tensor> state;
  for (const std::string& name : file.names()) state[name] = file.get(name);
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
