#pragma once
// A JSON value together with its path in the mission file, so that every reader of the
// mission format reports errors as "arena.floor.patches[1].radius: must be positive".
// Only the forward declaration of nlohmann::json here: the readers of each mission part see
// Field, not the JSON library, which costs every file that parsed it seconds to compile and check.
#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <initializer_list>
#include <string>

#include "core/geometry.hpp"
#include "missions/mission.hpp"

namespace sd {

class Field {
 public:
  using json = nlohmann::json;

  Field(const json& value, std::string path) : value_(&value), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& what) const;

  const std::string& path() const { return path_; }
  const json& raw() const { return *value_; }

  Field at(const std::string& key) const;
  bool has(const std::string& key) const;
  Field at(std::size_t index) const;
  /// Number of items of a list (fails on anything else).
  std::size_t items() const;

  /// Rejects keys this reader does not know: a misspelt field must not be ignored.
  void only(std::initializer_list<const char*> keys) const;

  void expect_object() const;
  bool is_object() const;
  bool is_text() const;
  /// The one key of an object that must hold exactly one of `expected` (a list to name in the
  /// error), such as a region's "circle" or "polygon".
  std::string single_key(const std::string& expected) const;
  const json& array() const;
  double number() const;
  double positive() const;
  double non_negative() const;
  double probability() const;
  int integer() const;
  int integer_in(int lo, int hi) const;
  bool boolean() const;
  std::string text() const;
  Vec2 vec2() const;
  Vec3 vec3() const;

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
