#include "web/password_slots.hpp"

#include <algorithm>

namespace sd::web {

PasswordSlots::Held PasswordSlots::take() {
  std::unique_lock lock(mutex_);
  freed_.wait(lock, [this] { return free_ > 0; });
  --free_;
  peak_ = std::max(peak_, ++held_);
  return Held(*this);
}

int PasswordSlots::peak() const {
  std::lock_guard lock(mutex_);
  return peak_;
}

void PasswordSlots::release() {
  {
    std::lock_guard lock(mutex_);
    ++free_;
    --held_;
  }
  freed_.notify_one();
}

}  // namespace sd::web
