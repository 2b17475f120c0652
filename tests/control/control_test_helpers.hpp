#pragma once
// Small builders shared by the control tests: module instances, FSM states, a check that
// an error message names a configuration token and a comparison of generator states.
#include <cctype>
#include <initializer_list>
#include <string>
#include <utility>

#include "control/control_software.hpp"
#include "core/rng.hpp"

namespace sd::test {

inline ModuleInstance module(int id, std::initializer_list<double> parameters = {}) {
  ModuleInstance m;
  m.id = id;
  std::size_t p = 0;
  for (const double v : parameters) m.parameters[p++] = v;
  return m;
}

inline FsmTransition transition(int target, ModuleInstance condition) { return {target, condition}; }

inline FsmState state(ModuleInstance behaviour, std::initializer_list<FsmTransition> transitions = {}) {
  return {behaviour, transitions};
}

inline ControlSoftware fsm(std::initializer_list<FsmState> states) {
  ControlSoftware software;
  software.architecture = Architecture::Fsm;
  software.fsm.states = states;
  return software;
}

inline bool same_rng_state(const Rng& a, const Rng& b) {
  const Rng::State x = a.state(), y = b.state();
  for (int i = 0; i < 4; ++i)
    if (x.s[i] != y.s[i]) return false;
  return x.coarse_left == y.coarse_left && x.coarse_bits == y.coarse_bits;
}

/// True if `message` contains `token` as a whole token ("--n1" does not match "--n1x0").
inline bool names_token(const std::string& message, const std::string& token) {
  for (std::size_t at = message.find(token); at != std::string::npos; at = message.find(token, at + 1)) {
    const std::size_t end = at + token.size();
    const bool clean_end = end == message.size() || !(std::isalnum(static_cast<unsigned char>(message[end])));
    const bool clean_start = at == 0 || message[at - 1] != '-';
    if (clean_end && clean_start) return true;
  }
  return false;
}

}  // namespace sd::test
