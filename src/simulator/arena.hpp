#pragma once
// The arena a swarm lives in, compiled once per mission and then only read (the MuJoCo
// model/data split): walls, floor colours, lights, and lookup tables derived from them so
// that the per-tick queries touch only the walls that can matter.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/geometry.hpp"
#include "simulator/region.hpp"

namespace sd {

/// Eight segments as coordinate arrays (a robot's proximity rays), for Wall::segment_entries.
struct SegmentBatch {
  static constexpr std::size_t kSize = 8;
  std::array<double, kSize> ax, ay, bx, by;
};

/// A static box wall: a rectangle in the plane, extruded to `height`.
struct Wall {
  Vec2 center;
  Vec2 axis{1.0, 0.0};         // unit vector along the wall's length
  double half_length = 0.0;
  double half_thickness = 0.0;
  double height = 0.08;
  std::uint32_t led_color = 0; // RGB of the wall's LEDs (0 = none), for coloured arenas
  /// Added by the loop function after the robots were placed (ARGoS SCA adds its shelter in
  /// Init, after MoveRobots): placement does not avoid it, so a robot may start inside it.
  bool placed_after_robots = false;

  Vec2 normal() const { return {-axis.y, axis.x}; }
  double bounding_radius() const;
  /// Distance from p to the wall's rectangle and the unit normal pointing from the wall to p.
  /// Inside, minus the distance to the nearest side, whose outward normal it gives (the
  /// side Chipmunk's circle-polygon test pushes a body out of: the least penetration).
  double distance(Vec2 p, Vec2* outward_normal) const;
  /// For limit >= 0, true only if distance(p, nullptr) > limit, without its square root:
  /// most walls a grid cell lists are far out of a robot's reach, and this rules them out
  /// first. Outside the wall, the larger of the gaps along its axis and across it bounds the
  /// distance from below, and kBoundMargin covers rounding, so no wall the exact test would
  /// keep is ever ruled out. (Inside, distance() is minus the depth to the nearest side,
  /// which the larger gap does not bound: hence no negative limit.)
  bool surely_beyond(Vec2 p, double limit) const {
    const Vec2 d = p - center;
    const double gap = std::max(std::abs(dot(d, axis)) - half_length, std::abs(dot(d, normal())) - half_thickness);
    return gap > limit + kBoundMargin;
  }
  static constexpr double kBoundMargin = 1e-9;  // m: orders of magnitude above any rounding in an arena
  /// First parameter t in [0, 1] where the segment a->b enters the rectangle, or a value > 1.
  /// A segment starting inside "enters" at 0.
  double segment_entry(Vec2 a, Vec2 b) const;
  /// True if p lies strictly inside the rectangle. A ray cast from there does not meet this
  /// wall in ARGoS: Chipmunk's segment query only tests the sides the start lies in front of.
  bool contains(Vec2 p) const {
    const Vec2 d = p - center;
    return std::abs(dot(d, axis)) < half_length && std::abs(dot(d, normal())) < half_thickness;
  }
  /// segment_entry of each segment of the batch, exactly, in one pass that vectorises.
  void segment_entries(const SegmentBatch& segments, std::span<double, SegmentBatch::kSize> t) const;
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

/// A square grid laid over the arena, for look-up tables: the cell a point falls in, and
/// cell centres. Cells are numbered row by row.
struct GridFrame {
  static constexpr std::size_t kOutside = static_cast<std::size_t>(-1);
  Vec2 origin;
  double cells_per_metre = 1.0;
  std::size_t width = 0, height = 0;

  /// The grid of cells of 1 / cells_per_metre that covers the box [lo, hi].
  static GridFrame covering(Vec2 lo, Vec2 hi, double cells_per_metre);
  std::size_t cells() const { return width * height; }
  double cell_size() const { return 1.0 / cells_per_metre; }
  double half_diagonal() const;
  /// The cell of p, or kOutside. A multiplication, not a division: a point within an ulp of
  /// a cell border may land in either cell, so every table is built to hold, in both cells,
  /// whatever is true around such a point.
  std::size_t cell_of(Vec2 p) const {
    const double fx = (p.x - origin.x) * cells_per_metre, fy = (p.y - origin.y) * cells_per_metre;
    if (!(fx >= 0.0 && fy >= 0.0)) return kOutside;
    const auto cx = static_cast<std::size_t>(fx), cy = static_cast<std::size_t>(fy);
    if (cx >= width || cy >= height) return kOutside;
    return cy * width + cx;
  }
  Vec2 center(std::size_t cell) const;
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
    const std::size_t c = floor_grid_.cell_of(p);
    return c == GridFrame::kOutside ? -1.0 : floor_cell_gray_[c];
  }
  static constexpr double kUniformFloorReach = 0.032;  // m: the ground sensors are 3.13 cm from the centre

  /// Walls within kWallReach of p (contacts and proximity rays).
  std::span<const std::uint16_t> walls_near(Vec2 p) const {
    const std::size_t c = wall_grid_.cell_of(p);
    return c == GridFrame::kOutside ? std::span<const std::uint16_t>(all_walls_) : near_.at(c);
  }
  /// Walls that may block the rising ray from ground point p to light `light`.
  std::span<const std::uint16_t> walls_shading(std::size_t light, Vec2 p) const {
    const std::size_t c = wall_grid_.cell_of(p);
    return c == GridFrame::kOutside ? std::span<const std::uint16_t>(all_walls_) : shading_[light].at(c);
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
  GridFrame wall_grid_;  // 10 cm cells: the wall lists below
  CellLists near_;
  std::vector<CellLists> shading_;
  std::vector<std::uint16_t> all_walls_;
  std::vector<std::uint16_t> interior_walls_;  // walls that can separate two robots

  GridFrame floor_grid_;  // 2 cm cells
  std::vector<double> floor_cell_gray_;  // per cell: the gray of its whole neighbourhood, or -1
  void compile_floor_cells(Vec2 lo, Vec2 hi);
};

}  // namespace sd
