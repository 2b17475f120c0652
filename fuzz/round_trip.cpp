// Print -> parse: whatever parses prints to a canonical string that parses back to the same
// control software and prints to the same string again (config_string.hpp's promise).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "control/config_string.hpp"
#include "finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sd::ControlSoftware software;
  try {
    software = sd::parse_control_software(text);
  } catch (const sd::ConfigError&) {
    return 0;
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("exception other than ConfigError: ") + e.what());
  }
  const std::string printed = sd::to_config_string(software);
  sd::ControlSoftware again;
  try {
    again = sd::parse_control_software(printed);
  } catch (const std::exception& e) {
    sd::fuzz::finding("the printed string does not parse: " + printed + " (" + e.what() + ")");
  }
  if (!(again == software)) sd::fuzz::finding("parses back to other control software: " + printed);
  const std::string reprinted = sd::to_config_string(again);
  if (reprinted != printed) sd::fuzz::finding("prints differently: " + printed + " then " + reprinted);
  return 0;
}
