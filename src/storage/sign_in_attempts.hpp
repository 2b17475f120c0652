#pragma once
// Failed sign-ins, counted per name in the accounts database, so the CLI and every server of a
// home share one count: after `failures_before_lockout` wrong passwords in a row a name is
// locked for `lockout`, then a right password works again. A name that has no account is
// counted and locked exactly like one that has, so the lock-out tells no name apart.
#include <chrono>
#include <cstdint>
#include <string_view>

#include "storage/sqlite.hpp"

namespace sd::storage {

struct SignInPolicy {
  int failures_before_lockout = 5;    // per name, in a row
  std::chrono::seconds lockout{60};
  int failures_per_address = 20;      // per client address of a server, in a row
};

class SignInAttempts {
 public:
  SignInAttempts(Database& db, SignInPolicy policy) : db_(db), policy_(policy) {}
  /// Seconds until the name may be tried again; 0 when it may be tried now.
  std::int64_t locked_for(std::string_view name, std::int64_t now);
  /// One more failure; locks the name when it reaches the policy's count.
  void failed(std::string_view name, std::int64_t now);
  /// A right password: the name's count starts again.
  void succeeded(std::string_view name);

 private:
  Database& db_;
  SignInPolicy policy_;
};

}  // namespace sd::storage
