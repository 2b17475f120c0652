#pragma once
// The configuration-string grammar shared with ARGoS3-AutoMoDe:
// parse `--fsm-config --nstates N --s0 B ...` into ControlSoftware and print it back.
// Printing then parsing gives back the same control software, bit for bit.
#include <span>
#include <stdexcept>
#include <string>
#include <vector>


#include "control/control_software.hpp"

namespace sd {

/// A malformed configuration string; the message names the offending token.
struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ParseOptions {
  /// Flavour of legacy strings whose module ids are all one digit (Chocolate by default).
  Flavour legacy_flavour = Flavour::Chocolate;
};

ControlSoftware parse_control_software(std::span<const std::string> tokens, ParseOptions options = {});
ControlSoftware parse_control_software(const std::string& text, ParseOptions options = {});

/// Canonical configuration string with two-digit ids, starting with --fsm-config, or with
/// --bt-config for behaviour trees (format B), or --nn-config for EvoStick networks.
std::string to_config_string(const ControlSoftware& software);

/// Behaviour trees: format B (`--nroot 3 --nchildroot K --n0 0 ...`) or Maple's original
/// format A (`--rootnode 0 --nchildsroot K --n0 0 --nc0 1 ...`), without the --bt-config.
ControlSoftware parse_behaviour_tree(std::span<const std::string> tokens, ParseOptions options = {});
std::string behaviour_tree_to_string(const BehaviourTree& tree);

/// EvoStick networks: `--w<o>x<i> <weight>` for output o (0 left, 1 right wheel) and input
/// i (0-24, 24 the bias), all 50 of them, without the --nn-config.
ControlSoftware parse_neural_network(std::span<const std::string> tokens);
std::string neural_network_to_string(const NeuralNetwork& network);

/// Shortest text that reads back as exactly the same double.
std::string format_number(double value);

std::vector<std::string> split_tokens(const std::string& text);

}  // namespace sd
