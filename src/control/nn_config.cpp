// EvoStick network strings: `--nn-config --w0x0 <w> ... --w1x24 <w>`, one token per weight,
// w<o>x<i> from input i to output o (0 left wheel, 1 right wheel; input 24 is the bias).
// Read with the grammar's shared token reader, so errors name the offending token and
// printing then parsing gives back the same weights bit for bit.
#include <regex>

#include "control/config_string.hpp"
#include "control/config_tokens.hpp"

namespace sd {

namespace {

std::string weight_token(std::size_t output, std::size_t input) {
  // Appended piece by piece: GCC 12 reports a false -Wrestrict on "literal" + std::string.
  std::string token = "--w";
  token += std::to_string(output);
  token += 'x';
  token += std::to_string(input);
  return token;
}

bool nn_name(const std::string& token) {
  static const std::regex pattern("--[a-z]+[0-9]{1,3}(x[0-9]{1,3})?");
  return std::regex_match(token, pattern);
}

}  // namespace

ControlSoftware parse_neural_network(std::span<const std::string> tokens) {
  config::TokenReader reader(tokens, "--nn-config", nn_name);
  ControlSoftware software;
  software.architecture = Architecture::NeuralNetwork;
  constexpr auto inputs = static_cast<std::size_t>(arlequin::kInputs);
  for (std::size_t o = 0; o < static_cast<std::size_t>(arlequin::kOutputs); ++o)
    for (std::size_t i = 0; i < inputs; ++i)
      software.network.weights[o * inputs + i] = reader.require(weight_token(o, i), "a network needs all 50 weights").value;
  reader.reject_unused([](const std::string&) {
    return "a network has weights --w<output>x<input> with output 0-1 and input 0-24 only";
  });
  return software;
}

std::string neural_network_to_string(const NeuralNetwork& network) {
  std::string out = "--nn-config";
  constexpr auto inputs = static_cast<std::size_t>(arlequin::kInputs);
  for (std::size_t o = 0; o < static_cast<std::size_t>(arlequin::kOutputs); ++o)
    for (std::size_t i = 0; i < inputs; ++i) {
      out += ' ';
      out += weight_token(o, i);
      out += ' ';
      out += format_number(network.weights[o * inputs + i]);
    }
  return out;
}

}  // namespace sd
