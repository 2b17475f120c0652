#include "robot/reference_model.hpp"

#include <algorithm>
#include <cmath>

#include "simulator/epuck.hpp"

namespace sd {

const std::array<Vec2, 8>& sensor_directions() {
  static const std::array<Vec2, 8> directions = [] {
    std::array<Vec2, 8> d{};
    for (std::size_t k = 0; k < 8; ++k) d[k] = Vec2::polar(1.0, wrap_signed(epuck::kSensorAngles[k]));
    return d;
  }();
  return directions;
}

void ReferenceModel::reset() { *this = ReferenceModel{}; }

void ReferenceModel::update(const SwarmState& swarm, int robot) {
  const auto r = static_cast<std::size_t>(robot);
  raw_proximity = swarm.proximity[r];
  raw_light = swarm.light[r];
  raw_ground = swarm.ground[r];

  // Ground: majority over the last 5 steps x 3 sensors (more than 10 of 15 samples). Each
  // step's black and white counts are kept, so the window sum is updated, not recounted.
  const auto slot = static_cast<std::size_t>(ground_samples % kGroundHistory);
  std::uint8_t black = 0, white = 0;
  for (const double g : raw_ground) {
    if (g < 0.03) ++black;
    else if (g > 0.85) ++white;
  }
  window_black += black - ground_black[slot];
  window_white += white - ground_white[slot];
  ground_black[slot] = black;
  ground_white[slot] = white;
  ++ground_samples;
  ground = window_black > 10 ? 0.0 : (window_white > 10 ? 1.0 : 0.5);

  const auto& directions = sensor_directions();
  Vec2 prox, light_sum;
  bool lit = false;
  for (std::size_t k = 0; k < 8; ++k) {
    prox += directions[k] * raw_proximity[k];
    light_sum += directions[k] * raw_light[k];
    lit = lit || raw_light[k] > 0.2;
  }
  const double prox_length = prox.length();
  proximity = prox_length > 1.0 ? prox * (1.0 / prox_length) : prox;
  const double light_length = light_sum.length();
  light = lit && light_length > 0.0 ? light_sum * (1.0 / light_length) : Vec2{};

  // Range and bearing: every sender is heard at most once per tick, so the number of
  // distinct senders is the number of packets.
  const std::size_t stride = swarm.rab_stride();
  packets = std::span<const RabPacket>(swarm.rab.data() + r * stride, swarm.rab_count[r]);
  neighbours = static_cast<int>(packets.size());
  Vec2 step_sum, step_positions;
  for (const RabPacket& p : packets) {
    step_sum += p.direction * (1.0 / (1.0 + p.range_cm));
    step_positions += p.direction * p.range_cm;
  }
  const auto rab_slot = static_cast<std::size_t>(rab_step % kRabBufferSteps);
  rab_steps[rab_slot] = step_sum;
  rab_position_steps[rab_slot] = step_positions;
  rab_message_steps[rab_slot] = neighbours;
  ++rab_step;
  attraction_sum = {};
  neighbour_position_sum = {};
  buffered_messages = 0;
  for (std::size_t k = 0; k < kRabBufferSteps; ++k) {
    attraction_sum += rab_steps[k];
    neighbour_position_sum += rab_position_steps[k];
    buffered_messages += rab_message_steps[k];
  }

  if (swarm.blobs_per_robot > 0)
    blobs = std::span<const CameraBlob>(swarm.blobs.data() + r * static_cast<std::size_t>(swarm.blobs_per_robot),
                                        swarm.blob_count[r]);
}

}  // namespace sd
