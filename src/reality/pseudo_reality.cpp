#include "reality/pseudo_reality.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/fnv.hpp"
#include "core/json_syntax.hpp"
#include "core/rng.hpp"

namespace sd {

namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw PseudoRealityError(path + ": " + what); }

double number(const json& v, const std::string& path) {
  if (!v.is_number()) fail(path, "expected a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(path, "expected a finite number");
  return x;
}

void in_domain(const RobotKnob& knob, double v, const std::string& path) {
  const std::string_view error = knob_domain_error(knob.domain, v);
  if (!error.empty()) fail(path, std::string(error));
}

KnobLaw read_law(const RobotKnob& knob, const json& v, const std::string& path) {
  if (v.is_number()) {
    const double x = number(v, path);
    in_domain(knob, x, path);
    return {KnobLaw::Kind::Fixed, x, x};
  }
  if (!v.is_object() || v.size() != 1)
    fail(path, "expected a number, {\"uniform\": [low, high]} or {\"around\": relative half-width}");
  if (v.contains("uniform")) {
    const json& range = v.at("uniform");
    const std::string at = path + ".uniform";
    if (!range.is_array() || range.size() != 2) fail(at, "expected [low, high]");
    const double lo = number(range[0], at + "[0]"), hi = number(range[1], at + "[1]");
    in_domain(knob, lo, at + "[0]");
    in_domain(knob, hi, at + "[1]");
    if (lo > hi) fail(at, "low must not exceed high");
    return {KnobLaw::Kind::Uniform, lo, hi};
  }
  if (v.contains("around")) {
    const double r = number(v.at("around"), path + ".around");
    if (r < 0.0 || r > 1.0) fail(path + ".around", "must be in [0, 1] (a relative half-width)");
    return {KnobLaw::Kind::Around, r, r};
  }
  fail(path + "." + v.begin().key(), "unknown law (expected uniform or around)");
}

std::string optional_text(const json& doc, const char* key) {
  if (!doc.contains(key)) return "";
  if (!doc.at(key).is_string()) fail(key, "expected a string");
  return doc.at(key).get<std::string>();
}

/// The interval [lo, hi] kept within the knob's domain (an "around" law next to a bound).
void clamp_to_domain(const RobotKnob& knob, double& lo, double& hi) {
  double floor = 0.0, ceiling = std::numeric_limits<double>::max();  // finite: a sample is a number
  if (knob.domain == KnobDomain::Probability) ceiling = 1.0;
  if (knob.domain == KnobDomain::Deviation) ceiling = std::nextafter(1.0, 0.0);
  lo = std::clamp(lo, floor, ceiling);
  hi = std::clamp(hi, floor, ceiling);
  if (knob.domain == KnobDomain::Positive) lo = std::max(lo, std::nextafter(0.0, 1.0));
}

}  // namespace

PseudoRealitySpec parse_pseudo_reality(const std::string& text, const std::string& what) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw PseudoRealityError(what + ": " + json_syntax_error(e, text));
  } catch (const json::out_of_range& e) {
    throw PseudoRealityError(what + ": " + json_number_error(e));
  }
  try {
    if (!doc.is_object()) fail("document", "expected an object");
    for (const auto& [key, value] : doc.items())
      if (key != "name" && key != "description" && key != "source" && key != "knobs") fail(key, "unknown field");
    PseudoRealitySpec spec;
    spec.name = optional_text(doc, "name");
    spec.description = optional_text(doc, "description");
    spec.source = optional_text(doc, "source");
    if (!doc.contains("knobs")) fail("knobs", "missing field");
    const json& knobs = doc.at("knobs");
    if (!knobs.is_object()) fail("knobs", "expected an object");
    spec.laws.assign(kRobotKnobs.size(), std::nullopt);
    for (const auto& item : knobs.items()) {
      const std::string& key = item.key();
      const nlohmann::json& value = item.value();
      const auto at = std::find_if(kRobotKnobs.begin(), kRobotKnobs.end(), [&](const RobotKnob& k) { return k.name == key; });
      if (at == kRobotKnobs.end()) fail("knobs." + key, "unknown knob");
      spec.laws[static_cast<std::size_t>(at - kRobotKnobs.begin())] = read_law(*at, value, "knobs." + key);
    }
    // Samples depend on the knobs' laws only: a changed description keeps them.
    Fnv1a digest;
    digest.add(knobs.dump());
    spec.digest = digest.hex();
    return spec;
  } catch (const PseudoRealityError& e) {
    throw PseudoRealityError(what + ": " + e.what());
  }
}

RobotModel PseudoRealitySpec::sample(const RobotModel& design, std::uint64_t k) const {
  Fnv1a seed;
  seed.add(digest);
  seed.add_u64(k);
  Rng rng(seed.value());
  RobotModel model = design;
  for (std::size_t i = 0; i < kRobotKnobs.size(); ++i) {
    const double u = rng.uniform();
    if (i >= laws.size() || !laws[i]) continue;
    const RobotKnob& knob = kRobotKnobs[i];
    const KnobLaw& law = *laws[i];
    double lo = law.a, hi = law.b;
    if (law.kind == KnobLaw::Kind::Around) {
      const double v = design.*(knob.member);
      lo = v * (1.0 - law.a);
      hi = v * (1.0 + law.a);
      clamp_to_domain(knob, lo, hi);
    }
    model.*(knob.member) = law.kind == KnobLaw::Kind::Fixed ? law.a : lo + (hi - lo) * u;
  }
  return model;
}

bool PseudoRealitySpec::varies() const {
  return std::any_of(laws.begin(), laws.end(), [](const std::optional<KnobLaw>& law) {
    return law && (law->kind == KnobLaw::Kind::Around ? law->a > 0.0 : law->kind == KnobLaw::Kind::Uniform && law->b > law->a);
  });
}

std::optional<PseudoRealitySpec> builtin_pseudo_reality(const std::string& name) {
  for (const BuiltinPseudoReality& b : builtin_pseudo_realities())
    if (b.name == name) return parse_pseudo_reality(std::string(b.json), "pseudo-reality " + name);
  return std::nullopt;
}

}  // namespace sd
