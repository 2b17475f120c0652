#pragma once
// The pseudo-realities a user names (Ligot & Birattari 2020; reality/pseudo_reality.hpp): a
// shipped specification by name, or a specification file under app/user_files' one rule; and
// the sample numbers they ask for.
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "app/user_files.hpp"
#include "missions/mission.hpp"
#include "reality/pseudo_reality.hpp"

namespace sd::app {

struct NamedPseudoReality {
  std::string reference;  // as the user named it: a shipped name or the file's path
  PseudoRealitySpec spec;
  std::string document;   // the specification's text, kept with a design so it resumes alike
};

/// InvalidRequest naming the bad field for a malformed specification, the scope's refusals
/// for a file the user may not read.
NamedPseudoReality load_requested_pseudo_reality(const std::string& name_or_path,
                                                 const FileScope& scope = FileScope::local());
/// A specification from its stored text (a design's folder), InvalidRequest when malformed.
NamedPseudoReality pseudo_reality_from_document(const std::string& reference, const std::string& document);
/// "K" or "A-B" with 1 <= A <= B, at most 10,000 samples; InvalidRequest otherwise.
std::vector<std::uint64_t> parse_sample_range(const std::string& text);
/// The mission run in sample k of the specification (its robot model replaced).
Mission in_pseudo_reality(const Mission& mission, const PseudoRealitySpec& spec, std::uint64_t sample);
/// As a front end asks for one sample (evaluate, export-argos, Python's Mission.in_pseudo_reality):
/// `mission` in sample `sample` ("K") of `pseudo_reality` (a shipped name or a file, read under
/// `scope`); unchanged when both are empty. InvalidRequest when only one is given, or for a range.
Mission in_requested_sample(Mission mission, const std::string& pseudo_reality, const std::string& sample,
                            const FileScope& scope = FileScope::local());

/// The shipped pseudo-realities, one row each: name, description, source, digest and the knobs
/// it varies (`pseudo-realities --json`, `GET /api/pseudo-realities`, `sd.pseudo_realities()`).
nlohmann::json pseudo_realities_document();
/// A specification's samples (`samples` as parse_sample_range reads it) as robot models beside
/// the design model of `mission`'s robot (`pseudo-realities NAME --json`, `sd.pseudo_reality_samples`).
nlohmann::json pseudo_reality_samples_document(const std::string& name_or_path, const std::string& mission,
                                               const std::string& samples, const FileScope& scope = FileScope::local());

}  // namespace sd::app
