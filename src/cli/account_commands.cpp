// Accounts: sign-up, sign-in, exit, show-users (thesis spellings as aliases), change-password, quota.
#include <nlohmann/json.hpp>
#include <CLI/CLI.hpp>
#include <signal.h>
#include <termios.h>
#include <unistd.h>

#include <iostream>
#include <memory>
#include <string>

#include "app/account_admin.hpp"
#include "app/accounts.hpp"
#include "app/documents.hpp"
#include "app/quotas.hpp"
#include "cli/command_registry.hpp"
#include "storage/clock.hpp"
#include "storage/passwords.hpp"

namespace sd::cli::account_commands {
namespace {

// ---- Reading a password -----------------------------------------------------------------

termios saved_terminal{};
volatile sig_atomic_t echo_is_off = 0;

// A Ctrl-C at the password prompt must not leave the terminal without echo.
extern "C" void restore_echo_and_reraise(int signal_number) {
  if (echo_is_off) tcsetattr(STDIN_FILENO, TCSANOW, &saved_terminal);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

/// Turns terminal echo off for its lifetime.
class EchoOff {
 public:
  EchoOff() {
    if (tcgetattr(STDIN_FILENO, &saved_terminal) != 0) throw std::runtime_error("cannot read the terminal settings");
    struct sigaction action {};
    action.sa_handler = restore_echo_and_reraise;
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &action, &previous_[i]);
    termios quiet = saved_terminal;
    quiet.c_lflag &= ~static_cast<tcflag_t>(ECHO);
    echo_is_off = 1;
    if (tcsetattr(STDIN_FILENO, TCSAFLUSH, &quiet) != 0) {
      echo_is_off = 0;
      for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &previous_[i], nullptr);
      throw std::runtime_error("cannot turn off terminal echo");
    }
  }
  ~EchoOff() {
    tcsetattr(STDIN_FILENO, TCSAFLUSH, &saved_terminal);
    echo_is_off = 0;
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &previous_[i], nullptr);
  }
  EchoOff(const EchoOff&) = delete;
  EchoOff& operator=(const EchoOff&) = delete;

 private:
  static constexpr int kSignals[3] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction previous_[3] {};
};

std::string read_line_or_fail(const char* what) {
  std::string line;
  if (!std::getline(std::cin, line) && line.empty()) throw UsageError(std::string("no password given on ") + what);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

std::string prompt_without_echo(const std::string& prompt) {
  std::string line;
  {
    EchoOff echo_off;  // before the prompt, so nothing typed after it is ever echoed
    std::cerr << prompt << std::flush;
    line = read_line_or_fail("the terminal");
  }
  std::cerr << '\n';  // the user's Enter was not echoed
  return line;
}

/// One line of stdin with --password-stdin, else a no-echo prompt (twice when `confirm`).
std::string read_password(bool from_stdin, const std::string& prompt, bool confirm) {
  if (from_stdin) return read_line_or_fail("standard input");
  if (!isatty(STDIN_FILENO))
    throw UsageError("standard input is not a terminal; to pass the password on standard input use --password-stdin");
  std::string password = prompt_without_echo(prompt);
  if (confirm) {
    std::string again = prompt_without_echo("Repeat the password: ");
    const bool same = again == password;
    storage::wipe(again);
    if (!same) {
      storage::wipe(password);
      throw UsageError("the two passwords differ; nothing was changed");
    }
  }
  return password;
}

/// Wipes the password when the command is done with it, whichever way it ends.
struct Password {
  std::string text;
  ~Password() { storage::wipe(text); }
};

// ---- The commands -------------------------------------------------------------------------

struct AccountOptions {
  std::string user;
  bool password_stdin = false;
  bool json = false;
};

void sign_up(const AccountOptions& options) {
  app::Home home;
  app::check_new_user_name(home, options.user);  // before asking for a password that would be thrown away
  Password password{read_password(options.password_stdin, "Password for new user " + options.user + ": ", true)};
  const auto user = app::sign_up(home, options.user, password.text);
  std::cout << "Created user " << user.name << ". Sign in with: swarmdesign sign-in " << user.name << '\n';
}

// The current password then the new one (twice on a terminal; two lines with --password-stdin).
void change_password(const AccountOptions& options) {
  app::Home home;
  const storage::User user = app::signed_in_user(home);
  Password old_password{read_password(options.password_stdin, "Current password for " + user.name + ": ", false)};
  Password new_password{read_password(options.password_stdin, "New password: ", true)};
  app::change_password_here(home, old_password.text, new_password.text);
  std::cout << "Changed the password of " << user.name << "; its other sessions (other terminals, web pages) are signed out.\n";
}

void sign_in(const AccountOptions& options) {
  app::Home home;
  Password password{read_password(options.password_stdin, "Password for " + options.user + ": ", false)};
  const auto signed_in = app::sign_in_here(home, options.user, password.text);
  std::cout << "Signed in as " << signed_in.user.name << " until " << storage::format_time(signed_in.expires_at)
            << ".\n";
}

void sign_out() {
  app::Home home;
  const app::SignedOut out = app::sign_out_here(home);
  if (out.removed_damaged_file) std::cout << "Removed the session file; you are signed out.\n";
  else if (!out.was_signed_in) std::cout << "Not signed in; nothing to do.\n";
  else std::cout << "Signed out" << (out.user ? " " + *out.user : std::string()) << ".\n";
}

void show_users(const AccountOptions& options) {
  app::Home home;
  const app::UserList list = app::list_users(home);
  if (options.json) {
    std::cout << app::users_document(list).dump(2) << '\n';
    return;
  }
  if (list.users.empty()) {
    std::cout << "No users yet. Create one with: swarmdesign sign-up USER\n";
    return;
  }
  for (const auto& user : list.users)
    std::cout << (list.me && *list.me == user.id ? "* " : "  ") << user.name << "  (since "
              << storage::format_time(user.created_at) << ")\n";
  if (list.me) std::cout << "(* signed in)\n";
}

void show_quota(const AccountOptions& options) {
  app::Home home;
  const storage::User user = app::signed_in_user(home);
  const app::QuotaUse use = app::quota_use(home, user);
  if (options.json) std::cout << app::quota_document(use).dump(2) << '\n';
  else std::cout << user.name << ": " << app::quota_text(use) << "\n";
}

const std::string kPasswordHelp =
    "The password is read from the terminal without echo, or as one line of standard input "
    "with --password-stdin.";

CommandRegistrar registrar{10, [](CLI::App& app, Context&) {
  auto options = std::make_shared<AccountOptions>();

  auto* sign_up_command = app.add_subcommand("sign-up", "Create a SwarmDesign account");
  sign_up_command->alias("signUp");
  sign_up_command->add_option("USER", options->user, "user name: a letter, then letters, digits, '.', '_' or '-'")
      ->required();
  sign_up_command->add_flag("--password-stdin", options->password_stdin, "read the password from standard input");
  sign_up_command->footer(kPasswordHelp + " Rule: " + storage::password_rule() +
                          ". It is stored only as an Argon2id hash.\n\nExample:\n  swarmdesign sign-up alice\n"
                          "  printf '%s\\n' \"$PASSWORD\" | swarmdesign sign-up alice --password-stdin");
  sign_up_command->callback([options] { sign_up(*options); });

  auto* sign_in_command = app.add_subcommand("sign-in", "Sign in; later commands act as this user");
  sign_in_command->alias("signIn");
  sign_in_command->add_option("USER", options->user, "user name")->required();
  sign_in_command->add_flag("--password-stdin", options->password_stdin, "read the password from standard input");
  sign_in_command->footer(kPasswordHelp + " A session lasts 7 days (or until `swarmdesign exit`); its token is kept in "
                          "$SWARMDESIGN_HOME/session, readable only by you. Five wrong passwords in a row lock the name for "
                          "a minute (here and in the web app).\n\nExample:\n  swarmdesign sign-in alice");
  sign_in_command->callback([options] { sign_in(*options); });

  auto* change_command = app.add_subcommand("change-password", "Change your own password (signs out your other sessions)");
  change_command->add_flag("--password-stdin", options->password_stdin,
                           "read the current password, then the new one, one line each, from standard input");
  change_command->footer(kPasswordHelp + " Rule: " + storage::password_rule() +
                         ". Your other sessions (other terminals, web pages) end; this one stays.\n\n"
                         "Example:\n  swarmdesign change-password");
  change_command->callback([options] { change_password(*options); });

  auto* exit_command = app.add_subcommand("exit", "Sign out: end the session and delete its token");
  exit_command->footer("Example:\n  swarmdesign exit");
  exit_command->callback([] { sign_out(); });

  auto* quota_command = app.add_subcommand("quota", "What your account uses of its quotas: disk and runs per day");
  quota_command->add_flag("--json", options->json, "print one JSON document");
  quota_command->footer("An administrator sets them (swarmdesign admin quota). A design counts its budget when it starts,\n"
                        "an experiment its whole plan; a resumed one counts nothing more. Work that would pass a\n"
                        "limit, and a file that would pass the disk limit, is refused before anything is written.\n\n"
                        "Example:\n  swarmdesign quota");
  quota_command->callback([options] { show_quota(*options); });

  auto* show_users_command = app.add_subcommand("show-users", "List the user names (* marks you)");
  show_users_command->alias("showUsers");
  show_users_command->add_flag("--json", options->json, "print one JSON document");
  show_users_command->footer("Example:\n  swarmdesign show-users");
  show_users_command->callback([options] { show_users(*options); });
}};

}  // namespace
}  // namespace sd::cli::account_commands
