#include "robot/reference_model.hpp"

#include <algorithm>
#include <cmath>

#include "simulator/epuck.hpp"

namespace sd {

namespace {

std::array<Vec2, 8> make_sensor_directions() {
  std::array<Vec2, 8> d{};
  for (std::size_t k = 0; k < 8; ++k) d[k] = Vec2::polar(1.0, wrap_signed(epuck::kSensorAngles[k]));
  return d;
}

// Built at start-up rather than on first use: update() runs for every robot at every step
// and should not test an initialisation guard each time.
const std::array<Vec2, 8> kSensorDirections = make_sensor_directions();

int next_slot(int slot, int slots) { return slot + 1 == slots ? 0 : slot + 1; }

/// Sum of the 8 readings, each at its sensor's reported angle (RM1.2's P and light sums).
Vec2 directional_sum(std::span<const double, 8> readings) {
  Vec2 sum;
  for (std::size_t k = 0; k < 8; ++k) sum += kSensorDirections[k] * readings[k];
  return sum;
}

}  // namespace

const std::array<Vec2, 8>& sensor_directions() { return kSensorDirections; }

void ReferenceModel::reset() { *this = ReferenceModel{}; }

int ReferenceModel::buffered_messages() const {
  int messages = 0;
  for (const int step : rab_message_steps) messages += step;
  return messages;
}

Vec2 ReferenceModel::recent_neighbour_position_sum(int steps, int& messages) const {
  if (steps >= kRabBufferSteps) {  // the whole buffer, summed as neighbour_position_sum does
    messages = buffered_messages();
    return neighbour_position_sum();
  }
  messages = 0;
  Vec2 sum;
  int slot = rab_slot;  // the slot after this step's
  for (int k = 0; k < steps; ++k) {
    slot = slot == 0 ? kRabBufferSteps - 1 : slot - 1;
    sum += rab_position_steps[static_cast<std::size_t>(slot)];
    messages += rab_message_steps[static_cast<std::size_t>(slot)];
  }
  return sum;
}

void ReferenceModel::update(const SwarmState& swarm, int robot) {
  const auto r = static_cast<std::size_t>(robot);
  raw_proximity = swarm.proximity[r];
  raw_light = swarm.light[r];
  raw_ground = swarm.ground[r];
  const std::size_t stride = swarm.rab_stride();
  packets = std::span<const RabPacket>(swarm.rab.data() + r * stride, swarm.rab_count[r]);
  if (swarm.blobs_per_robot > 0)
    blobs = std::span<const CameraBlob>(swarm.blobs.data() + r * static_cast<std::size_t>(swarm.blobs_per_robot),
                                        swarm.blob_count[r]);

  update_ground();
  update_range_and_bearing();
  // A robot not sensed for proximity or light does not read it at this step.
  if (swarm.demand[r] & SwarmState::kDemandProximity) update_proximity();
  if (swarm.demand[r] & SwarmState::kDemandLight) update_light();
}

void ReferenceModel::update_ground() {
  // Majority over the last 5 steps x 3 sensors (more than 10 of 15 samples). Each step's
  // black and white counts are kept, so the window sum is updated, not recounted.
  const auto slot = static_cast<std::size_t>(ground_slot);
  std::uint8_t black = 0, white = 0, black_demi = 0, white_demi = 0;
  for (const double g : raw_ground) {  // counted without branches: noisy readings
    black = static_cast<std::uint8_t>(black + (g < 0.03 ? 1 : 0));
    white = static_cast<std::uint8_t>(white + (g > 0.85 ? 1 : 0));
    black_demi = static_cast<std::uint8_t>(black_demi + (g < 0.02 ? 1 : 0));
    white_demi = static_cast<std::uint8_t>(white_demi + (g > 0.97 ? 1 : 0));
  }
  const auto demi = static_cast<std::size_t>(ground_slot_demiurge);
  window_black_demiurge += black_demi - ground_black_demiurge[demi];
  window_white_demiurge += white_demi - ground_white_demiurge[demi];
  ground_black_demiurge[demi] = black_demi;
  ground_white_demiurge[demi] = white_demi;
  // GetGroundInput's thresholds are RM1.x's: the per-step counts are `black` and `white`.
  window_black_input_demiurge += black - ground_black_input_demiurge[demi];
  window_white_input_demiurge += white - ground_white_input_demiurge[demi];
  ground_black_input_demiurge[demi] = black;
  ground_white_input_demiurge[demi] = white;
  ground_input_demiurge = window_black_input_demiurge > 10 ? 0.0 : (window_white_input_demiurge > 10 ? 1.0 : 0.5);
  ground_slot_demiurge = next_slot(ground_slot_demiurge, kDemiurgeGroundHistory);
  ground_demiurge = window_black_demiurge > 8 ? 0.0 : (window_white_demiurge > 8 ? 1.0 : 0.5);
  window_black += black - ground_black[slot];
  window_white += white - ground_white[slot];
  ground_black[slot] = black;
  ground_white[slot] = white;
  ground_slot = next_slot(ground_slot, kGroundHistory);
  ground = window_black > 10 ? 0.0 : (window_white > 10 ? 1.0 : 0.5);
}

void ReferenceModel::update_proximity() {
  const Vec2 sum = directional_sum(raw_proximity);
  const double length = sum.length();
  proximity = length > 1.0 ? sum * (1.0 / length) : sum;
}

void ReferenceModel::update_light() {
  const Vec2 sum = directional_sum(raw_light);
  const bool lit = std::any_of(raw_light.begin(), raw_light.end(), [](double v) { return v > 0.2; });
  const double length = sum.length();
  light = lit && length > 0.0 ? sum * (1.0 / length) : Vec2{};
}

void ReferenceModel::update_range_and_bearing() {
  // Every sender is heard at most once per tick, so the number of distinct senders is the
  // number of packets.
  neighbours = static_cast<int>(packets.size());
  Vec2 step_sum, step_positions;
  for (const RabPacket& p : packets) {
    step_sum += p.direction * (1.0 / (1.0 + p.range_cm));
    step_positions += p.direction * p.range_cm;
  }
  const auto slot = static_cast<std::size_t>(rab_slot);
  rab_steps[slot] = step_sum;
  rab_position_steps[slot] = step_positions;
  rab_message_steps[slot] = neighbours;
  rab_slot = next_slot(rab_slot, kRabBufferSteps);
}

}  // namespace sd
