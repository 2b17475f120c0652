#pragma once
// TuttiFrutti's coloured arenas (as its loop functions TuttiAg/St/FrLoopFunc build them): a
// regular polygon of `sides` walls, each made of `blocks` boxes of length l (0.01 thick, 0.10
// high), every block carrying ceil(l / led_spacing) LEDs whose colours the mission sets and
// changes.
// Geometry, with n sides, m blocks, side L = m l, apothem a = L / (2 tan(pi / n)):
//   side k (1-based) is centred at a (cos t_k, sin t_k), t_k = (k - 1) 2 pi / n (side 1 at +x);
//   block j (1-based) is centred at that point + d_j (sin t_k, -cos t_k),
//   d_j = L/2 - l/2 - (j - 1) l, so block 1 is at the side's clockwise end;
//   its LEDs sit 7.5 mm in front of the block's centre line (towards the arena), 6.7 cm high,
//   `led_spacing` apart along the block and centred on it (two at +-6.25 cm for l = 0.25).
// The blocks become ordinary walls of the arena (they stop robots and shade lights), the
// LEDs ArenaModel::leds (the camera sees them), initially off.
#include <cstdint>
#include <vector>

#include "simulator/arena.hpp"

namespace sd {

class Field;

/// Which arena LEDs belong to which block, for mission events that address blocks.
struct LedArena {
  struct Block {
    int side = 0, block = 0;       // 1-based, as the TuttiFrutti loop functions number them
    std::uint16_t wall = 0;        // index in ArenaModel::walls
    std::uint16_t first_led = 0;   // index in ArenaModel::leds
    std::uint16_t led_count = 0;
  };
  int sides = 0, blocks_per_side = 0;
  std::vector<Block> blocks;  // side after side, block after block

  bool empty() const { return blocks.empty(); }
  const Block& at(int side, int block) const {
    const int index = (side - 1) * blocks_per_side + (block - 1);
    return blocks[static_cast<std::size_t>(index)];
  }
};

/// {"sides": n, "blocks": m, "block_length": 0.25, "thickness": 0.01, "height": 0.1,
///  "led_spacing": 0.125}: appends the blocks to arena.walls and their LEDs to arena.leds.
LedArena read_led_polygon(const Field& f, ArenaModel& arena);

}  // namespace sd
