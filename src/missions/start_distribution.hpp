#pragma once
// Where robots start. Most missions draw uniformly in a region (for discs, the formula of
// experiments-loop-functions' CoreLoopFunctions). TuttiFrutti's loop functions use their own
// draw:
//   a, b ~ U(0, 1), swapped so that a <= b; c, d ~ U(-1, 1);
//   p = center + jitter (c, d) + radius (cos phi, sin phi), phi = from + span a / b,
// i.e. a point on an arc, jittered in a square:
//   AGGREGATION: center (0, 0),    radius 0.25, jitter 0.25, from 0, span 360 degrees;
//   STOP:        center (0, -0.2), radius 0.4,  jitter 0.2,  from 0, span -180 degrees;
//   FORAGING:    center (0, 0),    radius 0.4,  jitter 0.2,  from 0, span 360 degrees.
// Placement then rejects draws that overlap walls or robots placed before, as always.
#include <optional>

#include "core/rng.hpp"
#include "simulator/region.hpp"

namespace sd {

class Field;

struct JitteredArc {
  Vec2 center;
  double radius = 0.0;
  double jitter = 0.0;
  double from = 0.0, span = kTwoPi;  // rad
  Vec2 draw(Rng& rng) const;
  /// The square every draw falls in.
  Region support() const;
};

/// {"jittered_arc": {"center", "radius", "jitter", "from", "span"}} (degrees), or nothing if
/// the start is a region.
std::optional<JitteredArc> read_jittered_arc(const Field& f);

}  // namespace sd
