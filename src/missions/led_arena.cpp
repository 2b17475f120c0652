#include "missions/led_arena.hpp"

#include <cmath>

#include "core/math.hpp"
#include "missions/json_field.hpp"

namespace sd {

namespace {

constexpr double kLedInset = 0.0075;   // m in front of the block's centre line
constexpr double kLedHeight = 0.067;   // m

}  // namespace

LedArena read_led_polygon(const Field& f, ArenaModel& arena) {
  f.only({"sides", "blocks", "block_length", "thickness", "height", "led_spacing"});
  LedArena led_arena;
  const int n = led_arena.sides = f.at("sides").integer_in(3, 64);
  const int m = led_arena.blocks_per_side = f.at("blocks").integer_in(1, 64);
  const double l = f.at("block_length").positive();
  const double thickness = f.positive_or("thickness", 0.01);
  const double height = f.positive_or("height", 0.10);
  const double spacing = f.positive_or("led_spacing", 0.125);
  const int leds_per_block = static_cast<int>(std::ceil(l / spacing - 1e-9));
  if (leds_per_block > 16) f.at("led_spacing").fail("gives more than 16 LEDs per block");
  if (arena.walls.size() + static_cast<std::size_t>(n * m) > 60000) f.fail("too many blocks");
  const double side_length = m * l;
  const double apothem = side_length / (2.0 * math::tan(kPi / n));
  for (int k = 1; k <= n; ++k) {
    const double theta = (k - 1) * kTwoPi / n;
    const Vec2 inward = -Vec2::polar(1.0, theta);
    const Vec2 along{-inward.y, inward.x};  // from block 1 towards block m is -along
    const Vec2 side_center = inward * -apothem;
    for (int j = 1; j <= m; ++j) {
      const double d = side_length / 2 - l / 2 - (j - 1) * l;
      Wall w;
      w.center = side_center + along * d;
      w.axis = along;
      w.half_length = 0.5 * l;
      w.half_thickness = 0.5 * thickness;
      w.height = height;
      LedArena::Block block{k, j, static_cast<std::uint16_t>(arena.walls.size()),
                            static_cast<std::uint16_t>(arena.leds.size()), static_cast<std::uint16_t>(leds_per_block)};
      arena.walls.push_back(w);
      for (int e = 0; e < leds_per_block; ++e) {
        const Vec2 p = w.center + inward * kLedInset + along * ((e - 0.5 * (leds_per_block - 1)) * spacing);
        arena.leds.push_back({{p.x, p.y, kLedHeight}, block.wall, 0});
      }
      led_arena.blocks.push_back(block);
    }
  }
  return led_arena;
}

}  // namespace sd
