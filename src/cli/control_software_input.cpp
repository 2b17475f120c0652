#include "cli/control_software_input.hpp"

#include <CLI/CLI.hpp>

#include "core/bounded_file.hpp"

namespace sd::cli {

void add_control_software_options(CLI::App& command, ControlSoftwareOptions& options) {
  command.add_option("--config-file", options.config_file, "Read the control software from FILE instead of the command line");
  command.add_option("--legacy-flavour", options.legacy_flavour,
                     "Flavour of one-digit legacy strings: chocolate, tuttifrutti, maple (default chocolate)");
}

ControlSoftware read_control_software(const Context& context, const ControlSoftwareOptions& options) {
  const auto flavour = flavour_from_name(options.legacy_flavour);
  if (!flavour) throw UsageError("--legacy-flavour: unknown flavour '" + options.legacy_flavour + "'");
  ParseOptions parse;
  parse.legacy_flavour = *flavour;
  if (!options.config_file.empty()) {
    if (context.has_control_software()) throw UsageError("give the control software either inline or with --config-file, not both");
    std::string text;
    try {
      text = read_bounded_file(options.config_file, "configuration file").text;
    } catch (const FileReadError& e) {
      throw UsageError(std::string("--config-file: ") + e.what());
    }
    return parse_control_software(text, parse);
  }
  if (!context.has_control_software()) throw UsageError("no control software: end the command with --fsm-config ...");
  return parse_control_software(std::span<const std::string>(context.control_software), parse);
}

}  // namespace sd::cli
