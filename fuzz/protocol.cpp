// Experiment protocols as a user writes them (JSON, comments allowed), read by
// parse_protocol_text as read_protocol_file reads a file. ProtocolError is the rejection (a
// JSON syntax error or a number no double holds included). A protocol that reads must write
// (to_json) a document that reads back to the same document.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "experiments/protocol.hpp"
#include "finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sd::experiments::Protocol protocol;
  try {
    protocol = sd::experiments::parse_protocol_text(text, "fuzz.json");
  } catch (const sd::experiments::ProtocolError&) {
    return 0;
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("exception other than ProtocolError: ") + e.what());
  }
  try {
    const nlohmann::json written = sd::experiments::to_json(protocol);
    const nlohmann::json again = sd::experiments::to_json(sd::experiments::protocol_from_json(written));
    if (again != written) sd::fuzz::finding("written protocol reads back differently: " + written.dump());
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("a written protocol does not read back: ") + e.what());
  }
  return 0;
}
