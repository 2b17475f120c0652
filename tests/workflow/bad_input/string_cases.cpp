// Each string format: FSM, BT and NN configuration strings and the legacy one-digit form,
// with malformed numbers, unknown modules, truncation, huge and non-UTF-8 tokens.
#include <sstream>

#include "workflow/bad_input/catalogue.hpp"

namespace sd::test::bad_input {

namespace {
std::vector<std::string> split(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> tokens;
  for (std::string token; in >> token;) tokens.push_back(token);
  return tokens;
}

// A whole EvoStick network: 2 outputs x 25 inputs.
const std::string kNetwork = [] {
  std::string text = "--nn-config";
  for (int o = 0; o < 2; ++o)
    for (int i = 0; i < 25; ++i) text += " --w" + std::to_string(o) + "x" + std::to_string(i) + " 0.5";
  return text;
}();

// A configuration string and a phrase the error must contain (the token at fault).
const std::vector<std::pair<std::string, std::string>> kStrings{
    // FSM.
    {"--fsm-config", "--nstates"},
    {"--fsm-config --nstates", "--nstates"},
    {"--fsm-config --nstates 0", "--nstates"},
    {"--fsm-config --nstates 5 --s0 0", "--nstates"},
    {"--fsm-config --nstates -1", "--nstates"},
    {"--fsm-config --nstates x", "--nstates"},
    {"--fsm-config --nstates 1 --s0", "--s0"},
    {"--fsm-config --nstates 1 --s0 99", "--s0"},
    {"--fsm-config --nstates 1 --s0 10 --rwm0 abc", "--rwm0"},
    {"--fsm-config --nstates 1 --s0 10 --rwm0 1e999", "--rwm0"},
    {"--fsm-config --nstates 1 --s0 10 --rwm0 500", "--rwm0"},
    {"--fsm-config --nstates 1 --s0 10 --rwm0 nan", "--rwm0"},
    {"--fsm-config --nstates 1 --s0 10 --rwmX 5", "--rwmX"},
    {"--fsm-config --nstates 1 --s0 77", "77"},
    {"--fsm-config --nstates 1 --nstates 1 --s0 10", "--nstates"},
    {"--fsm-config --nstates 2 --s0 10 --rwm0 50 --s1 11 --n0 1 --n0x0 0 --c0x0 99", "'--c0x0 99': unknown condition id 99"},
    {"--fsm-config --nstates 2 --s0 10 --rwm0 50 --s1 11 --n0 1 --n0x0 5 --c0x0 15 --p0x0 0.5", "--n0x0"},
    {"--fsm-config --nstates 1 --s0 10 --rwm0 50 --n0 9", "--n0"},
    {"--fsm-config --nstates 2 --s0 10 --rwm0 50 --s1 11 --n0 1 --n0x0 0 --c0x0 15 --p0x0 2", "'--p0x0 2'"},
    {"--fsm-config --nstates 1 --s0 10 --rwm0 50 --n0 1", "'--n0 1'"},
    {"--fsm-config --nstates 1 --s0 10 --rwm0 " + std::string(100000, '5'), "--rwm0"},
    {"--fsm-config --nstates 1 --s0 10 --rwm0 50 --" + std::string(5000, 'z') + " 1", "--zzz"},
    {"--fsm-config --nstates 1 --s0 10 --rwm0 \xff\xfe", "--rwm0"},
    {"--fsm-config --nstates 1 --s0 10 --\xc3\x28 1", "--"},
    // BT.
    {"--bt-config", "--nroot"},
    {"--bt-config --nroot 3", "--nchildroot"},
    {"--bt-config --nroot 9 --nchildroot 1", "--nroot"},
    {"--bt-config --nroot 3 --nchildroot 0", "--nchildroot"},
    {"--bt-config --nroot 3 --nchildroot 99", "--nchildroot"},
    {"--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 99", "--c00"},
    {"--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 x", "--p00"},
    {"--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 1 --n01 5 --a01 98", "--a01"},
    {"--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 1", "--n01"},
    {"--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 1 --n01 5 --a01 44 --att01 1e400",
     "--att01"},
    // NN (EvoStick networks).
    {"--nn-config", "--w0x0"},
    {"--nn-config --w0x0 abc", "--w0x0"},
    {"--nn-config --w0x0 1", "--w"},
    {kNetwork + " --w9x99 1", "'--w9x99 1'"},
    {kNetwork + " --w0x0 1", "duplicate token '--w0x0'"},
    {kNetwork.substr(0, kNetwork.rfind(" --w")), "missing --w1x24"},
    // Legacy one-digit strings (Chocolate by default).
    {"--fsm-config --nstates 1 --s0 7", "--s0"},
    {"--fsm-config --nstates 2 --s0 0 --rwm0 50 --s1 1 --n0 1 --n0x0 0 --c0x0 9", "--c0x0"},
    {"--fsm-config --nstates 1 --s0 0 --rwm0 5x", "--rwm0"},
    {"--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 9", "--c00"},
    {"--fsm-config --nstates 1 --s0 0 --s0 1", "--s0"},
};
}  // namespace

std::vector<CliCase> string_cases(const Inputs&) {
  std::vector<CliCase> cases;
  for (const auto& [text, phrase] : kStrings) {
    std::vector<std::string> show{"show-config"};
    std::vector<std::string> evaluate{"evaluate", "--mission", "aac", "--json"};
    for (const auto& token : split(text)) {
      show.push_back(token);
      evaluate.push_back(token);
    }
    cases.push_back({show, "", 2, phrase});
    cases.push_back({evaluate, "", 2, phrase});
  }
  // The legacy flavour changes how one-digit strings read; a Maple legacy string with a
  // Chocolate-only module, and test-design in the active project.
  for (const char* flavour : {"maple", "tuttifrutti"}) {
    std::vector<std::string> args{"show-config", "--legacy-flavour", flavour};
    for (const auto& token : split("--fsm-config --nstates 2 --s0 0 --rwm0 50 --s1 1 --n0 1 --n0x0 0 --c0x0 8")) args.push_back(token);
    cases.push_back({args, "", 2, "--"});
  }
  for (const auto& token_text : {"--fsm-config --nstates 0", "--bt-config --nroot 3 --nchildroot 0"}) {
    std::vector<std::string> args{"test-design", "--seeds", "1-2"};
    for (const auto& token : split(token_text)) args.push_back(token);
    cases.push_back({args, "", 2, "--n"});
  }
  return cases;
}

}  // namespace sd::test::bad_input
