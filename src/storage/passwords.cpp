#include "storage/passwords.hpp"

#include <sodium.h>

#include <stdexcept>

#include "storage/sodium.hpp"

namespace sd::storage {

namespace {
constexpr std::size_t kMaximumPasswordBytes = 1024;  // hashing cost must not be user-driven
constexpr auto kOpsLimit = crypto_pwhash_OPSLIMIT_INTERACTIVE;
constexpr auto kMemLimit = crypto_pwhash_MEMLIMIT_INTERACTIVE;

std::size_t utf8_characters(std::string_view text) {
  std::size_t count = 0;
  for (const char c : text)
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++count;  // skip continuation bytes
  return count;
}
}  // namespace

std::string password_rule() {
  return "a password needs at least " + std::to_string(kMinimumPasswordLength) +
         " characters and must not be the user name";
}

std::string password_problem(std::string_view password, std::string_view user_name) {
  if (password.empty()) return "password is empty: " + password_rule();
  if (utf8_characters(password) < kMinimumPasswordLength) return "password is too short: " + password_rule();
  if (password.size() > kMaximumPasswordBytes)
    return "password is longer than " + std::to_string(kMaximumPasswordBytes) + " bytes";
  if (password == user_name) return "password is the user name: " + password_rule();
  return {};
}

std::string hash_password(std::string_view password) {
  ensure_sodium();
  char hash[crypto_pwhash_STRBYTES];
  if (crypto_pwhash_str_alg(hash, password.data(), password.size(), kOpsLimit, kMemLimit,
                            crypto_pwhash_ALG_ARGON2ID13) != 0)
    throw std::runtime_error("cannot hash the password: out of memory");
  return hash;
}

bool verify_password(const std::string& hash, std::string_view password) {
  ensure_sodium();
  return crypto_pwhash_str_verify(hash.c_str(), password.data(), password.size()) == 0;
}

const std::string& dummy_password_hash() {
  static const std::string hash = [] {
    ensure_sodium();
    unsigned char random[32];
    randombytes_buf(random, sizeof random);
    return hash_password(std::string_view(reinterpret_cast<const char*>(random), sizeof random));
  }();
  return hash;
}

void wipe(std::string& secret) {
  sodium_memzero(secret.data(), secret.size());
  secret.clear();
}

bool password_needs_rehash(const std::string& hash) {
  ensure_sodium();
  return crypto_pwhash_str_needs_rehash(hash.c_str(), kOpsLimit, kMemLimit) != 0;
}

}  // namespace sd::storage
