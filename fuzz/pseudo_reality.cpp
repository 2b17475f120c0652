// Pseudo-reality specifications (pseudo-realities/*.json, assess --pseudo-reality FILE): what
// parses must give, for any sample, a robot model whose every knob lies in its domain, the
// same model when asked twice, and a design model left alone by a specification that names
// no knob. PseudoRealityError is the rejection.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "finding.hpp"
#include "reality/pseudo_reality.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sd::PseudoRealitySpec spec;
  try {
    spec = sd::parse_pseudo_reality(text, "fuzz.json");
  } catch (const sd::PseudoRealityError&) {
    return 0;
  } catch (const std::exception& e) {
    sd::fuzz::finding(std::string("exception other than PseudoRealityError: ") + e.what());
  }
  const sd::RobotModel design;
  for (const std::uint64_t k : {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{1} << 40}) {
    const sd::RobotModel a = spec.sample(design, k), b = spec.sample(design, k);
    for (const sd::RobotKnob& knob : sd::kRobotKnobs) {
      const double v = a.*(knob.member);
      if (!std::isfinite(v) || !sd::knob_domain_error(knob.domain, v).empty())
        sd::fuzz::finding("sample " + std::to_string(k) + " puts " + std::string(knob.name) + " at " + std::to_string(v));
      if (v != b.*(knob.member)) sd::fuzz::finding("sample " + std::to_string(k) + " differs when drawn again");
      const bool named = spec.laws[static_cast<std::size_t>(&knob - sd::kRobotKnobs.data())].has_value();
      if (!named && v != design.*(knob.member)) sd::fuzz::finding(std::string(knob.name) + " moved though not named");
    }
  }
  return 0;
}
