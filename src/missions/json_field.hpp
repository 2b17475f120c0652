#pragma once
// A JSON value together with its path in the mission file, so that every reader of the
// mission format reports errors as "arena.floor.patches[1].radius: must be positive".
#include <nlohmann/json.hpp>

#include <climits>
#include <cmath>
#include <initializer_list>
#include <set>
#include <string>

#include "core/geometry.hpp"
#include "core/json_integer.hpp"
#include "missions/mission.hpp"

namespace sd {

class Field {
 public:
  using json = nlohmann::json;

  Field(const json& value, std::string path) : value_(&value), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& what) const { throw MissionError(path_ + ": " + what); }

  const std::string& path() const { return path_; }
  const json& raw() const { return *value_; }

  Field at(const std::string& key) const {
    expect_object();
    if (!value_->contains(key)) throw MissionError(child_path(key) + ": missing field");
    return Field(value_->at(key), child_path(key));
  }
  bool has(const std::string& key) const { return value_->is_object() && value_->contains(key); }
  Field at(std::size_t index) const { return Field(value_->at(index), path_ + "[" + std::to_string(index) + "]"); }
  /// Number of items of a list (fails on anything else).
  std::size_t items() const { return array().size(); }

  /// Rejects keys this reader does not know: a misspelt field must not be ignored.
  void only(std::initializer_list<const char*> keys) const {
    expect_object();
    const std::set<std::string> allowed(keys.begin(), keys.end());
    for (const auto& [key, v] : value_->items())
      if (!allowed.count(key)) throw MissionError(child_path(key) + ": unknown field");
  }

  void expect_object() const {
    if (!value_->is_object()) fail("expected an object");
  }
  const json& array() const {
    if (!value_->is_array()) fail("expected a list");
    return *value_;
  }
  double number() const {
    if (!value_->is_number()) fail("expected a number");
    const double v = value_->get<double>();
    if (!std::isfinite(v)) fail("expected a finite number");
    return v;
  }
  double positive() const {
    const double v = number();
    if (v <= 0.0) fail("must be positive");
    return v;
  }
  double non_negative() const {
    const double v = number();
    if (v < 0.0) fail("must not be negative");
    return v;
  }
  double probability() const {
    const double v = number();
    if (v < 0.0 || v > 1.0) fail("must be in [0, 1]");
    return v;
  }
  int integer() const {
    if (!value_->is_number_integer()) fail("expected an integer");
    const auto v = json_integer<int>(*value_);  // 2^40 would wrap into range as an int
    if (!v) fail("must be between " + std::to_string(INT_MIN) + " and " + std::to_string(INT_MAX));
    return *v;
  }
  int integer_in(int lo, int hi) const {
    const int v = integer();
    if (v < lo || v > hi) fail("must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    return v;
  }
  bool boolean() const {
    if (!value_->is_boolean()) fail("expected true or false");
    return value_->get<bool>();
  }
  std::string text() const {
    if (!value_->is_string()) fail("expected a string");
    return value_->get<std::string>();
  }
  Vec2 vec2() const {
    if (!value_->is_array() || value_->size() != 2) fail("expected [x, y]");
    return {at(0).number(), at(1).number()};
  }
  Vec3 vec3() const {
    if (!value_->is_array() || value_->size() != 3) fail("expected [x, y, z]");
    return {at(0).number(), at(1).number(), at(2).number()};
  }

  // Optional fields with a default.
  double number_or(const std::string& key, double fallback) const { return has(key) ? at(key).number() : fallback; }
  double positive_or(const std::string& key, double fallback) const { return has(key) ? at(key).positive() : fallback; }
  bool boolean_or(const std::string& key, bool fallback) const { return has(key) ? at(key).boolean() : fallback; }

 private:
  std::string child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const json* value_;
  std::string path_;
};

}  // namespace sd
