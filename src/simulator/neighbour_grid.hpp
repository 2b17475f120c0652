#pragma once
// A uniform grid over the robots' centres, rebuilt every tick, so that in a large swarm each
// robot looks only at the robots near it instead of at all of them (what makes the cost per
// robot grow with the swarm). Robots are binned by a counting sort: within a cell they keep
// ascending index order, and the cells of one grid row are contiguous, so a box query is a
// few contiguous runs of coordinates that a plain loop can vectorise.
//
// The grid only ever narrows which robots are looked at; every caller applies its own exact
// test to what it gets, in robot-index order where order matters, so results do not depend
// on whether the grid is used.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geometry.hpp"

namespace sd {

class NeighbourGrid {
 public:
  /// Sizes the buffers for `robots` robots, so that build never allocates.
  void reserve(std::size_t robots);
  /// Bins the centres (x[i], y[i]) into square cells of side at least `cell`: a box query
  /// of half-width `cell` around a centre then meets at most 3 x 3 cells.
  void build(const double* x, const double* y, int robots, double cell);

  /// Calls visit(begin, end) for contiguous ranges [begin, end) of the binned arrays (x(),
  /// y(), robot()) that together hold every robot whose centre lies in the box
  /// [lo_x, hi_x] x [lo_y, hi_y], and possibly others near it.
  template <class Visit>
  void for_each_run(double lo_x, double lo_y, double hi_x, double hi_y, Visit&& visit) const {
    const int first_column = column(lo_x), last_column = column(hi_x);
    for (int r = row(lo_y), last_row = row(hi_y); r <= last_row; ++r) {
      const std::size_t base = static_cast<std::size_t>(r) * static_cast<std::size_t>(columns_);
      const int begin = cell_start_[base + static_cast<std::size_t>(first_column)];
      const int end = cell_start_[base + static_cast<std::size_t>(last_column) + 1];
      if (begin < end) visit(begin, end);
    }
  }

  /// The same for the box spanned by a and b grown by `margin` on every side: the robots
  /// within `margin` of a point (a == b) or of a segment a-b.
  template <class Visit>
  void for_each_run_near(Vec2 a, Vec2 b, double margin, Visit&& visit) const {
    for_each_run(std::min(a.x, b.x) - margin, std::min(a.y, b.y) - margin, std::max(a.x, b.x) + margin,
                 std::max(a.y, b.y) + margin, visit);
  }

  /// The binned robots: their indices and centres, cell by cell.
  const std::uint16_t* robot() const { return robot_.data(); }
  const double* x() const { return x_.data(); }
  const double* y() const { return y_.data(); }

 private:
  int column(double x) const;
  int row(double y) const;

  double min_x_ = 0.0, min_y_ = 0.0, inverse_cell_ = 1.0;
  int columns_ = 1, rows_ = 1;
  std::size_t max_cells_ = 1;
  std::vector<int> cell_start_;       // per cell, then one past the last: start in the binned arrays
  std::vector<int> cell_of_;          // per robot, its cell
  std::vector<std::uint16_t> robot_;  // binned
  std::vector<double> x_, y_;         // binned
};

}  // namespace sd
