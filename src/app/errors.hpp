#pragma once
// What can go wrong in a job, as kinds a front end maps once: the CLI to exit statuses
// (misuse 2, everything else 1), a server to HTTP codes. The rule for "misuse": the request
// itself is wrong whatever the stored state — a malformed value (budget, seed, password,
// configuration string, mission file), a value out of its domain, a name that no catalogue
// has (mission, module, flavour), a budget below the optimiser's minimum. A well-formed request
// that the stored state refuses (not signed in, no such project, a design still running, a
// design that cannot be resumed) is a failure of the work, and so is a run that fails.
#include <exception>
#include <stdexcept>
#include <string>

#include "storage/design_store.hpp"
#include "storage/errors.hpp"

namespace sd::app {

/// The request is malformed (see above).
struct InvalidRequest : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// InvalidRequest(problem) unless it is empty: for the validators that return a problem's line.
inline void require(const std::string& problem) {
  if (!problem.empty()) throw InvalidRequest(problem);
}

/// The job's own errors are storage's: NotFound, Conflict, AccessDenied, and
/// DesignFolderError for a design folder that cannot be used as asked.
using storage::AccessDenied;
using storage::Conflict;
using storage::DesignFolderError;
using storage::NotFound;
using storage::TooManyAttempts;

enum class ErrorKind { InvalidRequest, NotFound, Conflict, AccessDenied, Refused, TooManyAttempts, Failed };

/// The kind of an error thrown by a job (anything unknown is Failed).
ErrorKind classify(const std::exception& error);

/// The CLI's exit status for an error: 2 for InvalidRequest, 1 for any other.
int exit_status(ErrorKind kind);

}  // namespace sd::app
