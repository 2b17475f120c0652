#pragma once
// Failed sign-ins per client address, in this server's memory (the per-name count is in the
// accounts database: storage/sign_in_attempts.hpp). An address that fails too often in a row
// waits out a lock-out, whichever names it tries, so guessing many names from one place is as
// slow as guessing one password.
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include "app/accounts.hpp"

namespace sd::web {

class SignInLimiter {
 public:
  explicit SignInLimiter(storage::SignInPolicy policy) : policy_(policy) {}
  /// Seconds (rounded up) until the address may try again; 0 when it may now.
  std::int64_t locked_for(const std::string& address);
  void failed(const std::string& address);
  void succeeded(const std::string& address);

 private:
  using Clock = std::chrono::steady_clock;
  struct Count {
    int failures = 0;
    Clock::time_point last_failure;
    Clock::time_point locked_until;
  };
  static constexpr std::size_t kMaxAddresses = 4096;  // memory stays bounded whatever the traffic

  storage::SignInPolicy policy_;
  std::mutex mutex_;
  std::map<std::string, Count> counts_;
};

}  // namespace sd::web
