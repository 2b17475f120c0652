// Field's readers: each names the path of what is wrong in one line.
#include "missions/json_field.hpp"

#include <nlohmann/json.hpp>

#include <climits>
#include <cmath>
#include <set>

#include "core/json_integer.hpp"

namespace sd {

void Field::fail(const std::string& what) const { throw MissionError(path_ + ": " + what); }

Field Field::at(const std::string& key) const {
  expect_object();
  if (!value_->contains(key)) throw MissionError(child_path(key) + ": missing field");
  return Field(value_->at(key), child_path(key));
}
bool Field::has(const std::string& key) const { return value_->is_object() && value_->contains(key); }
Field Field::at(std::size_t index) const { return Field(value_->at(index), path_ + "[" + std::to_string(index) + "]"); }
std::size_t Field::items() const { return array().size(); }

void Field::only(std::initializer_list<const char*> keys) const {
  expect_object();
  const std::set<std::string> allowed(keys.begin(), keys.end());
  for (const auto& [key, v] : value_->items())
    if (!allowed.count(key)) throw MissionError(child_path(key) + ": unknown field");
}

void Field::expect_object() const {
  if (!value_->is_object()) fail("expected an object");
}
bool Field::is_object() const { return value_->is_object(); }
bool Field::is_text() const { return value_->is_string(); }
std::string Field::single_key(const std::string& expected) const {
  expect_object();
  if (value_->size() != 1) fail("expected exactly one of " + expected);
  return value_->begin().key();
}
const Field::json& Field::array() const {
  if (!value_->is_array()) fail("expected a list");
  return *value_;
}
double Field::number() const {
  if (!value_->is_number()) fail("expected a number");
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("expected a finite number");
  return v;
}
double Field::positive() const {
  const double v = number();
  if (v <= 0.0) fail("must be positive");
  return v;
}
double Field::non_negative() const {
  const double v = number();
  if (v < 0.0) fail("must not be negative");
  return v;
}
double Field::probability() const {
  const double v = number();
  if (v < 0.0 || v > 1.0) fail("must be in [0, 1]");
  return v;
}
int Field::integer() const {
  if (!value_->is_number_integer()) fail("expected an integer");
  const auto v = json_integer<int>(*value_);  // 2^40 would wrap into range as an int
  if (!v) fail("must be between " + std::to_string(INT_MIN) + " and " + std::to_string(INT_MAX));
  return *v;
}
int Field::integer_in(int lo, int hi) const {
  const int v = integer();
  if (v < lo || v > hi) fail("must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return v;
}
bool Field::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false");
  return value_->get<bool>();
}
std::string Field::text() const {
  if (!value_->is_string()) fail("expected a string");
  return value_->get<std::string>();
}
Vec2 Field::vec2() const {
  if (!value_->is_array() || value_->size() != 2) fail("expected [x, y]");
  return {at(0).number(), at(1).number()};
}
Vec3 Field::vec3() const {
  if (!value_->is_array() || value_->size() != 3) fail("expected [x, y, z]");
  return {at(0).number(), at(1).number(), at(2).number()};
}

}  // namespace sd
