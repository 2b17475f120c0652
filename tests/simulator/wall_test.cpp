// Wall queries of the arena model: the slab test that proximity rays, lights and lines of
// sight use.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "core/rng.hpp"
#include "simulator/arena.hpp"

namespace sd {
namespace {

/// The slab test written the plain way, with early exits: where the segment a->b enters the
/// wall's rectangle, or 2 if it misses.
double plain_segment_entry(const Wall& wall, Vec2 a, Vec2 b) {
  const Vec2 n = wall.normal();
  const double la[2] = {dot(a - wall.center, wall.axis), dot(a - wall.center, n)};
  const double lb[2] = {dot(b - wall.center, wall.axis), dot(b - wall.center, n)};
  const double half[2] = {wall.half_length, wall.half_thickness};
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 2; ++k) {
    const double d = lb[k] - la[k];
    if (std::abs(d) < 1e-15) {
      if (std::abs(la[k]) > half[k]) return 2.0;
      continue;
    }
    double ta = (-half[k] - la[k]) / d, tb = (half[k] - la[k]) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return 2.0;
  }
  return t0;
}

Wall tilted_wall() {
  Wall w;
  w.center = {0.2, -0.1};
  w.axis = Vec2::polar(1.0, 0.7);
  w.half_length = 0.33;
  w.half_thickness = 0.005;
  return w;
}

TEST(Wall, SegmentEntryIsWhereTheSegmentMeetsTheBox) {
  Wall w;  // along x, 0.4 m long, 2 cm thick
  w.half_length = 0.2;
  w.half_thickness = 0.01;
  EXPECT_DOUBLE_EQ(w.segment_entry({0.0, -0.11}, {0.0, 0.09}), 0.5);  // enters at y = -0.01
  EXPECT_GT(w.segment_entry({0.0, -0.11}, {0.0, -0.02}), 1.0);        // stops short
  EXPECT_GT(w.segment_entry({0.3, -0.1}, {0.3, 0.1}), 1.0);           // passes beyond the end
  EXPECT_EQ(w.segment_entry({0.0, 0.0}, {0.0, 0.1}), 0.0);            // starts inside
  EXPECT_GT(w.segment_entry({-0.5, 0.05}, {0.5, 0.05}), 1.0);         // parallel, outside
  EXPECT_DOUBLE_EQ(w.segment_entry({-0.5, 0.0}, {0.5, 0.0}), 0.3);    // parallel, through
}

TEST(Wall, SegmentEntryAgreesBitForBitWithThePlainSlabTest) {
  // Random segments around a tilted wall, many of them parallel to one of its axes or
  // ending on its faces, where the branch-free test must still give exactly the same value.
  const Wall w = tilted_wall();
  const Vec2 n = w.normal();
  Rng rng(5);
  int hits = 0, misses = 0;
  for (int k = 0; k < 200000; ++k) {
    const Vec2 a = w.center + w.axis * rng.uniform(-0.5, 0.5) + n * rng.uniform(-0.1, 0.1);
    Vec2 b;
    switch (k % 4) {
      case 0: b = a + Vec2::polar(rng.uniform(0.0, 0.3), rng.uniform(-kPi, kPi)); break;
      case 1: b = a + w.axis * rng.uniform(-0.3, 0.3); break;  // along the wall
      case 2: b = a + n * rng.uniform(-0.1, 0.1); break;       // across it
      default: b = w.center + w.axis * rng.uniform(-0.4, 0.4) + n * (rng.uniform() < 0.5 ? -1.0 : 1.0) * w.half_thickness;
    }
    const double expected = plain_segment_entry(w, a, b);
    const double got = w.segment_entry(a, b);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(expected))
        << "a = (" << a.x << ", " << a.y << "), b = (" << b.x << ", " << b.y << ")";
    (expected <= 1.0 ? hits : misses) += 1;
  }
  EXPECT_GT(hits, 20000);
  EXPECT_GT(misses, 20000);
}

TEST(Wall, SegmentEntriesOfABatchAreEachSegmentsEntry) {
  // The 8-ray batch the proximity sensor uses gives, ray by ray, exactly segment_entry.
  const Wall w = tilted_wall();
  Rng rng(9);
  for (int round = 0; round < 20000; ++round) {
    SegmentBatch batch;
    for (std::size_t k = 0; k < SegmentBatch::kSize; ++k) {
      const Vec2 a = w.center + Vec2::polar(rng.uniform(0.0, 0.4), rng.uniform(-kPi, kPi));
      const Vec2 b = (k % 3 == 0) ? a + w.axis * rng.uniform(-0.1, 0.1) : a + Vec2::polar(0.1, rng.uniform(-kPi, kPi));
      batch.ax[k] = a.x;
      batch.ay[k] = a.y;
      batch.bx[k] = b.x;
      batch.by[k] = b.y;
    }
    std::array<double, SegmentBatch::kSize> t;
    w.segment_entries(batch, t);
    for (std::size_t k = 0; k < SegmentBatch::kSize; ++k)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(t[k]),
                std::bit_cast<std::uint64_t>(w.segment_entry({batch.ax[k], batch.ay[k]}, {batch.bx[k], batch.by[k]})));
  }
}

TEST(Wall, SurelyBeyondNeverRulesOutAWallTheExactDistanceKeeps) {
  // Physics::step keeps a wall if distance < limit and the proximity rays if distance <=
  // limit, each after surely_beyond has ruled the wall out or not: both decisions are
  // unchanged only if surely_beyond(p, limit) implies distance > limit. Random walls, tilted
  // or not, points around their corners, along their faces and inside them, and limits at
  // the exact distance, an ulp or a hair on either side of it, and at the bound itself
  // (where a bound compared with >=, or with its margin the wrong way, would fail).
  Rng rng(17);
  const double inf = std::numeric_limits<double>::infinity();
  int ruled_out = 0, kept_at_limit = 0;
  for (int k = 0; k < 200000; ++k) {
    Wall w;
    w.center = {rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0)};
    w.axis = k % 3 == 0 ? Vec2{1.0, 0.0} : k % 3 == 1 ? Vec2{0.0, -1.0} : Vec2::polar(1.0, rng.uniform(-kPi, kPi));
    w.half_length = rng.uniform(0.005, 1.0);
    w.half_thickness = rng.uniform(0.001, 0.05);
    const Vec2 n = w.normal();
    const double side_a = rng.uniform() < 0.5 ? -1.0 : 1.0, side_n = rng.uniform() < 0.5 ? -1.0 : 1.0;
    Vec2 anchor;
    switch (k / 3 % 3) {
      case 0: anchor = w.center + w.axis * (side_a * w.half_length) + n * (side_n * w.half_thickness); break;  // a corner
      case 1: anchor = w.center + w.axis * rng.uniform(-w.half_length, w.half_length) + n * (side_n * w.half_thickness); break;
      default: anchor = w.center + w.axis * rng.uniform(-1.2, 1.2) * w.half_length + n * rng.uniform(-2.0, 2.0) * w.half_thickness;
    }
    const Vec2 p = anchor + Vec2::polar(rng.uniform() < 0.2 ? 0.0 : rng.uniform(0.0, 0.3), rng.uniform(-kPi, kPi));
    const double exact = w.distance(p, nullptr);
    const Vec2 d = p - w.center;
    const double bound = std::max(std::abs(dot(d, w.axis)) - w.half_length, std::abs(dot(d, n)) - w.half_thickness);
    for (const double limit : {exact, std::nextafter(exact, -inf), std::nextafter(exact, inf), exact - 1e-12, exact + 1e-12, bound,
                               std::nextafter(bound, -inf), bound - w.kBoundMargin, rng.uniform(0.0, 0.3)}) {
      if (limit < 0.0) continue;  // surely_beyond is for limits of a reach
      if (w.surely_beyond(p, limit)) {
        ASSERT_GT(exact, limit) << "p = (" << p.x << ", " << p.y << "), wall " << w.center.x << ", " << w.center.y << ", axis "
                                << w.axis.x << ", " << w.axis.y << ", limit " << limit;
        ++ruled_out;
      } else if (exact <= limit && exact >= limit - 1e-12) {
        ++kept_at_limit;
      }
    }
  }
  EXPECT_GT(ruled_out, 40000);      // the bound does spare far walls the exact test
  EXPECT_GT(kept_at_limit, 200000);  // and many walls sat right at the limit
}

}  // namespace
}  // namespace sd
