#include "engine/ecs/context.h"

#include <algorithm>

namespace engine::ecs {

Context::~Context() {
  clear();
}

Context& Context::operator=(Context&& other) noexcept {
  if (this != &other) {
    clear();
    entries_ = std::move(other.entries_);
    order_ = std::move(other.order_);
    other.entries_.clear();
    other.order_.clear();
  }
  return *this;
}

void Context::clear() noexcept {
  // Newest first: a singleton created later may refer to an earlier one.
  while (!order_.empty()) eraseId(order_.back());
}

void Context::eraseId(std::uint32_t id) noexcept {
  order_.erase(std::find(order_.begin(), order_.end(), id));
  // Moved out before destruction so a destructor that looks the type up sees it absent.
  std::unique_ptr<Entry> doomed = std::move(entries_[id]);
}

}  // namespace engine::ecs
