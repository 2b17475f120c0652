// The editor's drawing model, as /api/print receives it ({"software": MODEL}, src/web/API.md).
// A JSON syntax error and app::InvalidRequest are the rejections. A drawing that is accepted
// must draw (software_document) to a model that is accepted again as the same software.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "app/control_software_document.hpp"
#include "app/errors.hpp"
#include "control/config_string.hpp"
#include "finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const nlohmann::json model = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (model.is_discarded()) return 0;
  sd::ControlSoftware software;
  try {
    software = sd::app::software_from_document(model);
  } catch (const sd::app::InvalidRequest&) {
    return 0;
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("exception other than InvalidRequest: ") + e.what());
  }
  try {
    const nlohmann::json drawn = sd::app::software_document(software);
    if (!(sd::app::software_from_document(drawn) == software))
      sd::fuzz::finding("the drawing of accepted software reads back as other software: " + drawn.dump());
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("the drawing of accepted software is refused: ") + e.what());
  }
  return 0;
}
