#pragma once
// A workflow test whose home is also served over HTTP (the real `run-exp` binary), for the tests
// that check that the CLI and the page agree: the server starts once the accounts it needs
// exist (serve(), or the first signed_in()) and stops before the home is removed.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "web/web_client.hpp"
#include "workflow/workflow_fixture.hpp"

namespace sd::test {

class ServedWorkflowTest : public WorkflowTest {
 protected:
  void TearDown() override {
    server_.reset();
    WorkflowTest::TearDown();
  }
  /// Serves home() from now on (once).
  void serve() {
    if (!server_) server_.emplace(home());
  }
  int port() {
    serve();
    return server_->port();
  }
  /// A client of the server signed in as `name` (a refused sign-in fails the test).
  WebClient signed_in(const std::string& name, const std::string& password) {
    WebClient client(port());
    EXPECT_TRUE(client.sign_in(name, password)) << name << ": " << client.last_refusal();
    return client;
  }

 private:
  std::optional<RunningServer> server_;
};

}  // namespace sd::test
