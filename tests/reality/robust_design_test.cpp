// A robust design: Iterated F-Race whose instances are pseudo-reality samples. Its runs are
// the samples' runs, it is reproducible from its seed, it resumes from its folder to the same
// end, and its folder says how it was made.
#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "app/design_job.hpp"
#include "app/documents.hpp"
#include "app/errors.hpp"
#include "storage/design_store.hpp"
#include "workflow/design_helpers.hpp"

namespace sd::test {
namespace {

class RobustDesign : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("sd-robust-" + std::to_string(::getpid()) + "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
    mission_ = write_short_mission(folder_).string();
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  app::NewDesignSettings settings(const std::string& pseudo_reality, const std::string& samples = "101-104") const {
    app::NewDesignSettings s;
    s.mission = mission_;
    s.budget = 1100;
    s.space.fsm = true;
    s.space.flavours = {Flavour::Chocolate};
    s.seed = 7;
    s.pseudo_reality = pseudo_reality;
    s.pseudo_reality_samples = samples;
    return s;
  }
  nlohmann::json run(const app::NewDesignSettings& s, const std::string& name, const app::CancelToken* cancel = nullptr) {
    app::PreparedDesign d = app::prepare_new_design(s, folder_ / name);
    const app::DesignOutcome o = app::run_design(d, {.threads = 2, .cancel = cancel});
    return o.report ? design_outcome(app::design_report_document(*o.report).dump()) : nlohmann::json();
  }

  std::filesystem::path folder_;
  std::string mission_;
};

TEST_F(RobustDesign, RacesOnTheSamplesAndSaysSoInItsFolderAndReport) {
  const app::PreparedDesign d = app::check_new_design(settings("sampled-around"));
  ASSERT_TRUE(d.reality);
  ASSERT_EQ(d.instance_models.size(), 4u);
  EXPECT_EQ(d.options.n_instances, 4u);
  const nlohmann::json robust = run(settings("sampled-around"), "robust");
  const nlohmann::json plain = run(settings(""), "plain");
  EXPECT_NE(robust, plain) << "racing in other robot models must change the race";
  const storage::DesignMeta meta = storage::DesignStore::open(folder_ / "robust").meta();
  EXPECT_EQ(meta.pseudo_reality, "sampled-around");
  EXPECT_EQ(meta.pseudo_reality_samples, "101-104");
  EXPECT_NE(meta.pseudo_reality_document.find("\"knobs\""), std::string::npos);
  EXPECT_TRUE(storage::DesignStore::open(folder_ / "plain").meta().pseudo_reality.empty());
  // Same seed, same design.
  EXPECT_EQ(run(settings("sampled-around"), "again"), robust);
}

TEST_F(RobustDesign, ResumesToTheEndOfAnUninterruptedRun) {
  const nlohmann::json whole = run(settings("sampled-around"), "whole");
  app::CancelToken token;
  token.cancel();  // stops after its first race step
  EXPECT_TRUE(run(settings("sampled-around"), "cut", &token).is_null());
  app::PreparedDesign resumed = app::prepare_resume(folder_ / "cut");
  ASSERT_TRUE(resumed.reality);
  EXPECT_EQ(resumed.instance_models.size(), 4u);
  const app::DesignOutcome o = app::run_design(resumed, {.threads = 1});
  ASSERT_TRUE(o.report);
  EXPECT_EQ(design_outcome(app::design_report_document(*o.report).dump()), whole);
}

TEST_F(RobustDesign, BadPseudoRealitiesAreRefusedBeforeAnythingIsWritten) {
  EXPECT_THROW(app::prepare_new_design(settings("nowhere"), folder_ / "x"), app::InvalidRequest);
  EXPECT_THROW(app::prepare_new_design(settings("sampled-around", "0-3"), folder_ / "x"), app::InvalidRequest);
  EXPECT_THROW(app::prepare_new_design(settings("sampled-around", "1-5000"), folder_ / "x"), app::InvalidRequest);
  EXPECT_FALSE(std::filesystem::exists(folder_ / "x"));
}

}  // namespace
}  // namespace sd::test
