#pragma once
// Every module law, by flavour: what catalogue.cpp puts in each entry. A law is defined next
// to the laws it shares code with (behaviours.cpp, maple_behaviours.cpp, conditions.cpp).
#include "modules/law.hpp"

namespace sd::laws {

/// Stop (11, 21 without its colour, 31, 41): both wheels at 0.
extern const BehaviourLaw stop;
/// What an id the catalogue lacks runs: a law that throws std::invalid_argument, never a
/// silent stop.
extern const BehaviourLaw unknown_behaviour;
extern const ConditionLaw unknown_condition;

namespace chocolate {  // 10-15, ARGoS3-AutoMoDe master
extern const BehaviourLaw exploration, phototaxis, anti_phototaxis, attraction, repulsion;
}
namespace tuttifrutti {  // 20-29: Chocolate's laws plus the LED colour cle; the colour followers
extern const BehaviourLaw exploration, stop, attraction, repulsion, go_to_color, go_away_color;
}
namespace coconut {  // 30-35, Demiurge: the exploration scheme is a parameter
extern const BehaviourLaw exploration, phototaxis, anti_phototaxis, attraction, repulsion;
}
namespace maple {  // 40-45, the behaviour-tree branch's own laws
extern const BehaviourLaw exploration, phototaxis, anti_phototaxis, attraction, repulsion;
}
namespace arlequin {  // 50-55: the module's shipped network, by digit
extern const BehaviourLaw network[6];
}

/// The floor conditions, one set per reference model's floor filter: RM1.2's (Chocolate,
/// Maple), RM3.0's (TuttiFrutti), Demiurge's 10-step one (Coconut, Arlequin).
struct FloorLaws {
  const ConditionLaw &black, &gray, &white;
};
extern const FloorLaws rm1_floor, demiurge_floor;
extern const ConditionLaw neighbours_count, inverted_neighbours_count, fixed_probability, color_detection;

}  // namespace sd::laws
