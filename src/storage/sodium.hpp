#pragma once
// libsodium, as the storage layer uses it for secrets that are not passwords (those are
// Argon2id hashes, passwords.hpp): it must be initialised once before use.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>

namespace sd::storage {

void ensure_sodium();

/// What is stored of a secret that the program itself drew (a session token, an invitation
/// code): its BLAKE2b-256 digest. Such a secret has far more entropy than a password, so a
/// fast hash suffices, and a stolen database still opens no session and makes no account.
using SecretHash = std::array<unsigned char, 32>;
SecretHash hash_secret(std::string_view secret);

/// `length` letters and digits from libsodium's generator, none that look alike (56 symbols,
/// about 5.8 bits each): a secret a person types or pastes (an invitation, a one-time password).
std::string readable_secret(std::size_t length);

}  // namespace sd::storage
