// A design as a job of the application layer, with no CLI in between: a test observer watches
// it, a cancel token stops it at a checkpoint chosen in advance, prepare_resume continues it,
// and it ends exactly where an uninterrupted run — and the `swarmdesign design` command — ends.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/design_job.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "evaluation/evaluator.hpp"
#include "workflow/design_helpers.hpp"
#include "workflow/swarmdesign_process.hpp"

namespace sd::test {
namespace {

/// Counts what the design reports, and cancels it once checkpoint `cancel_at` is durable.
class Watcher final : public app::DesignObserver {
 public:
  explicit Watcher(std::int64_t cancel_at = 0) : cancel_at_(cancel_at) {}
  void progress(const design::Progress& p) override {
    ++progress_calls;
    EXPECT_GE(p.experiments_used, last_experiments);
    EXPECT_LE(p.experiments_used, p.budget);
    last_experiments = p.experiments_used;
  }
  void checkpoint(std::int64_t step) override {
    EXPECT_EQ(step, last_step + 1) << "checkpoints are numbered one by one";
    last_step = step;
    if (cancel_at_ > 0 && step == cancel_at_) token.cancel();
  }
  app::CancelToken token;
  int progress_calls = 0;
  long long last_experiments = 0;
  std::int64_t last_step = 0;

 private:
  std::int64_t cancel_at_;
};

class DesignJob : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("sd-app-" + std::to_string(::getpid()) + "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
    mission_ = write_short_mission(folder_).string();
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  app::NewDesignSettings settings(long long budget = 1100, std::uint64_t seed = 5) const {
    design::DesignSpaceRequest space;
    space.fsm = true;
    space.flavours = {Flavour::Chocolate};
    return {mission_, budget, space, seed};
  }
  static nlohmann::json outcome_of(const app::DesignReport& report) {
    return design_outcome(app::design_report_document(report).dump());
  }

  std::filesystem::path folder_;
  std::string mission_;
};

TEST_F(DesignJob, CancelledAtACheckpointAndResumedItEndsAsTheUninterruptedDesignAndTheCli) {
  // Uninterrupted, through the library.
  app::PreparedDesign whole = app::prepare_new_design(settings(), folder_ / "whole");
  Watcher watch_whole;
  const app::DesignOutcome done = app::run_design(whole, {.threads = 2, .observer = &watch_whole});
  ASSERT_FALSE(done.cancelled);
  ASSERT_TRUE(done.report);
  EXPECT_GT(watch_whole.progress_calls, 10);
  EXPECT_EQ(watch_whole.last_experiments, done.report->experiments_used);

  // Cancelled at checkpoint 12 (mid-race), then resumed on another thread count.
  const auto parts = folder_ / "parts";
  app::PreparedDesign first = app::prepare_new_design(settings(), parts);
  Watcher stopper(12);
  const app::DesignOutcome stopped = app::run_design(first, {.threads = 1, .observer = &stopper, .cancel = &stopper.token});
  EXPECT_TRUE(stopped.cancelled);
  EXPECT_FALSE(stopped.report);
  EXPECT_EQ(stopper.last_step, 12);
  EXPECT_EQ(checkpoint_step(parts), 12);
  EXPECT_LT(stopped.experiments_used, done.report->experiments_used);

  app::PreparedDesign rest = app::prepare_resume(parts);
  EXPECT_TRUE(rest.resuming);
  Watcher watch_rest;
  watch_rest.last_step = 12;  // the resumed design numbers its checkpoints on from the last one
  const app::DesignOutcome resumed = app::run_design(rest, {.threads = 2, .observer = &watch_rest});
  ASSERT_TRUE(resumed.report);
  EXPECT_TRUE(resumed.report->resumed);
  EXPECT_EQ(outcome_of(*resumed.report), outcome_of(*done.report));
  EXPECT_EQ(experiment_log(parts), experiment_log(folder_ / "whole"));

  // The command line runs the same job: the same design, the same result.
  const Outcome cli = run_swarmdesign({"design", "--mission", mission_, "--budget", "1100", "--fsm", "--chocolate",
                                       "--seed", "5", "--threads", "1", "--json", "--out", (folder_ / "cli").string()},
                                      "", {});
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  EXPECT_EQ(design_outcome(cli.out), outcome_of(*done.report));
}

/// Local threads that, in batch `batch`, score half the batch and then hear a cancel: what a
/// Stop pressed in the middle of a long race step does.
class CancelMidStep final : public Evaluator {
 public:
  CancelMidStep(app::CancelToken& token, int batch) : token_(token), batch_(batch) {}
  void evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) override {
    if (++batches_ == batch_) {
      EXPECT_GE(tasks.size(), 2u);
      const std::size_t half = tasks.size() / 2;
      inner_.evaluate(mission, tasks.first(half), scores.first(half));
      token_.cancel();
      inner_.stop_when(&token_.flag());
      inner_.evaluate(mission, tasks.subspan(half), scores.subspan(half));  // throws EvaluationStopped
      ADD_FAILURE() << "a raised stop flag must stop the batch";
    }
    inner_.evaluate(mission, tasks, scores);
  }
  int workers() const override { return 1; }
  int batches() const { return batches_; }

 private:
  ThreadedEvaluator inner_{1};
  app::CancelToken& token_;
  int batch_;
  int batches_ = 0;
};

TEST_F(DesignJob, ACancelInTheMiddleOfARaceStepStopsItThereAndTheResumedDesignIsTheUninterruptedOne) {
  app::PreparedDesign whole = app::prepare_new_design(settings(), folder_ / "whole");
  const app::DesignOutcome done = app::run_design(whole, {.threads = 2});
  ASSERT_TRUE(done.report);

  const auto parts = folder_ / "parts";
  app::PreparedDesign first = app::prepare_new_design(settings(), parts);
  app::CancelToken token;
  CancelMidStep evaluator(token, 6);
  const app::DesignOutcome stopped = app::run_design(first, {.threads = 1, .evaluator = &evaluator, .cancel = &token});
  EXPECT_TRUE(stopped.cancelled);
  EXPECT_FALSE(stopped.report);
  EXPECT_EQ(evaluator.batches(), 6) << "no batch after the cancel";
  EXPECT_GT(stopped.experiments_used, 0);
  EXPECT_LT(stopped.experiments_used, done.report->experiments_used);

  // The half-scored step left nothing behind: resumed, the design is the uninterrupted one.
  app::PreparedDesign rest = app::prepare_resume(parts);
  const app::DesignOutcome resumed = app::run_design(rest, {.threads = 2});
  ASSERT_TRUE(resumed.report);
  EXPECT_EQ(outcome_of(*resumed.report), outcome_of(*done.report));
  EXPECT_EQ(experiment_log(parts), experiment_log(folder_ / "whole"));
}

TEST_F(DesignJob, BadRequestsAreRefusedBeforeAnythingIsWritten) {
  auto small = settings(50);
  EXPECT_THROW(app::prepare_new_design(small, folder_ / "small"), app::InvalidRequest);
  auto unknown = settings();
  unknown.mission = "no-such-mission";
  EXPECT_THROW(app::prepare_new_design(unknown, folder_ / "unknown"), app::InvalidRequest);
  EXPECT_THROW(app::prepare_resume(folder_ / "nothing-here"), app::DesignFolderError);
  EXPECT_FALSE(std::filesystem::exists(folder_ / "small"));
  EXPECT_FALSE(std::filesystem::exists(folder_ / "unknown"));

  try {
    app::prepare_new_design(small, folder_ / "small");
  } catch (const std::exception& e) {
    EXPECT_EQ(app::exit_status(app::classify(e)), 2);
    EXPECT_NE(std::string(e.what()).find("below the minimum"), std::string::npos);
  }
}

TEST_F(DesignJob, AFinishedDesignIsNotResumedAndAFolderIsNotReused) {
  app::PreparedDesign d = app::prepare_new_design(settings(), folder_ / "d");
  ASSERT_TRUE(app::run_design(d, {.threads = 2}).report);
  EXPECT_THROW(app::prepare_resume(folder_ / "d"), app::DesignFolderError);
  EXPECT_THROW(app::prepare_new_design(settings(), folder_ / "d"), app::DesignFolderError);
  EXPECT_NO_THROW(app::prepare_resume(folder_ / "d", true));
}

TEST_F(DesignJob, EachSearchMethodResumesToItsUninterruptedDesignAndTheCliRunsTheSame) {
  for (const design::MethodInfo* method : {&design::kRandomSearch, &design::kLocalSearch}) {
    const std::string name(method->name);
    SCOPED_TRACE(name);
    auto asked = settings();
    asked.method = method;
    app::PreparedDesign whole = app::prepare_new_design(asked, folder_ / (name + "-whole"));
    const app::DesignOutcome done = app::run_design(whole, {.threads = 2});
    ASSERT_TRUE(done.report);
    EXPECT_EQ(done.report->method, name);
    EXPECT_EQ(app::design_report_document(*done.report).at("method"), name);

    const auto parts = folder_ / (name + "-parts");
    app::PreparedDesign first = app::prepare_new_design(asked, parts);
    Watcher stopper(9);
    ASSERT_TRUE(app::run_design(first, {.threads = 1, .observer = &stopper, .cancel = &stopper.token}).cancelled);
    app::PreparedDesign rest = app::prepare_resume(parts);
    EXPECT_EQ(rest.method, method);  // read back from design.db
    const app::DesignOutcome resumed = app::run_design(rest, {.threads = 2});
    ASSERT_TRUE(resumed.report);
    EXPECT_EQ(outcome_of(*resumed.report), outcome_of(*done.report));
    EXPECT_EQ(experiment_log(parts), experiment_log(folder_ / (name + "-whole")));

    // Asked again with the other optimiser, the folder's design is refused, naming its method.
    try {
      app::prepare_design_in(settings(), parts);
      ADD_FAILURE() << "another method must not continue this design";
    } catch (const app::DesignFolderError& e) {
      EXPECT_NE(std::string(e.what()).find("method " + name), std::string::npos) << e.what();
    }

    const Outcome cli = run_swarmdesign({"design", "--mission", mission_, "--budget", "1100", "--fsm", "--chocolate",
                                         "--seed", "5", "--method", name, "--threads", "1", "--json", "--out",
                                         (folder_ / (name + "-cli")).string()},
                                        "", {});
    ASSERT_EQ(cli.exit_code, 0) << cli.err;
    EXPECT_EQ(design_outcome(cli.out), outcome_of(*done.report));
  }
  // Not the same design as Iterated F-Race's with the same seed.
  app::PreparedDesign irace = app::prepare_new_design(settings(), folder_ / "irace");
  ASSERT_TRUE(app::run_design(irace, {.threads = 2}).report);
  EXPECT_NE(experiment_log(folder_ / "irace"), experiment_log(folder_ / "random-search-whole"));
  EXPECT_NE(experiment_log(folder_ / "local-search-whole"), experiment_log(folder_ / "random-search-whole"));

  const Outcome unknown = run_swarmdesign({"design", "--mission", mission_, "--budget", "1100", "--method", "evostick",
                                           "--out", (folder_ / "evo").string()},
                                          "", {});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("unknown design method 'evostick' (automode, random-search or local-search)"), std::string::npos)
      << unknown.err;
}

}  // namespace
}  // namespace sd::test
