// Migrations: a new home gets the latest schema, reopening changes nothing, and a database
// from a newer SwarmDesign is refused rather than damaged.
#include <gtest/gtest.h>

#include "storage/schema.hpp"
#include "storage/sqlite.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {
namespace {

using workflow_schema = WorkflowTest;

TEST_F(workflow_schema, ANewHomeGetsTheLatestSchemaWithForeignKeysAndWal) {
  run_ok({"show-users"});
  EXPECT_EQ(query("PRAGMA user_version"), std::to_string(storage::latest_schema_version()));
  EXPECT_EQ(query("PRAGMA journal_mode"), "wal");
  const std::string first = snapshot();
  run_ok({"show-users"});
  EXPECT_EQ(snapshot(), first);
}

TEST_F(workflow_schema, ADatabaseFromANewerSwarmDesignIsRefused) {
  run_ok({"show-users"});
  {
    storage::Database db(database(), false);
    db.execute("PRAGMA user_version = 999");
  }
  expect_error(run({"show-users"}), 1, "newer than this swarmdesign understands");
  EXPECT_EQ(query("PRAGMA user_version"), "999");
}

}  // namespace
}  // namespace sd::test
