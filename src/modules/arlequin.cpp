#include "modules/arlequin.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/json_syntax.hpp"
#include "core/math.hpp"
#include "modules/arlequin_builtin_weights.hpp"
#include "simulator/epuck.hpp"

namespace sd::arlequin {

namespace {

constexpr std::size_t kGroundInput = 16, kNeighbourCountInput = 19, kNeighbourDirectionInput = 20, kBiasInput = 24;

std::array<Vec2, 4> make_diagonals() {
  std::array<Vec2, 4> d{};
  for (std::size_t k = 0; k < 4; ++k) d[k] = Vec2::polar(1.0, kPi * static_cast<double>(2 * k + 1) / 4.0);
  return d;
}

/// u_k = (1 at pi (2k + 1) / 4): the four diagonal directions of inputs 20-23. Built at
/// start-up: the network's inputs are encoded for every robot at every step.
const std::array<Vec2, 4> kDiagonals = make_diagonals();

}  // namespace

void set_neighbour_direction_inputs(Vec2 centre, Inputs& x) {
  for (std::size_t k = 0; k < 4; ++k) x[kNeighbourDirectionInput + k] = std::max(0.0, dot(centre, kDiagonals[k]));
}

Inputs encode_inputs(const ReferenceModel& rm) {
  Inputs x{};
  for (std::size_t k = 0; k < 8; ++k) {
    x[k] = rm.raw_proximity[k];
    x[8 + k] = rm.raw_light[k];
  }
  // The majority filter gives one value for all three sensors; the thresholds are DEMI's.
  for (std::size_t k = 0; k < 3; ++k)
    x[kGroundInput + k] = rm.ground <= 0.1 ? 0.0 : (rm.ground >= 0.95 ? 1.0 : rm.raw_ground[k]);
  x[kNeighbourCountInput] = 1.0 - 2.0 / (1.0 + math::exp(static_cast<double>(rm.neighbours)));
  if (const int messages = rm.buffered_messages(); messages > 0) {
    set_neighbour_direction_inputs(rm.neighbour_position_sum() * (1.0 / static_cast<double>(messages)), x);
  }
  x[kBiasInput] = 1.0;
  return x;
}

std::array<double, kOutputs> forward(const Weights& weights, const Inputs& inputs) {
  std::array<double, kOutputs> out{};
  for (std::size_t o = 0; o < static_cast<std::size_t>(kOutputs); ++o) {
    double sum = 0.0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(kInputs); ++i)
      sum += weights[o * static_cast<std::size_t>(kInputs) + i] * inputs[i];
    out[o] = 1.0 / (1.0 + math::exp(-kSigmoidSlope * sum));
  }
  return out;
}

Actuation wheels_from_outputs(const std::array<double, kOutputs>& outputs) {
  constexpr double kMax = epuck::kMaxWheelSpeedCm;
  return {-kMax + 2.0 * kMax * outputs[0], -kMax + 2.0 * kMax * outputs[1]};
}

Actuation drive(const Weights& weights, const ReferenceModel& rm) {
  return wheels_from_outputs(forward(weights, encode_inputs(rm)));
}

Weights weights_from_json(std::string_view json_text, std::string_view source) {
  const std::string where(source);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(json_text, nullptr, true, true);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(where + ": not JSON (" + e.what() + ")");
  } catch (const nlohmann::json::out_of_range& e) {
    throw std::runtime_error(where + ": not JSON (" + json_number_error(e) + ")");
  }
  Weights w{};
  const char* rows[] = {"left", "right"};
  for (std::size_t o = 0; o < 2; ++o) {
    const auto* row = doc.contains("weights") && doc["weights"].is_object() && doc["weights"].contains(rows[o])
                          ? &doc["weights"][rows[o]]
                          : nullptr;
    if (!row || !row->is_array() || row->size() != static_cast<std::size_t>(kInputs))
      throw std::runtime_error(where + ": weights." + rows[o] + " must be an array of " + std::to_string(kInputs) +
                               " numbers");
    for (std::size_t i = 0; i < static_cast<std::size_t>(kInputs); ++i) {
      const auto& v = (*row)[i];
      if (!v.is_number() || !std::isfinite(v.get<double>()))
        throw std::runtime_error(where + ": weights." + rows[o] + "[" + std::to_string(i) + "] is not a finite number");
      w[o * static_cast<std::size_t>(kInputs) + i] = v.get<double>();
    }
  }
  return w;
}

const Weights& shipped_weights(int id) {
  if (!is_module(id)) throw std::out_of_range("no Arlequin module " + std::to_string(id) + " (50-55)");
  // Parsed once, on first use: when control software that uses the module is prepared for a
  // run (prepare_behaviour), never inside a tick. A file that is missing or broken fails every use of its
  // module with the same message rather than running a network of zeros.
  struct Entry {
    std::optional<Weights> weights;
    std::string error;
  };
  static const std::array<Entry, 6> table = [] {
    std::array<Entry, 6> t;
    for (std::size_t d = 0; d < t.size(); ++d) {
      const std::string name(kModuleNames[d]);
      t[d].error = "the build carries no data/arlequin/" + name + ".json";
      for (const BuiltinWeightFile& file : builtin_weight_files()) {
        if (file.name != name) continue;
        try {
          t[d].weights = weights_from_json(file.json, "data/arlequin/" + name + ".json");
        } catch (const std::runtime_error& e) {
          t[d].error = e.what();
        }
      }
    }
    return t;
  }();
  const Entry& entry = table[static_cast<std::size_t>(id - kFirstModuleId)];
  if (!entry.weights) throw std::runtime_error("Arlequin module " + std::to_string(id) + ": " + entry.error);
  return *entry.weights;
}

}  // namespace sd::arlequin
