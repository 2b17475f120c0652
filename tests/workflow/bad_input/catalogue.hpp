#pragma once
// The bad-input catalogue: every user-facing input with malformed variants, as data. Each case
// names the input kind, the command line or route, the bad input, the documented status and a
// phrase the one error line must contain to name what is wrong.
#include <filesystem>
#include <string>
#include <vector>

namespace sd::test::bad_input {

/// One command line that must be refused.
struct CliCase {
  std::vector<std::string> args;
  std::string input;  // standard input
  int exit_code;      // cli.md: 2 misuse, 1 refused work
  std::string phrase;
};

/// How an HTTP case is sent.
enum class Caller { SignedIn, SignedOut, NoCsrf, WrongContentType };

struct HttpCase {
  std::string method;  // GET or POST
  std::string path;
  std::string body;  // sent as is (may be malformed JSON)
  Caller caller;
  int status;
  std::string phrase;
};

/// Where the catalogue's prepared inputs live (files written by write_bad_files).
struct Inputs {
  std::filesystem::path scratch;  // outside the home
  std::filesystem::path files;    // the malformed files
  std::filesystem::path own;      // a folder inside alice's projects (for the web's own-file rule)
};

/// Writes every malformed file the cases name under inputs.files and inputs.own.
void write_bad_files(const Inputs& inputs);

std::vector<CliCase> argument_cases(const Inputs& inputs);
std::vector<CliCase> file_cases(const Inputs& inputs);
std::vector<CliCase> string_cases(const Inputs& inputs);
std::vector<HttpCase> http_cases(const Inputs& inputs);

}  // namespace sd::test::bad_input
