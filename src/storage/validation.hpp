#pragma once
// Rules for what users type: names that become folder names, hosts, budgets. Each check
// returns the problem in words (empty when the value is fine), so the command line can
// report it as misuse and the stores can refuse it as a last line of defence.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace sd::storage {

/// 1-32 characters: a letter, then letters, digits, '.', '_' or '-'.
std::string user_name_problem(std::string_view name);

/// 1-64 characters: a letter or digit, then letters, digits, '.', '_' or '-'
/// (it becomes a folder name, so no path separators, no "..", no leading dot).
std::string project_name_problem(std::string_view name);

/// A host name or IPv4 address for a cluster connection; never starts with '-', so it can
/// never be read as an option by ssh later.
std::string host_problem(std::string_view host);

/// A login name on a cluster: letters, digits, '.', '_' or '-', not starting with '-'.
std::string cluster_user_problem(std::string_view user);
/// A path on a cluster (its job folder, its swarmdesign program): "" (the default) or a path
/// of printable characters without quotes, '$', '`', '\\' or newlines (it goes into job scripts).
std::string cluster_path_problem(std::string_view what, std::string_view path);

/// Decimal digits only, no sign, at least 1, fits in 64 bits; nullopt otherwise.
std::optional<std::int64_t> parse_positive_integer(std::string_view text);

}  // namespace sd::storage
