#include "app/inputs.hpp"

#include <random>

#include "app/errors.hpp"
#include "storage/validation.hpp"

namespace sd::app {

namespace {
bool is_decimal(const std::string& text) {
  return !text.empty() && text.size() <= 19 && text.find_first_not_of("0123456789") == std::string::npos;
}
}  // namespace

long long parse_budget(const std::string& text) {
  const auto budget = storage::parse_positive_integer(text);
  if (!budget)
    throw InvalidRequest("budget '" + text + "': expected a positive integer (a number of simulation runs, e.g. 20000)");
  return *budget;
}

std::uint64_t parse_seed(const std::string& text) {
  if (!is_decimal(text)) throw InvalidRequest("seed '" + text + "': expected a non-negative integer");
  return std::stoull(text);
}

std::vector<std::uint64_t> parse_seed_range(const std::string& text) {
  const auto bound = [&](const std::string& part) -> std::uint64_t {
    if (!is_decimal(part)) throw InvalidRequest("seeds '" + text + "': expected S or A-B with non-negative integers");
    return std::stoull(part);
  };
  const auto dash = text.find('-');
  if (dash == std::string::npos) return {bound(text)};
  const std::uint64_t a = bound(text.substr(0, dash)), b = bound(text.substr(dash + 1));
  if (b < a) throw InvalidRequest("seeds '" + text + "': the range is empty");
  if (b - a >= 1'000'000) throw InvalidRequest("seeds '" + text + "': at most 1,000,000 seeds");
  std::vector<std::uint64_t> seeds;
  for (std::uint64_t s = a; s <= b; ++s) seeds.push_back(s);
  return seeds;
}

std::uint64_t random_seed() {
  std::random_device device;
  return std::uniform_int_distribution<std::uint64_t>(1, 2147483647)(device);
}

}  // namespace sd::app
