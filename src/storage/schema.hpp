#pragma once
// The accounts-and-projects schema and its versioned migrations (PRAGMA user_version).
#include "storage/sqlite.hpp"

namespace sd::storage {

/// The schema version this build writes and understands.
int latest_schema_version();

/// The version recorded in the database (0 for a new database).
int schema_version(Database& db);

/// Applies every missing migration, each in its own transaction, so a crash leaves the
/// database at a whole version. Refuses a database written by a newer SwarmDesign.
void migrate(Database& db);
/// The same up to `version` only: a home as an older SwarmDesign left it (the migration tests).
void migrate_to(Database& db, int version);

}  // namespace sd::storage
