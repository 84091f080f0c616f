#pragma once
// The blend caches of a training loop on frozen Gaussians (rasterize.h's BlendCache), one per view, within a
// memory budget: a view's cache is recorded on its first iteration and kept if it fits beside those kept
// before; a view whose cache does not fit blends every iteration (its one recording is dropped). First come,
// first kept: with views visited in random order, which views are kept does not change how many are read.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "splat/rasterize.h"

namespace cls {

class ViewBlendCaches {
 public:
  // `budget_bytes` 0: no caches (every call blends).
  ViewBlendCaches(int views, std::size_t budget_bytes);
  // The cache for the view's RasterizeSettings: empty on its first iteration (the rasterizer records into it),
  // recorded after; null where the view's did not fit.
  std::shared_ptr<BlendCache> settings_for(int view);
  // After an iteration of the view: its newly recorded cache is kept or dropped by the budget.
  void recorded(int view);
  int kept_views() const { return kept_; }
  std::size_t bytes() const { return used_; }

 private:
  enum class State : uint8_t { Untried, Kept, Dropped };
  std::vector<std::shared_ptr<BlendCache>> caches_;
  std::vector<State> state_;
  std::size_t budget_, used_ = 0;
  int kept_ = 0;
};

}  // namespace cls
