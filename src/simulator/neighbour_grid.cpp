#include "simulator/neighbour_grid.hpp"

#include <algorithm>
#include <cmath>

namespace sd {

void NeighbourGrid::reserve(std::size_t robots) {
  // A few cells per robot at most: a finer grid would cost more to clear than it saves.
  max_cells_ = 4 * robots + 64;
  cell_start_.assign(max_cells_ + 1, 0);
  cell_of_.assign(robots, 0);
  robot_.assign(robots, 0);
  x_.assign(robots, 0.0);
  y_.assign(robots, 0.0);
}

int NeighbourGrid::column(double x) const {
  return std::clamp(static_cast<int>((x - min_x_) * inverse_cell_), 0, columns_ - 1);
}

int NeighbourGrid::row(double y) const {
  return std::clamp(static_cast<int>((y - min_y_) * inverse_cell_), 0, rows_ - 1);
}

void NeighbourGrid::build(const double* x, const double* y, int robots, double cell) {
  double max_x = x[0], max_y = y[0];
  min_x_ = x[0];
  min_y_ = y[0];
  for (int i = 1; i < robots; ++i) {
    min_x_ = std::min(min_x_, x[i]);
    max_x = std::max(max_x, x[i]);
    min_y_ = std::min(min_y_, y[i]);
    max_y = std::max(max_y, y[i]);
  }
  // Cells as small as asked, unless that would make more cells than the buffers hold.
  const double width = max_x - min_x_, height = max_y - min_y_;
  for (;; cell *= 1.25) {  // NOLINT(cert-flp30-c): grows until the cells fit; ends by its break
    inverse_cell_ = 1.0 / cell;
    columns_ = static_cast<int>(width * inverse_cell_) + 1;
    rows_ = static_cast<int>(height * inverse_cell_) + 1;
    if (static_cast<double>(columns_) * rows_ <= static_cast<double>(max_cells_)) break;
  }
  const auto cells = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);

  // Counting sort by cell; robots are taken in index order, so each cell stays sorted.
  std::fill(cell_start_.begin(), cell_start_.begin() + static_cast<std::ptrdiff_t>(cells + 1), 0);
  for (int i = 0; i < robots; ++i) {
    const int c = row(y[i]) * columns_ + column(x[i]);
    cell_of_[static_cast<std::size_t>(i)] = c;
    ++cell_start_[static_cast<std::size_t>(c) + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  for (int i = 0; i < robots; ++i) {
    const auto slot = static_cast<std::size_t>(cell_start_[static_cast<std::size_t>(cell_of_[static_cast<std::size_t>(i)])]++);
    robot_[slot] = static_cast<std::uint16_t>(i);
    x_[slot] = x[i];
    y_[slot] = y[i];
  }
  // Each start now holds the next cell's start: shift back by one cell.
  for (std::size_t c = cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
}

}  // namespace sd
