// What ranks send each other survives the trip exactly, malformed buffers are refused, and a
// batch is cut so that every rank gets work and no chunk is empty.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mpi/mpi_evaluator.hpp"
#include "mpi/wire.hpp"

namespace sd::mpi {
namespace {

TEST(wire, WorkChunksRoundTripExactly) {
  WorkChunk chunk{7, 3, 42, 2, "abc123", {{-1, 9, "--fsm-config --nstates 1 --s0 0 --rwm0 5", {}}, {17, 1ULL << 40, "", {}}}};
  const WorkChunk back = decode_work(encode(chunk));
  EXPECT_EQ(back.evaluator, 7u);
  EXPECT_EQ(back.batch, 3u);
  EXPECT_EQ(back.first, 42u);
  EXPECT_EQ(back.threads, 2);
  EXPECT_EQ(back.mission_digest, "abc123");
  ASSERT_EQ(back.tasks.size(), 2u);
  EXPECT_EQ(back.tasks[0].key, -1);
  EXPECT_EQ(back.tasks[0].software, chunk.tasks[0].software);
  EXPECT_EQ(back.tasks[1].key, 17);
  EXPECT_EQ(back.tasks[1].seed, 1ULL << 40);
}

TEST(wire, ScoresKeepEveryBit) {
  const ChunkScores scores{9, 3, {0.1, -0.0, std::nextafter(1.0, 2.0), std::numeric_limits<double>::infinity(), 1e-310}};
  const ChunkScores back = decode_scores(encode(scores));
  ASSERT_EQ(back.scores.size(), scores.scores.size());
  for (std::size_t i = 0; i < scores.scores.size(); ++i) {
    EXPECT_EQ(std::signbit(back.scores[i]), std::signbit(scores.scores[i]));
    EXPECT_EQ(back.scores[i], scores.scores[i]);
  }
  EXPECT_EQ(back.first, 3u);
  EXPECT_EQ(back.batch, 9u);
}

TEST(wire, MissionsAndFailuresRoundTrip) {
  const MissionText mission = decode_mission(encode(MissionText{"d1", "{\"name\": \"x\"}", "built-in"}));
  EXPECT_EQ(mission.digest, "d1");
  EXPECT_EQ(mission.document, "{\"name\": \"x\"}");
  EXPECT_EQ(mission.source, "built-in");
  const ChunkFailure failure = decode_failure(encode(ChunkFailure{2, 5, "the mission does not load here"}));
  EXPECT_EQ(failure.first, 5u);
  EXPECT_EQ(failure.message, "the mission does not load here");
}

TEST(wire, TruncatedOrPaddedBuffersAreRefused) {
  auto bytes = encode(WorkChunk{1, 1, 0, 1, "d", {{1, 2, "software", {}}}});
  auto truncated = bytes;
  truncated.resize(bytes.size() - 3);
  EXPECT_THROW(decode_work(truncated), WireError);
  auto padded = bytes;
  padded.push_back('x');
  EXPECT_THROW(decode_work(padded), WireError);
  EXPECT_THROW(decode_scores(std::vector<char>(5, '\xff')), WireError);
}

TEST(chunks, AFewRunsPerThreadFewerWhenTheBatchIsShort) {
  EXPECT_EQ(chunk_size(400, 1, 3), 2u);   // long batch: two runs per thread
  EXPECT_EQ(chunk_size(400, 4, 12), 8u);
  EXPECT_EQ(chunk_size(5, 1, 3), 1u);     // short batch: one run, so every rank gets some
  EXPECT_EQ(chunk_size(1, 8, 64), 8u);    // one run per thread at least (the caller clips to what is left)
  EXPECT_GE(chunk_size(0, 1, 1), 1u);
}

}  // namespace
}  // namespace sd::mpi
