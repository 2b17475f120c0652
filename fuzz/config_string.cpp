// Configuration strings as a user types them: FSM, behaviour trees (formats A and B, with or
// without --bt-config) and EvoStick networks, read as every legacy flavour. The first byte
// picks the flavour one-digit legacy ids mean and the entry point; the rest is the string.
// ConfigError is the parsers' one rejection; any other exception escaping is a finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "control/config_string.hpp"
#include "finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return -1;
  const std::uint8_t choice = data[0];
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  sd::ParseOptions options;
  options.legacy_flavour = static_cast<sd::Flavour>(1 + (choice & 7) % 5);
  try {
    switch ((choice >> 3) & 3) {
      case 0: (void)sd::parse_control_software(text, options); break;
      case 1: (void)sd::parse_behaviour_tree(sd::split_tokens(text), options); break;
      case 2: (void)sd::parse_neural_network(sd::split_tokens(text)); break;
      default: (void)sd::parse_control_software(sd::split_tokens(text), options); break;
    }
  } catch (const sd::ConfigError&) {
    // The documented rejection.
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("exception other than ConfigError: ") + e.what());
  }
  return 0;
}
