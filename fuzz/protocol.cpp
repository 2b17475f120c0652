// Experiment protocols as a user writes them (JSON, comments allowed, as read_protocol_file
// reads them). A JSON syntax error and ProtocolError are the rejections. A protocol that
// reads must write (to_json) a document that reads back to the same document.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "experiments/protocol.hpp"
#include "finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error&) {
    return 0;
  }
  sd::experiments::Protocol protocol;
  try {
    protocol = sd::experiments::protocol_from_json(document);
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
