#include "simulator/arena.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/branchless.hpp"
#include "core/vector_clones.hpp"

namespace sd {

namespace {

template <typename Predicate>
CellLists build_lists(std::size_t cells, std::size_t wall_count, Predicate&& keep) {
  CellLists lists;
  lists.offsets.reserve(cells + 1);
  lists.offsets.push_back(0);
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t w = 0; w < wall_count; ++w)
      if (keep(c, w)) lists.items.push_back(static_cast<std::uint16_t>(w));
    lists.offsets.push_back(static_cast<std::uint32_t>(lists.items.size()));
  }
  return lists;
}

}  // namespace

double Wall::bounding_radius() const { return std::sqrt(half_length * half_length + half_thickness * half_thickness); }

double Wall::distance(Vec2 p, Vec2* outward_normal) const {
  const Vec2 d = p - center;
  const Vec2 n = normal();
  const double lx = dot(d, axis), ly = dot(d, n);
  const double qx = std::clamp(lx, -half_length, half_length), qy = std::clamp(ly, -half_thickness, half_thickness);
  const double ex = lx - qx, ey = ly - qy;
  const double dist = std::sqrt(ex * ex + ey * ey);
  if (dist > 0.0) {
    if (outward_normal) *outward_normal = (axis * ex + n * ey) * (1.0 / dist);
    return dist;
  }
  // Inside the box: the nearest side (across the wall unless p is nearer an end).
  const double across = half_thickness - std::abs(ly), along = half_length - std::abs(lx);
  if (along < across) {
    if (outward_normal) *outward_normal = lx >= 0.0 ? axis : -axis;
    return -along;
  }
  if (outward_normal) *outward_normal = ly >= 0.0 ? n : -n;
  return -across;
}

namespace {

/// The slab test of segment_entry for one segment given by its ends' coordinates, written
/// without jumps: whether a proximity ray or a line of sight meets a wall is a coin toss for
/// the predictor. `pick(c, a, b)` is `c ? a : b`: sd::select for one segment (GCC would
/// jump on a plain conditional), a plain conditional in a loop over segments (which then
/// vectorises, and select's bit masks would stop it). An axis the segment runs along
/// (|d| < 1e-15) constrains nothing if the segment lies within the slab, and rules the hit
/// out if it does not. Entry and exit bounds are gathered first and compared once, which
/// gives what testing after each axis gives, since the bounds only tighten.
template <typename Pick>
inline double slab_entry(const Wall& wall, double ax, double ay, double bx, double by, Pick pick) {
  const Vec2 n = wall.normal();
  const double dax = ax - wall.center.x, day = ay - wall.center.y;
  const double dbx = bx - wall.center.x, dby = by - wall.center.y;
  double enter = 0.0, leave = 1.0;
  auto slab = [&](double from, double to, double half) {
    const double d = to - from;
    const bool along = std::abs(d) < 1e-15;
    const double safe_d = pick(along, 1.0, d);
    const double ta = (-half - from) / safe_d, tb = (half - from) / safe_d;
    const double inf = std::numeric_limits<double>::infinity();
    const bool outside = std::abs(from) > half;
    const double lo = pick(along, pick(outside, inf, -inf), pick(ta < tb, ta, tb));
    const double hi = pick(along, pick(outside, -inf, inf), pick(ta < tb, tb, ta));
    enter = pick(enter < lo, lo, enter);
    leave = pick(hi < leave, hi, leave);
  };
  slab(dax * wall.axis.x + day * wall.axis.y, dbx * wall.axis.x + dby * wall.axis.y, wall.half_length);
  slab(dax * n.x + day * n.y, dbx * n.x + dby * n.y, wall.half_thickness);
  return pick(enter > leave, 2.0, enter);
}

}  // namespace

double Wall::segment_entry(Vec2 a, Vec2 b) const {
  return slab_entry(*this, a.x, a.y, b.x, b.y, [](bool c, double x, double y) { return select(c, x, y); });
}

SD_VECTOR_CLONES void Wall::segment_entries(const SegmentBatch& segments, std::span<double, SegmentBatch::kSize> t) const {
  auto pick = [](bool c, double a, double b) { return c ? a : b; };
  for (std::size_t k = 0; k < SegmentBatch::kSize; ++k)
    t[k] = slab_entry(*this, segments.ax[k], segments.ay[k], segments.bx[k], segments.by[k], pick);
}

bool ArenaModel::camera_line_of_sight(Vec3 camera, Vec3 led, int skip_wall) const {
  for (const std::uint16_t w : interior_walls_) {
    if (static_cast<int>(w) == skip_wall) continue;
    const Wall& wall = walls[w];
    // The ray descends from the camera to the LED; it is blocked if it is inside the wall's
    // footprint anywhere below the wall's top, i.e. at its exit from the footprint.
    const double t_in = wall.segment_entry(camera.xy(), led.xy());
    if (t_in > 1.0) continue;
    const double t_out = 1.0 - wall.segment_entry(led.xy(), camera.xy());
    const double z_out = camera.z + (led.z - camera.z) * std::min(t_out, 1.0);
    if (z_out <= wall.height) return false;
  }
  return true;
}

double ArenaModel::light_clearance_fraction(std::size_t light, double height) const {
  const double z = lights[light].position.z;
  return z > height ? height / z : 1.0;
}

GridFrame GridFrame::covering(Vec2 lo, Vec2 hi, double cells_per_metre) {
  GridFrame grid;
  grid.origin = lo;
  grid.cells_per_metre = cells_per_metre;
  grid.width = static_cast<std::size_t>(std::ceil((hi.x - lo.x) * cells_per_metre));
  grid.height = static_cast<std::size_t>(std::ceil((hi.y - lo.y) * cells_per_metre));
  return grid;
}

double GridFrame::half_diagonal() const { return cell_size() * std::sqrt(0.5); }

Vec2 GridFrame::center(std::size_t cell) const {
  // NOLINTNEXTLINE(bugprone-integer-division): cell / width is the row, an integer
  return origin + Vec2{(static_cast<double>(cell % width) + 0.5) * cell_size(), (static_cast<double>(cell / width) + 0.5) * cell_size()};
}

bool ArenaModel::line_of_sight_walls(Vec2 p, Vec2 q) const {
  for (const std::uint16_t w : interior_walls_)
    if (walls[w].segment_entry(p, q) <= 1.0) return false;
  return true;
}

void ArenaModel::compile() {
  all_walls_.clear();
  interior_walls_.clear();
  for (std::size_t w = 0; w < walls.size(); ++w) all_walls_.push_back(static_cast<std::uint16_t>(w));

  // A wall that has every other wall on its inner side encloses the swarm: robots start
  // inside and contacts keep them there, so no robot-to-robot segment can cross it.
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const Wall& wall = walls[w];
    const Vec2 n = wall.normal();
    int side = 0;
    bool encloses = walls.size() >= 3;
    for (std::size_t o = 0; o < walls.size() && encloses; ++o) {
      if (o == w) continue;
      const Wall& other = walls[o];
      for (const double sa : {-1.0, 1.0})
        for (const double sb : {-1.0, 1.0}) {
          const Vec2 corner = other.center + other.axis * (sa * other.half_length) + other.normal() * (sb * other.half_thickness);
          const double s = dot(corner - wall.center, n);
          if (std::abs(s) <= wall.half_thickness + 1e-6) continue;
          const int this_side = s > 0.0 ? 1 : -1;
          if (side == 0) side = this_side;
          else if (side != this_side) encloses = false;
        }
    }
    if (!encloses) interior_walls_.push_back(static_cast<std::uint16_t>(w));
  }

  // Grid over the walls' bounds with a margin, for the per-tick wall look-ups.
  Vec2 lo{-0.5, -0.5}, hi{0.5, 0.5};
  for (const Wall& wall : walls) {
    const double r = wall.bounding_radius();
    lo = {std::min(lo.x, wall.center.x - r), std::min(lo.y, wall.center.y - r)};
    hi = {std::max(hi.x, wall.center.x + r), std::max(hi.y, wall.center.y + r)};
  }
  const Vec2 margin{0.3, 0.3};
  wall_grid_ = GridFrame::covering(lo - margin, hi + margin, 10.0);
  const std::size_t cells = wall_grid_.cells();
  const double half_diagonal = wall_grid_.half_diagonal();

  compile_floor_cells(lo, hi);

  near_ = build_lists(cells, walls.size(), [&](std::size_t c, std::size_t w) {
    return walls[w].distance(wall_grid_.center(c), nullptr) <= kWallReach + half_diagonal;
  });

  // A ray rising from p towards a light clears a wall of height H after the fraction
  // H / z of the way; for every p in a cell those truncated rays lie within the cell's
  // half-diagonal of the ray from the cell's centre.
  shading_.clear();
  for (std::size_t l = 0; l < lights.size(); ++l) {
    const Vec2 target = lights[l].position.xy();
    shading_.push_back(build_lists(cells, walls.size(), [&](std::size_t c, std::size_t w) {
      const Vec2 p = wall_grid_.center(c);
      const double t = light_clearance_fraction(l, walls[w].height);
      return distance_to_segment(walls[w].center, p, p + (target - p) * t) <= half_diagonal + walls[w].bounding_radius();
    }));
  }
}

void ArenaModel::compile_floor_cells(Vec2 lo, Vec2 hi) {
  for (const FloorPatch& patch : floor_patches) {
    const auto [plo, phi] = patch.region.bounds();
    lo = {std::min(lo.x, plo.x), std::min(lo.y, plo.y)};
    hi = {std::max(hi.x, phi.x), std::max(hi.y, phi.y)};
  }
  floor_grid_ = GridFrame::covering(lo, hi, 50.0);
  floor_cell_gray_.assign(floor_grid_.cells(), -1.0);
  // A cell is uniform when every patch edge is further from its centre than its half-diagonal
  // plus the sensors' reach: then each patch contains all of the neighbourhood or none of it,
  // and the first match (hence the gray) is the same everywhere in it.
  const double clearance = floor_grid_.half_diagonal() + kUniformFloorReach + 1e-9;
  for (std::size_t cell = 0; cell < floor_grid_.cells(); ++cell) {
    const Vec2 c = floor_grid_.center(cell);
    const bool uniform = std::all_of(floor_patches.begin(), floor_patches.end(),
                                     [&](const FloorPatch& patch) { return patch.region.boundary_distance(c) > clearance; });
    if (uniform) floor_cell_gray_[cell] = floor_gray(c);
  }
}

}  // namespace sd
