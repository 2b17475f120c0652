#include "modules/arlequin_demiurge.hpp"

#include <charconv>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/math.hpp"
#include "modules/arlequin_builtin_weights.hpp"

namespace sd::arlequin::demiurge {

namespace {

constexpr std::size_t kGroundInput = 16, kNeighbourCountInput = 19, kBiasInput = 24;

/// Reads `index,left,center,right` rows; the values are parsed as float, as the C++ compiler
/// reads Demiurge's `const float` literals (both round correctly).
GreySamples parse_grey_samples(std::string_view csv) {
  GreySamples s;
  const auto fail = [](const std::string& why) {
    throw std::runtime_error("data/arlequin-demiurge/grey-samples.csv: " + why);
  };
  std::size_t line_end = csv.find('\n');
  if (line_end == std::string_view::npos || csv.substr(0, line_end) != "index,left,center,right")
    fail("the first line must be index,left,center,right");
  const char* p = csv.data() + line_end + 1;
  const char* end = csv.data() + csv.size();
  for (int row = 0; row < kGreySamples; ++row) {
    int index = -1;
    auto r = std::from_chars(p, end, index);
    if (r.ec != std::errc{} || index != row) fail("row " + std::to_string(row) + " is missing or out of order");
    p = r.ptr;
    for (auto* table : {&s.left, &s.centre, &s.right}) {
      if (p == end || *p != ',') fail("row " + std::to_string(row) + " needs four comma-separated fields");
      float v = 0.0F;
      r = std::from_chars(p + 1, end, v);
      if (r.ec != std::errc{} || !(v >= 0.0F && v <= 1.0F)) fail("row " + std::to_string(row) + " has a value outside [0, 1]");
      (*table)[static_cast<std::size_t>(row)] = v;
      p = r.ptr;
    }
    while (p != end && (*p == '\r' || *p == '\n')) ++p;
  }
  if (p != end) fail("more than " + std::to_string(kGreySamples) + " rows");
  return s;
}

/// ARGoS's Uniform(CRange<UInt32>(0, 4204)): an index in 0..4203 (4204 only for the largest
/// 32-bit draw, which we leave out).
double grey_sample(const std::array<float, kGreySamples>& table, Rng& rng) {
  return static_cast<double>(table[rng.uniform_int(0, static_cast<std::uint32_t>(kGreySamples - 1))]);
}

}  // namespace

const GreySamples& grey_samples() {
  static const GreySamples samples = parse_grey_samples(demiurge_grey_samples_csv());
  return samples;
}

Inputs encode_inputs(const ReferenceModel& rm, int steps_since_entry, Rng& rng) {
  Inputs x{};
  for (std::size_t k = 0; k < 8; ++k) {
    x[k] = rm.raw_proximity[k];
    x[8 + k] = rm.raw_light[k];
  }
  const double floor = rm.ground_input_demiurge;
  if (floor <= 0.1 || floor >= 0.95) {
    for (std::size_t k = 0; k < 3; ++k) x[kGroundInput + k] = floor <= 0.1 ? 0.0 : 1.0;
  } else {
    const GreySamples& samples = grey_samples();
    x[kGroundInput] = grey_sample(samples.left, rng);  // drawn in this order: left, centre, right
    x[kGroundInput + 1] = grey_sample(samples.centre, rng);
    x[kGroundInput + 2] = grey_sample(samples.right, rng);
  }
  x[kNeighbourCountInput] = 1.0 - 2.0 / (1.0 + math::exp(static_cast<double>(rm.neighbours)));
  int messages = 0;
  const Vec2 sum = rm.recent_neighbour_position_sum(steps_since_entry, messages);
  if (messages > 0) set_neighbour_direction_inputs(sum * (1.0 / static_cast<double>(messages)), x);
  x[kBiasInput] = 1.0;
  return x;
}

}  // namespace sd::arlequin::demiurge
