#include "web/sign_in_limiter.hpp"

#include <algorithm>

namespace sd::web {

std::int64_t SignInLimiter::locked_for(const std::string& address) {
  std::lock_guard lock(mutex_);
  const auto it = counts_.find(address);
  if (it == counts_.end()) return 0;
  const auto left = it->second.locked_until - Clock::now();
  if (left <= Clock::duration::zero()) return 0;
  return std::chrono::ceil<std::chrono::seconds>(left).count();
}

void SignInLimiter::failed(const std::string& address) {
  std::lock_guard lock(mutex_);
  const auto now = Clock::now();
  if (counts_.size() >= kMaxAddresses && !counts_.contains(address)) {
    // Forget the address whose last failure is oldest (and not locked now).
    auto oldest = counts_.end();
    for (auto it = counts_.begin(); it != counts_.end(); ++it)
      if (it->second.locked_until <= now && (oldest == counts_.end() || it->second.last_failure < oldest->second.last_failure))
        oldest = it;
    if (oldest == counts_.end()) return;  // every one is locked: count no more
    counts_.erase(oldest);
  }
  Count& count = counts_[address];
  if (count.locked_until != Clock::time_point{} && count.locked_until <= now) count = Count{};  // a lock-out served
  count.last_failure = now;
  if (++count.failures >= policy_.failures_per_address && count.locked_until <= now)
    count.locked_until = now + policy_.lockout;
}

void SignInLimiter::succeeded(const std::string& address) {
  std::lock_guard lock(mutex_);
  counts_.erase(address);
}

}  // namespace sd::web
