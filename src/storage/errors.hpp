#pragma once
// Why a request on the stored state was refused. All are failures of the work (exit 1 on
// the command line); misuse is caught earlier by the rules in validation.hpp.
#include <stdexcept>
#include <string>

namespace sd::storage {

/// No such thing for this user (a foreign project is reported exactly like a missing one).
struct NotFound : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The name is taken, or the thing is busy.
struct Conflict : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Wrong password, not signed in, expired session.
struct AccessDenied : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The right password of an account an administrator disabled.
struct AccountDisabled : AccessDenied {
  using AccessDenied::AccessDenied;
};

/// Too many failed sign-ins: the name (or the client) must wait.
struct TooManyAttempts : std::runtime_error {
  TooManyAttempts(const std::string& message, long long seconds) : std::runtime_error(message), retry_after(seconds) {}
  long long retry_after;  // seconds
};

/// A value that the validation rules refuse reached a store.
struct InvalidInput : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

}  // namespace sd::storage
