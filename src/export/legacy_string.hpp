#pragma once
// Control software as the ARGoS3-AutoMoDe code base of its flavour reads it: the inverse of
// the legacy reader (ParseOptions::legacy_flavour), so that export, then parse with that
// flavour, gives back the same control software bit for bit. Which code base reads what:
//   Chocolate   one-digit ids; FSMs for ARGoS3-AutoMoDe master's automode_main, trees
//               (--nroot form) for the BehaviorTree branch's automode_main_bt.
//   TuttiFrutti one-digit ids, FSMs only (ARGoS3-AutoMoDe branch tuttifrutti).
//   Maple       one-digit ids; trees in Maple's own --rootnode form when they have its shape
//               (Sequence* over Selectors of conditions then one action that never succeeds),
//               else the BehaviorTree branch's --nroot form; FSMs as Chocolate's.
//   Coconut,    no one-digit code base: the only implementation, the unified Demiurge code
//   Arlequin    base (AmmarHsn/Demiurge), reads the two-digit ids SwarmDesign prints (its
//               commit b5bacbe read Coconut as "--flavor 2" with one-digit ids; its
//               commit 0179ecf reads two digits). Demiurge's Arlequin modules run its own NEAT
//               genomes, not SwarmDesign's networks: the string carries no weights.
// Every code base reads the neighbour-count threshold xi from --p<i>x<j> and eta from
// --w<i>x<j>, as SwarmDesign does, except Demiurge, which reads xi from --n<i>x<j> (the
// token that also names the destination): there a neighbour-count condition exports only
// from an FSM and when its xi equals that token's value (Demiurge's tree builder gives
// conditions no xi at all).
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "control/control_software.hpp"

namespace sd::argos {

/// The control software cannot be given to the code base asked for; the message names every
/// module (or the architecture) that stands in the way.
struct ExportRefused : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

enum class TreeForm { Automatic, RootNode, NRoot };

struct ExportOptions {
  std::optional<Flavour> flavour;  // none: the one flavour every module belongs to
  TreeForm tree_form = TreeForm::Automatic;
};

struct LegacyString {
  std::string text;      // starts with --fsm-config or --bt-config
  Flavour flavour = Flavour::Chocolate;
  std::string reader;    // the code base and program that read it
};

LegacyString to_legacy_string(const ControlSoftware& software, const ExportOptions& options = {});

/// "chocolate, tuttifrutti, maple, coconut or arlequin" -> the flavour; ExportRefused otherwise.
Flavour export_flavour(const std::string& name);

}  // namespace sd::argos
