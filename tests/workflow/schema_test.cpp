// Migrations: a new home gets the latest schema, reopening changes nothing, a home an older
// SwarmDesign left (with rows) migrates keeping every row, and a database from a newer
// SwarmDesign is refused rather than damaged.
#include <gtest/gtest.h>

#include <filesystem>

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

TEST_F(workflow_schema, AHomeOfSchema8WithRowsMigratesToTheLatestKeepingEveryRow) {
  // As a SwarmDesign of schema 8 left it (before methods, quotas and invitations): two accounts,
  // a project with a design, an experiment whose EvoStick design was assessed.
  {
    std::filesystem::create_directories(home());
    storage::Database db(database());
    storage::migrate_to(db, 8);
    ASSERT_EQ(storage::schema_version(db), 8);
    db.execute(R"sql(
      INSERT INTO users (name, password_hash, created_at, role) VALUES ('ann', '$argon2id$old', 1, 'admin'), ('bob', '$argon2id$old', 2, 'user');
      INSERT INTO projects (owner_id, name, path, mission, budget, location, created_at) VALUES (1, 'p', 'users/ann/projects/p', 'aac', 5000, 'local', 3);
      INSERT INTO designs (project_id, architectures, flavours, mission, budget, seed, state, path, created_at, updated_at)
        VALUES (1, 'fsm', 'chocolate', 'aac', 5000, 7, 'finished', 'users/ann/projects/p/designs/1', 4, 5);
      INSERT INTO experiments (project_id, name, protocol, state, owner, heartbeat_at, path, created_at, updated_at)
        VALUES (1, 'e', '{}', 'finished', '', 0, 'users/ann/projects/p/experiments/e', 6, 7);
      INSERT INTO experiment_designs (experiment_id, mission, condition, replicate, method, architectures, flavours, budget, seed)
        VALUES (1, 'aac', 'evo', 1, 'evostick', 'fsm', 'chocolate', 1000, 9);
      INSERT INTO experiment_assessments (design_id, seed, score) VALUES (1, 1, 2.5), (1, 2, 3.5);
    )sql");
  }
  run_ok({"show-users"});  // any command migrates the home it opens
  EXPECT_EQ(query("PRAGMA user_version"), std::to_string(storage::latest_schema_version()));
  EXPECT_EQ(query("PRAGMA integrity_check"), "ok");
  EXPECT_EQ(query("SELECT count(*) FROM pragma_foreign_key_check"), "0");
  // Every row is there, the new columns at their meaning for older rows.
  EXPECT_EQ(query("SELECT group_concat(name || ':' || role || ':' || ifnull(quota_disk_bytes, 'default'), ' ') FROM users"),
            "ann:admin:default bob:user:default");
  EXPECT_EQ(query("SELECT method || ':' || state || ':' || seed FROM designs"), "automode:finished:7");
  EXPECT_EQ(query("SELECT method || ':' || condition FROM experiment_designs"), "evostick:evo");
  // Migration 9 edits experiment_designs' CHECK in place: rebuilding the table would have
  // cascaded the deletion of its assessments.
  EXPECT_EQ(query("SELECT group_concat(score, ' ') FROM experiment_assessments"), "2.5 3.5");
  EXPECT_EQ(query("SELECT count(*) FROM server_quota"), "1");
  EXPECT_EQ(query("SELECT count(*) FROM run_use") + query("SELECT count(*) FROM invitations"), "00");
  {  // and the edited CHECK takes any method's name now, still refusing an empty one
    storage::Database db(database(), false);
    db.execute("INSERT INTO experiment_designs (experiment_id, mission, condition, replicate, method, architectures, flavours, budget, seed) "
               "VALUES (1, 'aac', 'other', 1, 'random-search', 'fsm', 'chocolate', 1000, 9)");
    EXPECT_THROW(db.execute("INSERT INTO experiment_designs (experiment_id, mission, condition, replicate, method, architectures, "
                            "flavours, budget, seed) VALUES (1, 'aac', 'empty', 1, '', 'fsm', 'chocolate', 1000, 9)"),
                 storage::DatabaseError);
  }
  const std::string migrated = snapshot();
  run_ok({"show-users"});
  EXPECT_EQ(snapshot(), migrated) << "migrated once";
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
