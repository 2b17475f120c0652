#pragma once
// Readers for the geometric pieces every part of a mission file uses: colours, floor
// regions, zones (regions, rings, limits) and robot filters.
#include <cstdint>

#include "missions/json_field.hpp"
#include "missions/zone.hpp"

namespace sd {

/// ARGoS colour names (gray = GRAY50) or "#rrggbb".
std::uint32_t read_color(const Field& f);
/// What the ground sensor reads on a colour: grayscale / 255 (ARGoS ToGrayScale weights).
double gray_of(std::uint32_t rgb);

/// {"circle": {...}} | {"rectangle": {...}} | {"polygon": [...]}
Region read_region(const Field& f);
/// A region, or {"ring": {"center", "radius", "half_width"}}, or
/// {"limits": {"x_min", "x_max", "y_min", "y_max", "strict"}} (at least one limit).
Zone read_zone(const Field& f);
/// Absent: all robots; {"in": ZONE}; {"not_in": [ZONE, ...]}.
RobotFilter read_robot_filter(const Field& parent, const char* key);

}  // namespace sd
