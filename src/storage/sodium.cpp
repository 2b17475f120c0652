#include "storage/sodium.hpp"

#include <sodium.h>

#include <stdexcept>

namespace sd::storage {

void ensure_sodium() {
  // sodium_init is thread-safe and idempotent (returns 1 when already done).
  if (sodium_init() < 0) throw std::runtime_error("cannot initialise libsodium");
}

SecretHash hash_secret(std::string_view secret) {
  ensure_sodium();
  SecretHash hash{};
  crypto_generichash(hash.data(), hash.size(), reinterpret_cast<const unsigned char*>(secret.data()), secret.size(),
                     nullptr, 0);
  return hash;
}

std::string readable_secret(std::size_t length) {
  static constexpr char kAlphabet[] = "abcdefghijkmnpqrstuvwxyzABCDEFGHJKLMNPQRSTUVWXYZ23456789";
  ensure_sodium();
  std::string out;
  for (std::size_t i = 0; i < length; ++i) out.push_back(kAlphabet[randombytes_uniform(sizeof kAlphabet - 1)]);
  return out;
}

}  // namespace sd::storage
