#pragma once
// SwarmDesign accounts: user names with Argon2id password hashes.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/sqlite.hpp"

namespace sd::storage {

struct User {
  std::int64_t id = 0;
  std::string name;
  std::int64_t created_at = 0;
};

bool user_exists(Database& db, std::string_view name);

/// Creates an account; Conflict if the name is taken (names are case-insensitive). `also` runs
/// in the same transaction once the row is in (an invitation used up): if it throws, no
/// account is made.
User create_user(Database& db, std::string_view name, std::string_view password,
                 const std::function<void(const User&)>& also = {});

/// The account if the password is right; AccessDenied with the same words for an unknown name
/// and a wrong password, after the same work (an unknown name is checked against a dummy
/// Argon2id hash), so neither the answer nor its time tells which names exist. Re-hashes an
/// old-limits hash on success.
User authenticate(Database& db, std::string_view name, std::string_view password);

std::vector<User> list_users(Database& db);

}  // namespace sd::storage
