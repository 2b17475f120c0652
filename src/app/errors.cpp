#include "app/errors.hpp"

#include "control/config_string.hpp"
#include "experiments/protocol.hpp"
#include "missions/mission.hpp"
#include "storage/home_archive.hpp"

namespace sd::app {

ErrorKind classify(const std::exception& error) {
  if (dynamic_cast<const InvalidRequest*>(&error) || dynamic_cast<const storage::InvalidInput*>(&error) ||
      dynamic_cast<const ConfigError*>(&error) || dynamic_cast<const MissionError*>(&error) ||
      dynamic_cast<const experiments::ProtocolError*>(&error))
    return ErrorKind::InvalidRequest;
  if (dynamic_cast<const NotFound*>(&error)) return ErrorKind::NotFound;
  if (dynamic_cast<const Conflict*>(&error)) return ErrorKind::Conflict;
  if (dynamic_cast<const AccessDenied*>(&error)) return ErrorKind::AccessDenied;
  if (dynamic_cast<const TooManyAttempts*>(&error)) return ErrorKind::TooManyAttempts;
  if (dynamic_cast<const DesignFolderError*>(&error) || dynamic_cast<const storage::BackupError*>(&error))
    return ErrorKind::Refused;
  return ErrorKind::Failed;
}

int exit_status(ErrorKind kind) { return kind == ErrorKind::InvalidRequest ? 2 : 1; }

}  // namespace sd::app
