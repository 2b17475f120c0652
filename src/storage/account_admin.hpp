#pragma once
// What a server's administrator does to accounts (issue #56): roles, disabling, a new password,
// deleting; and what each user does to their own (a new password). Every change that should
// end a session ends it here, in the same transaction.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/accounts.hpp"
#include "storage/sqlite.hpp"

namespace sd::storage {

enum class Role { User, Admin };

struct AccountRow {
  User user;
  Role role = Role::User;
  bool disabled = false;
  std::optional<std::int64_t> last_sign_in;  // Unix seconds; never signed in: nullopt
};

std::vector<AccountRow> account_rows(Database& db);
/// NotFound for an unknown name.
AccountRow account_row(Database& db, std::string_view name);

/// Disables (every session of the account ends) or enables it.
void set_disabled(Database& db, std::int64_t user_id, bool disabled);
void set_role(Database& db, std::int64_t user_id, Role role);
/// Stores `password`'s Argon2id hash (InvalidInput when it breaks the rule) and ends every
/// session of the account but `keep_token`'s (the one that asked, for a user's own change).
void set_password(Database& db, const User& user, std::string_view password, std::optional<std::string_view> keep_token);
/// Deletes the account's rows (its projects, designs and sessions go with them).
void delete_account_rows(Database& db, std::int64_t user_id);

std::string_view role_name(Role role);

}  // namespace sd::storage
