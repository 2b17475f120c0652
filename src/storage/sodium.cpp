#include "storage/sodium.hpp"

#include <sodium.h>

#include <stdexcept>

namespace sd::storage {
void ensure_sodium() {
  // sodium_init is thread-safe and idempotent (returns 1 when already done).
  if (sodium_init() < 0) throw std::runtime_error("cannot initialise libsodium");
}
}  // namespace sd::storage
