#pragma once
// The arena a swarm lives in, compiled once per mission and then only read (the MuJoCo
// model/data split): walls, floor colours, lights, and lookup tables derived from them so
// that the per-tick queries touch only the walls that can matter.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/geometry.hpp"
#include "simulator/region.hpp"

namespace sd {

/// A static box wall: a rectangle in the plane, extruded to `height`.
struct Wall {
  Vec2 center;
  Vec2 axis{1.0, 0.0};         // unit vector along the wall's length
  double half_length = 0.0;
  double half_thickness = 0.0;
  double height = 0.08;
  std::uint32_t led_color = 0; // RGB of the wall's LEDs (0 = none), for coloured arenas

  Vec2 normal() const { return {-axis.y, axis.x}; }
  double bounding_radius() const;
  /// Distance from p to the wall's rectangle and the unit normal pointing from the wall to p.
  double distance(Vec2 p, Vec2* outward_normal) const;
  /// First parameter t in [0, 1] where the segment a->b enters the rectangle, or a value > 1.
  double segment_entry(Vec2 a, Vec2 b) const;
};

struct FloorPatch {
  Region region;
  double gray = 0.0;            // ground-sensor value, grayscale / 255
  std::uint32_t rgb = 0;        // for drawing
};

/// An LED on a wall block (TuttiFrutti arenas); its colour changes during a run, so the
/// colour lives in SwarmState::arena_led_color, initialised from `initial_color`.
struct ArenaLed {
  Vec3 position;
  std::uint16_t wall = 0;
  std::uint32_t initial_color = 0;  // 0 = off
};

struct Light {
  Vec3 position;
  double intensity = 0.0;
  std::uint32_t rgb = 0xffff00;
};

/// Gray levels of ARGoS' named colours as the ground sensor sees them.
inline constexpr double kGrayBlack = 0.0;
inline constexpr double kGrayWhite = 1.0;
inline constexpr double kGray50 = 127.0 / 255.0;

/// Compressed lists of wall indices per grid cell.
struct CellLists {
  std::vector<std::uint32_t> offsets;  // cells + 1
  std::vector<std::uint16_t> items;
  std::span<const std::uint16_t> at(std::size_t cell) const {
    return {items.data() + offsets[cell], items.data() + offsets[cell + 1]};
  }
};

class ArenaModel {
 public:
  std::vector<Wall> walls;
  std::vector<FloorPatch> floor_patches;  // first match wins
  double floor_background_gray = kGray50;
  std::uint32_t floor_background_rgb = 0x7f7f7f;
  std::vector<Light> lights;
  std::vector<ArenaLed> leds;

  /// Builds the lookup tables; call once after filling the fields above.
  void compile();

  double floor_gray(Vec2 p) const {
    for (const FloorPatch& patch : floor_patches)
      if (patch.region.contains(p)) return patch.gray;
    return floor_background_gray;
  }
  /// The floor's gray everywhere within kUniformFloorReach of p, or a negative value if the
  /// floor may change within that distance (then ask floor_gray point by point). Most robots
  /// are far from any patch edge, and this spares them a region test per ground sensor.
  double uniform_floor_gray(Vec2 p) const {
    const double fx = (p.x - floor_origin_.x) * kFloorCellsPerMetre, fy = (p.y - floor_origin_.y) * kFloorCellsPerMetre;
    if (!(fx >= 0.0 && fy >= 0.0)) return -1.0;
    const auto cx = static_cast<std::size_t>(fx), cy = static_cast<std::size_t>(fy);
    if (cx >= floor_w_ || cy >= floor_h_) return -1.0;
    return floor_cell_gray_[cy * floor_w_ + cx];
  }
  static constexpr double kUniformFloorReach = 0.032;  // m: the ground sensors are 3.13 cm from the centre

  /// Walls within kWallReach of p (contacts and proximity rays).
  std::span<const std::uint16_t> walls_near(Vec2 p) const {
    const std::size_t c = cell_of(p);
    return c == kOutside ? std::span<const std::uint16_t>(all_walls_) : near_.at(c);
  }
  /// Walls that may block the rising ray from ground point p to light `light`.
  std::span<const std::uint16_t> walls_shading(std::size_t light, Vec2 p) const {
    const std::size_t c = cell_of(p);
    return c == kOutside ? std::span<const std::uint16_t>(all_walls_) : shading_[light].at(c);
  }
  /// True if no wall separates p from q (walls that enclose every robot are skipped: a
  /// segment between two robots can never cross them).
  bool line_of_sight_walls(Vec2 p, Vec2 q) const;
  /// True if no wall stops the descending camera ray from `camera` to `led` (only walls that
  /// can separate two points inside the arena are checked). `skip_wall` is the LED's own.
  bool camera_line_of_sight(Vec3 camera, Vec3 led, int skip_wall = -1) const;
  /// The fraction of the way to a light beyond which a rising ray clears a body of `height`.
  double light_clearance_fraction(std::size_t light, double height) const;

  static constexpr double kWallReach = 0.16;  // m: body radius + proximity reach + motion margin

 private:
  static constexpr std::size_t kOutside = static_cast<std::size_t>(-1);
  // A multiplication, not a division: a point within an ulp of a cell border may land in
  // either cell, and both cells' lists hold every wall within reach of it.
  std::size_t cell_of(Vec2 p) const {
    const double fx = (p.x - grid_origin_.x) * kCellsPerMetre, fy = (p.y - grid_origin_.y) * kCellsPerMetre;
    if (!(fx >= 0.0 && fy >= 0.0)) return kOutside;
    const auto cx = static_cast<std::size_t>(fx), cy = static_cast<std::size_t>(fy);
    if (cx >= grid_w_ || cy >= grid_h_) return kOutside;
    return cy * grid_w_ + cx;
  }

  Vec2 grid_origin_;
  static constexpr double kCellsPerMetre = 10.0;
  static constexpr double kCellSize = 1.0 / kCellsPerMetre;  // m
  std::size_t grid_w_ = 0, grid_h_ = 0;
  CellLists near_;
  std::vector<CellLists> shading_;
  std::vector<std::uint16_t> all_walls_;
  std::vector<std::uint16_t> interior_walls_;  // walls that can separate two robots

  static constexpr double kFloorCellsPerMetre = 50.0;
  Vec2 floor_origin_;
  std::size_t floor_w_ = 0, floor_h_ = 0;
  std::vector<double> floor_cell_gray_;  // per cell: the gray of its whole neighbourhood, or -1
  void compile_floor_cells(Vec2 lo, Vec2 hi);
};

}  // namespace sd
