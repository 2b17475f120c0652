#pragma once
// Passwords are kept only as Argon2id hashes (libsodium crypto_pwhash_str, INTERACTIVE
// limits: 64 MiB, 2 passes, about 0.1 s), salted and self-describing ("$argon2id$v=19$...").
#include <string>
#include <string_view>

namespace sd::storage {

constexpr std::size_t kMinimumPasswordLength = 8;

/// The password rule in words, for --help and error messages.
std::string password_rule();

/// What is wrong with a new password (empty when acceptable): at least 8 characters,
/// at most 1024 bytes, and not the user name.
std::string password_problem(std::string_view password, std::string_view user_name);

std::string hash_password(std::string_view password);

/// Constant-time check of a password against a stored hash.
bool verify_password(const std::string& hash, std::string_view password);

/// A hash of a random password under this build's limits, made once per process: checking a
/// password against it costs what checking a real one costs (for a name that has no account).
const std::string& dummy_password_hash();

/// Overwrites a password in memory once it is no longer needed.
void wipe(std::string& secret);

/// True when a hash was made with other limits than this build's, so it is re-hashed on
/// the next successful sign-in.
bool password_needs_rehash(const std::string& hash);

}  // namespace sd::storage
