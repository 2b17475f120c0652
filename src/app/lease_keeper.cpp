#include "app/lease_keeper.hpp"

#include <optional>

#include "storage/lease.hpp"

namespace sd::app {

LeaseKeeper::LeaseKeeper(std::filesystem::path home, std::function<void(Home&)> renew)
    : thread_([this, home = std::move(home), renew = std::move(renew)] { beat(home, renew); }) {}

void LeaseKeeper::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void LeaseKeeper::beat(const std::filesystem::path& home, const std::function<void(Home&)>& renew) {
  std::optional<Home> h;
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::seconds(storage::kHeartbeatSeconds), [&] { return stopping_; })) {
    lock.unlock();
    try {
      if (!h) h.emplace(home);
      renew(*h);
    } catch (const std::exception&) {
      // A busy database misses one beat; the lease lasts several.
    }
    lock.lock();
  }
}

}  // namespace sd::app
