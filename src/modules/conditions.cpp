#include "modules/conditions.hpp"

#include <cmath>
#include <stdexcept>

#include "core/math.hpp"
#include "modules/laws.hpp"

namespace sd {

double neighbours_probability(double xi, double eta, int neighbours) {
  // xi is stored as an integer by AutoMoDe; the difference is signed (the old unsigned
  // wrap-around is a bug we do not reproduce).
  return 1.0 / (1.0 + math::exp(eta * (std::trunc(xi) - static_cast<double>(neighbours))));
}

std::vector<double> neighbours_table(const ModuleInstance& c, int max_neighbours) {
  const ModuleSpec* spec = find_module(ModuleKind::Condition, c.id);
  if (!spec || !spec->condition.neighbours_logistic) return {};
  const LawParameters p = spec->law_parameters(c);
  std::vector<double> table;
  for (int n = 0; n <= max_neighbours; ++n) table.push_back(neighbours_probability(p[0], p[1], n));
  return table;
}

namespace {

// A table is sized for one swarm; a count it does not cover is computed rather than assumed
// impossible.
double lookup_neighbours_probability(LawParameters p, int neighbours, std::span<const double> table) {
  if (neighbours >= 0 && static_cast<std::size_t>(neighbours) < table.size())
    return table[static_cast<std::size_t>(neighbours)];
  return neighbours_probability(p[0], p[1], neighbours);
}

}  // namespace

bool check_condition(const ModuleInstance& c, const ReferenceModel& rm, Rng& rng, std::span<const double> table) {
  const ModuleSpec& spec = module_to_run(ModuleKind::Condition, c.id);
  return spec.condition.check(spec.law_parameters(c), rm, rng, table);
}

// The laws the catalogue's entries carry (laws.hpp). A floor condition's Bernoulli draw
// happens only on its floor, as in AutoMoDe.
namespace laws {

namespace {
using P = LawParameters;
using RM = ReferenceModel;
using Table = std::span<const double>;
constexpr ParameterNames kProbability{"p"};
}  // namespace

namespace {
const ConditionLaw rm1_black{[](P p, const RM& rm, Rng& rng, Table) { return rm.ground <= 0.1 && rng.bernoulli(p[0]); }, kProbability};
const ConditionLaw rm1_gray{[](P p, const RM& rm, Rng& rng, Table) { return rm.ground > 0.1 && rm.ground < 0.95 && rng.bernoulli(p[0]); }, kProbability};
const ConditionLaw rm1_white{[](P p, const RM& rm, Rng& rng, Table) { return rm.ground >= 0.95 && rng.bernoulli(p[0]); }, kProbability};
// Coconut and Arlequin run on Demiurge's RM3.0, whose floor filter keeps 10 steps.
const ConditionLaw demiurge_black{[](P p, const RM& rm, Rng& rng, Table) { return rm.ground_demiurge <= 0.1 && rng.bernoulli(p[0]); }, kProbability};
const ConditionLaw demiurge_gray{[](P p, const RM& rm, Rng& rng, Table) {
  return rm.ground_demiurge > 0.1 && rm.ground_demiurge < 0.95 && rng.bernoulli(p[0]);
}, kProbability};
const ConditionLaw demiurge_white{[](P p, const RM& rm, Rng& rng, Table) { return rm.ground_demiurge >= 0.95 && rng.bernoulli(p[0]); }, kProbability};
}  // namespace

const ConditionLaw unknown_condition{[](P, const RM&, Rng&, Table) -> bool {
  throw std::invalid_argument("a condition module the catalogue lacks was checked");
}, {}};

const FloorLaws rm1_floor{rm1_black, rm1_gray, rm1_white};
const FloorLaws demiurge_floor{demiurge_black, demiurge_gray, demiurge_white};

const ConditionLaw neighbours_count{[](P p, const RM& rm, Rng& rng, Table table) {
  return rng.bernoulli(lookup_neighbours_probability(p, rm.neighbours, table));
}, {"p", "w"}, /*neighbours_logistic=*/true};
const ConditionLaw inverted_neighbours_count{[](P p, const RM& rm, Rng& rng, Table table) {
  return rng.bernoulli(1.0 - lookup_neighbours_probability(p, rm.neighbours, table));
}, {"p", "w"}, /*neighbours_logistic=*/true};
const ConditionLaw fixed_probability{[](P p, const RM&, Rng& rng, Table) { return rng.bernoulli(p[0]); }, kProbability};
// ColorDetection (TuttiFrutti): a blob of colour l at 6 cm or more.
const ConditionLaw color_detection{[](P p, const RM& rm, Rng& rng, Table) {
  const std::uint32_t rgb = palette_color(static_cast<int>(p[1]));
  for (const CameraBlob& blob : rm.blobs)
    if (blob.rgb == rgb && blob.distance_cm >= 6.0) return rng.bernoulli(p[0]);
  return false;
}, {"p", "l"}};

}  // namespace laws

}  // namespace sd
