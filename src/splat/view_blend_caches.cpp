#include "splat/view_blend_caches.h"

namespace cls {

ViewBlendCaches::ViewBlendCaches(int views, std::size_t budget_bytes)
    : caches_(static_cast<std::size_t>(views)), state_(static_cast<std::size_t>(views), State::Untried), budget_(budget_bytes) {}

std::shared_ptr<BlendCache> ViewBlendCaches::settings_for(int view) {
  std::shared_ptr<BlendCache>& cache = caches_.at(static_cast<std::size_t>(view));
  if (budget_ == 0 || state_[static_cast<std::size_t>(view)] == State::Dropped) return nullptr;
  if (!cache) cache = make_blend_cache();
  return cache;
}

void ViewBlendCaches::recorded(int view) {
  const std::size_t i = static_cast<std::size_t>(view);
  if (state_.at(i) != State::Untried || !caches_[i]) return;
  const std::size_t bytes = blend_cache_bytes(*caches_[i]);
  if (bytes == 0) return;  // not recorded (yet)
  if (used_ + bytes <= budget_) {
    used_ += bytes;
    ++kept_;
    state_[i] = State::Kept;
  } else {
    caches_[i].reset();
    state_[i] = State::Dropped;
  }
}

}  // namespace cls
