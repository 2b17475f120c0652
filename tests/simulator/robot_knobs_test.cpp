// Each knob of the robot model (kRobotKnobs) against what the argos3-epuck code does with
// the same setting: the noise's distribution, measured over many draws with tolerances of
// five standard errors, and the per-robot deviations' gains. The design model (the new
// knobs all 0) must run bit for bit as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "control/config_string.hpp"
#include "core/rng.hpp"
#include "evaluation/simulation.hpp"
#include "evaluation/trace_writer.hpp"
#include "missions/catalogue.hpp"
#include "missions/mission.hpp"
#include "simulator/epuck.hpp"
#include "simulator/robot_deviations.hpp"
#include "simulator/sensors.hpp"
#include "swarm_builder.hpp"

namespace sd {
namespace {

using test::robots;

RobotModel noiseless() {
  RobotModel m;
  m.proximity_noise = m.light_noise = m.ground_noise = m.wheel_noise = 0.0;
  m.rab_loss = 0.0;
  return m;
}

/// Mean and variance of a sample (Welford's update), the standard error of its mean, and its
/// extremes.
struct Moments {
  double n = 0.0, mean_ = 0.0, m2 = 0.0, min = INFINITY, max = -INFINITY;
  void add(double x) {
    n += 1.0;
    const double delta = x - mean_;
    mean_ += delta / n;
    m2 += delta * (x - mean_);
    min = std::min(min, x);
    max = std::max(max, x);
  }
  double mean() const { return mean_; }
  double variance() const { return m2 / (n - 1.0); }
  double sd() const { return std::sqrt(variance()); }
  double standard_error() const { return std::sqrt(variance() / n); }
};

// ---- Light noise: argos3-epuck adds U(-a, a) to each reading, then truncates to [0, 1].

TEST(RobotKnobs, LightNoiseOnADarkSensorIsTheClampedUniform) {
  ArenaModel arena;  // no light: every true reading is 0
  arena.compile();
  for (const double a : {0.9, 0.05}) {
    RobotModel model = noiseless();
    model.light_noise = a;
    SwarmState s = robots({{{0, 0}, 0.3}});
    Rng rng(17);
    Moments reading;
    double positive = 0.0;
    for (int t = 0; t < 5000; ++t) {
      sense_light(arena, model, s, rng);
      for (const double v : s.light[0]) {
        reading.add(v);
        positive += v > 0.0 ? 1.0 : 0.0;
      }
    }
    // clamp01(U(-a, a)): 0 half the time, else U(0, a); mean a / 4, E[X^2] = a^2 / 6, and
    // kurtosis 2.376, so a sample standard deviation's relative error is sqrt(1.376 / 4n).
    const double mean = a / 4.0, sd = std::sqrt(a * a / 6.0 - mean * mean);
    EXPECT_NEAR(reading.mean(), mean, 5.0 * sd / std::sqrt(reading.n)) << "a = " << a;
    EXPECT_NEAR(positive / reading.n, 0.5, 5.0 * 0.5 / std::sqrt(reading.n)) << "a = " << a;
    EXPECT_NEAR(reading.sd(), sd, 5.0 * sd * std::sqrt(1.376 / (4.0 * reading.n))) << "a = " << a;
  }
}

TEST(RobotKnobs, LightNoiseAddsToALitSensorAndTruncatesAtOne) {
  // A sensor whose true reading r lies in (0.1, 0.9) reads, with a = 0.9, clamp01(r + U):
  // 1 with probability (r - 0.1) / 1.8, 0 with probability (0.9 - r) / 1.8, else r + U.
  ArenaModel arena;
  arena.lights.push_back({{0.3, 0.0, 0.1}, 1.0});
  arena.compile();
  SwarmState s = robots({{{0, 0}, 0.0}});
  Rng rng(5);
  sense_light(arena, noiseless(), s, rng);
  const double truth = s.light[0][0];
  ASSERT_GT(truth, 0.3);
  ASSERT_LT(truth, 0.8);
  RobotModel model = noiseless();
  model.light_noise = 0.9;
  Moments reading;
  double ones = 0.0;
  for (int t = 0; t < 40000; ++t) {
    sense_light(arena, model, s, rng);
    reading.add(s.light[0][0]);
    ones += s.light[0][0] == 1.0 ? 1.0 : 0.0;
  }
  const double p_one = (truth + 0.9 - 1.0) / 1.8;
  EXPECT_NEAR(ones / reading.n, p_one, 5.0 * std::sqrt(p_one * (1.0 - p_one) / reading.n));
  // E[clamp01(r + U)] = (integral of x over [0, 1] + 1 x (r - 0.1)) / 1.8.
  const double mean = (0.5 + (truth - 0.1)) / 1.8;
  EXPECT_NEAR(reading.mean(), mean, 5.0 * reading.standard_error());
}

// ---- Range-and-bearing loss.

/// Whether a robot's body (other than a's and b's) lies within a body radius of the segment
/// between the centres of a and b: an independent statement of the RAB line of sight.
bool body_between(const SwarmState& s, int a, int b) {
  const Vec2 pa = s.position[static_cast<std::size_t>(a)], ab = s.position[static_cast<std::size_t>(b)] - pa;
  for (int c = 0; c < s.size; ++c) {
    if (c == a || c == b) continue;
    const Vec2 pc = s.position[static_cast<std::size_t>(c)] - pa;
    const double t = dot(pc, ab) / ab.squared_length();
    if (t <= 0.0 || t >= 1.0) continue;
    if ((pc - ab * t).length() < epuck::kBodyRadius) return true;
  }
  return false;
}

/// A random swarm of `n` robots in a square of side `side`, no two closer than 8 cm.
SwarmState random_swarm(int n, double side, Rng& rng) {
  SwarmState s;
  s.resize(n);
  for (int i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(i);
    bool ok = false;
    while (!ok) {
      s.position[r] = {rng.uniform(0.0, side), rng.uniform(0.0, side)};
      ok = true;
      for (std::size_t j = 0; j < r; ++j) ok = ok && (s.position[j] - s.position[r]).length() > 0.08;
    }
    s.yaw[r] = rng.uniform(-kPi, kPi);
    s.heading[r] = Vec2::polar(1.0, s.yaw[r]);
  }
  s.broad_phase.build(s.position);
  return s;
}

TEST(RobotKnobs, RabLossOneDropsEveryPacketAndLossZeroDeliversEveryVisiblePairBothWays) {
  ArenaModel arena;
  arena.compile();
  RobotModel all = noiseless(), none = noiseless();
  none.rab_loss = 1.0;
  Rng placement(3), rng(4);
  int delivered = 0, hidden = 0, far = 0;
  for (int config = 0; config < 200; ++config) {
    SwarmState s = random_swarm(8, 1.2, placement);
    sense_range_and_bearing(arena, none, s, rng);
    for (int i = 0; i < s.size; ++i) EXPECT_EQ(s.rab_count[static_cast<std::size_t>(i)], 0);
    sense_range_and_bearing(arena, all, s, rng);
    for (int i = 0; i < s.size; ++i) {
      // Which senders robot i hears, against distance and line of sight.
      std::set<int> heard;
      const auto r = static_cast<std::size_t>(i);
      for (int k = 0; k < s.rab_count[r]; ++k) {
        const RabPacket& p = s.rab[r * s.rab_stride() + static_cast<std::size_t>(k)];
        heard.insert(p.sender);
        const double d = (s.position[p.sender] - s.position[r]).length();
        EXPECT_NEAR(p.range_cm, d * 100.0 - 7.0, 1e-9);
      }
      for (int j = 0; j < s.size; ++j) {
        if (j == i) continue;
        const bool in_range = (s.position[static_cast<std::size_t>(j)] - s.position[r]).length() < all.rab_range;
        const bool visible = !body_between(s, i, j);
        EXPECT_EQ(heard.count(j) == 1, in_range && visible) << "config " << config << ": " << j << " -> " << i;
        delivered += in_range && visible ? 1 : 0;
        hidden += in_range && !visible ? 1 : 0;
        far += in_range ? 0 : 1;
      }
    }
  }
  // The configurations cover all three cases.
  EXPECT_GT(delivered, 1000);
  EXPECT_GT(hidden, 50);
  EXPECT_GT(far, 1000);
}

// ---- Range-and-bearing position noise: argos3-epuck adds CVector3(N(0, s), inclination
// U[0, pi], azimuth U[0, 2 pi)) to the sender-minus-receiver offset, range = its 3D length
// in cm minus 7 and bearing = its azimuth in the receiver's frame.

TEST(RobotKnobs, RabNoiseAddsAVectorOfNormalLengthToTheSenderOffset) {
  ArenaModel arena;
  arena.compile();
  const double d = 0.5;
  for (const double noise : {0.05, 0.1}) {
    RobotModel model = noiseless();
    model.rab_noise = noise;
    // Robot 1 lies due north of robot 0, which faces east: its true bearing is pi / 2.
    SwarmState s = robots({{{0, 0}, 0.0}, {{0.0, d}, 1.0}});
    Rng rng(21);
    Moments squared, bearing_error;
    const int draws = 50000;
    for (int t = 0; t < draws; ++t) {
      sense_range_and_bearing(arena, model, s, rng);
      ASSERT_EQ(s.rab_count[0], 1);
      const RabPacket& p = s.rab[0];
      const double r = (p.range_cm + 7.0) / 100.0;
      squared.add(r * r);
      bearing_error.add(wrap_signed(p.bearing() - kPi / 2.0));
    }
    // |offset + n|^2 = d^2 + 2 offset.n + L^2: E = d^2 + s^2 whatever n's direction.
    EXPECT_NEAR(squared.mean(), d * d + noise * noise, 5.0 * squared.standard_error()) << "s = " << noise;
    EXPECT_NEAR(bearing_error.mean(), 0.0, 5.0 * bearing_error.standard_error()) << "s = " << noise;
    // The bearing error atan(n_across / (d + n_along)) has variance E[n_across^2] / d^2 =
    // s^2 E[sin^2 inclination] E[sin^2 azimuth] / d^2 = s^2 / (4 d^2) for ARGoS' draw (the
    // inclination uniform in angle, not in area, which would give s^2 / 3; a planar vector,
    // s^2 / 2), plus (9 / 16) s^2 / d^2 of that at the next order. n_across has kurtosis
    // 27 / 4, hence the standard error of the variance.
    const double predicted = noise * noise / (4.0 * d * d) * (1.0 + 9.0 / 16.0 * noise * noise / (d * d));
    const double variance_se = predicted * std::sqrt((27.0 / 4.0 - 1.0) / draws);
    EXPECT_NEAR(bearing_error.variance(), predicted, 5.0 * variance_se) << "s = " << noise;
  }
}

TEST(RobotKnobs, RabWithoutNoiseIsExact) {
  ArenaModel arena;
  arena.compile();
  SwarmState s = robots({{{0, 0}, 0.0}, {{0.3, 0.4}, 1.0}});
  Rng rng(2);
  for (int t = 0; t < 100; ++t) {
    sense_range_and_bearing(arena, noiseless(), s, rng);
    ASSERT_EQ(s.rab_count[0], 1);
    EXPECT_NEAR(s.rab[0].range_cm, 43.0, 1e-9);
    EXPECT_NEAR(s.rab[0].bearing(), std::atan2(0.4, 0.3), 1e-12);
  }
}

// ---- Camera noise: argos3-epuck adds CVector2(N(0, s), U[0, 2 pi)) to the LED's planar
// offset after the in-view check, and reports that vector's length in cm and its angle.

TEST(RobotKnobs, CameraNoiseAddsAPlanarVectorOfNormalLength) {
  ArenaModel arena;
  arena.compile();
  // Robot 1 faces east; its lit rear LED is 0.036 m behind its centre, d = 0.3 m east of
  // robot 0 (in view: within 0.335 m), which faces north (the blob lies to its right).
  const double d = 0.3;
  SwarmState s = robots({{{0, 0}, kPi / 2}, {{d + 0.036, 0.0}, 0.0}});
  s.led[1] = 0xff0000;
  RobotModel model;
  model.camera_noise = 0.05;
  // Without an Rng the camera is exact, noise or not.
  sense_camera(arena, model, s);
  ASSERT_EQ(s.blob_count[0], 1);
  EXPECT_NEAR(s.blobs[0].distance_cm, d * 100.0, 1e-9);
  Rng rng(9);
  Moments squared, angle_error;
  const int draws = 50000;
  for (int t = 0; t < draws; ++t) {
    sense_camera(arena, model, s, &rng);
    ASSERT_EQ(s.blob_count[0], 1);
    const double r = s.blobs[0].distance_cm / 100.0;
    squared.add(r * r);
    angle_error.add(wrap_signed(s.blobs[0].angle() + kPi / 2.0));
  }
  const double noise = model.camera_noise;
  EXPECT_NEAR(squared.mean(), d * d + noise * noise, 5.0 * squared.standard_error());
  EXPECT_NEAR(angle_error.mean(), 0.0, 5.0 * angle_error.standard_error());
  // A planar vector: the component across the offset has variance s^2 / 2 (kurtosis 9 / 2),
  // plus (3 / 4) s^2 / d^2 of that at the next order.
  const double predicted = noise * noise / (2.0 * d * d) * (1.0 + 0.75 * noise * noise / (d * d));
  const double variance_se = predicted * std::sqrt((9.0 / 2.0 - 1.0) / draws);
  EXPECT_NEAR(angle_error.variance(), predicted, 5.0 * variance_se);

  // s = 0 with an Rng: exact.
  model.camera_noise = 0.0;
  for (int t = 0; t < 100; ++t) {
    sense_camera(arena, model, s, &rng);
    ASSERT_EQ(s.blob_count[0], 1);
    EXPECT_NEAR(s.blobs[0].distance_cm, d * 100.0, 1e-9);
    EXPECT_NEAR(s.blobs[0].angle(), -kPi / 2.0, 1e-12);
  }
}

// ---- Wheel noise, through Simulation: argos3-epuck multiplies each wheel's speed by
// 1 + N(0, s) at every control step.

/// One robot alone in a large arena, starting at the origin facing +x; proximity noise 0 so
/// that exploration never turns: it drives straight at 12 cm/s for 3 s.
Mission lone_robot_mission() {
  Mission m = parse_mission(R"({
    "name": "lone-robot", "duration": 3, "robots": 1,
    "robot": {"proximity_noise": 0},
    "arena": {"walls": [{"regular_polygon": {"sides": 12, "apothem": 3.0, "length": 1.608, "thickness": 0.01, "height": 0.08}}]},
    "start": {"circle": {"center": [0, 0], "radius": 0.5}},
    "objective": {"type": "robots_in_region_per_tick", "region": {"circle": {"center": [1, 0], "radius": 0.2}}, "direction": "maximize"}
  })",
                            "test");
  m.start_poses = {{{0.0, 0.0}, 0.0}};
  return m;
}

struct Drive {
  double path = 0.0;     // m, the sum of each tick's displacement
  double forward = 0.0;  // m, the final displacement along the start heading
};

Drive drive(Simulation& simulation, std::uint64_t seed, const RobotModel& model) {
  simulation.reset(seed, &model);
  Drive result;
  Vec2 last = simulation.swarm().position[0];
  while (!simulation.finished()) {
    simulation.step();
    const Vec2 p = simulation.swarm().position[0];
    result.path += (p - last).length();
    last = p;
  }
  result.forward = last.x;
  return result;
}

TEST(RobotKnobs, WheelNoiseSpreadsTheDistanceDrivenInProportionToItsDeviation) {
  const Mission mission = lone_robot_mission();
  const ControlSoftware software = parse_control_software(std::string("--fsm-config --nstates 1 --s0 10 --rwm0 50"));
  Simulation simulation(mission, software);
  RobotModel model = mission.robot;
  Moments path[3], forward[3];  // forward: only its spread without noise is checked
  const double noises[3] = {0.0, 0.05, 0.15};
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    for (int k = 0; k < 3; ++k) {
      model.wheel_noise = noises[k];
      const Drive d = drive(simulation, seed, model);
      path[k].add(d.path);
      forward[k].add(d.forward);
    }
  }
  // Without noise every seed drives the same straight line.
  EXPECT_EQ(path[0].min, path[0].max);
  EXPECT_EQ(forward[0].min, forward[0].max);
  EXPECT_GT(forward[0].mean(), 0.3);
  // The path length is the sum over control steps of c_k x the mean of the two wheels'
  // speeds, 0.12 (1 + s (n_l + n_r) / 2), where c_k is how long the command drives: 0.1 s,
  // but 0.07 s for the first (the robot ramps up from rest) and 0.09 s for the last (a
  // tick's first sub-step moves at the previous speed). Its standard deviation is therefore
  // 0.12 s sqrt(sum c_k^2 / 2), sum c_k^2 = 0.07^2 + 27 x 0.1^2 + 0.09^2: linear in s. The
  // forward displacement is not: the heading's random walk shortens it by a term in s^2.
  // A sample standard deviation of n draws has a relative standard error of 1 / sqrt(2 n).
  const double per_s = 0.12 * std::sqrt((0.07 * 0.07 + 27 * 0.01 + 0.09 * 0.09) / 2.0);
  const double relative = 5.0 / std::sqrt(2.0 * path[1].n);
  EXPECT_NEAR(path[1].sd(), per_s * 0.05, relative * per_s * 0.05);
  EXPECT_NEAR(path[2].sd(), per_s * 0.15, relative * per_s * 0.15);
  EXPECT_NEAR(path[2].sd() / path[1].sd(), 3.0, 0.15 * 3.0);
  // The mean distance does not depend on the noise (E[1 + N(0, s)] = 1).
  EXPECT_NEAR(path[2].mean(), path[0].mean(), 5.0 * path[2].standard_error());
}

// ---- Per-robot deviations.

TEST(RobotKnobs, DeviationsAreUniformGainsFixedBySeedAndDifferentAcrossRobots) {
  RobotModel model;
  model.wheel_deviation = 0.1;
  model.proximity_deviation = 0.2;
  model.light_deviation = 0.3;
  model.rab_range_deviation = 0.25;
  const int n = 2000;
  RobotDeviations a, b, c;
  a.draw(model, n, 7);
  b.draw(model, n, 7);
  c.draw(model, n, 8);
  ASSERT_TRUE(a.active);
  auto check = [&](const std::vector<double>& gains, double deviation, double scale, const char* what) {
    ASSERT_EQ(gains.size(), static_cast<std::size_t>(n)) << what;
    Moments m;
    for (const double g : gains) {
      EXPECT_GE(g, scale * (1.0 - deviation)) << what;
      EXPECT_LE(g, scale * (1.0 + deviation)) << what;
      m.add(g / scale);
    }
    // U[1 - d, 1 + d]: mean 1, variance d^2 / 3, kurtosis 9 / 5 (so a sample standard
    // deviation's relative error is sqrt(0.8 / 4n)).
    const double sd = deviation / std::sqrt(3.0);
    EXPECT_NEAR(m.mean(), 1.0, 5.0 * sd / std::sqrt(n)) << what;
    EXPECT_NEAR(m.sd(), sd, 5.0 * sd * std::sqrt(0.8 / (4.0 * n))) << what;
    EXPECT_EQ(std::set<double>(gains.begin(), gains.end()).size(), gains.size()) << what << ": robots differ";
  };
  check(a.wheel_left, model.wheel_deviation, 1.0, "wheel_left");
  check(a.wheel_right, model.wheel_deviation, 1.0, "wheel_right");
  check(a.proximity, model.proximity_deviation, 1.0, "proximity");
  check(a.light, model.light_deviation, 1.0, "light");
  check(a.rab_range, model.rab_range_deviation, model.rab_range, "rab_range");
  EXPECT_NE(a.wheel_left, a.wheel_right);  // each wheel its own gain
  // The same seed draws the same gains; another seed, others.
  EXPECT_EQ(a.wheel_left, b.wheel_left);
  EXPECT_EQ(a.wheel_right, b.wheel_right);
  EXPECT_EQ(a.proximity, b.proximity);
  EXPECT_EQ(a.light, b.light);
  EXPECT_EQ(a.rab_range, b.rab_range);
  EXPECT_NE(a.wheel_left, c.wheel_left);
  EXPECT_NE(a.light, c.light);

  // One kind at 0: its gains are exactly 1, and the kinds drawn before it are unchanged.
  RobotModel no_light = model;
  no_light.light_deviation = 0.0;
  RobotDeviations d;
  d.draw(no_light, n, 7);
  EXPECT_EQ(d.wheel_left, a.wheel_left);
  EXPECT_EQ(d.wheel_right, a.wheel_right);
  EXPECT_EQ(d.proximity, a.proximity);
  for (const double g : d.light) EXPECT_EQ(g, 1.0);
}

// A kind at 0 still takes its draws, so the kinds after it get the same gains for a seed
// whether or not it deviates (found when this test first ran: they did not).
TEST(RobotKnobs, AKindsGainsDoNotDependOnWhetherAnotherKindIsDrawn) {
  RobotModel model;
  model.wheel_deviation = model.proximity_deviation = model.light_deviation = model.rab_range_deviation = 0.2;
  RobotModel no_light = model;
  no_light.light_deviation = 0.0;
  RobotDeviations a, b;
  a.draw(model, 20, 7);
  b.draw(no_light, 20, 7);
  EXPECT_EQ(a.rab_range, b.rab_range);
  RobotModel no_wheels = model;
  no_wheels.wheel_deviation = 0.0;
  b.draw(no_wheels, 20, 7);
  EXPECT_EQ(a.light, b.light);
}

TEST(RobotKnobs, WithoutDeviationsTheDrawIsInactiveAndTouchesNothing) {
  RobotDeviations dev;
  dev.active = true;
  dev.wheel_left = {0.5, 0.6};
  dev.wheel_right = {0.7};
  dev.proximity = {1.1, 1.2, 1.3};
  dev.light = {};
  dev.rab_range = {0.9};
  const RobotDeviations before = dev;
  dev.draw(RobotModel{}, 20, 3);
  EXPECT_FALSE(dev.active);
  EXPECT_EQ(dev.wheel_left, before.wheel_left);
  EXPECT_EQ(dev.wheel_right, before.wheel_right);
  EXPECT_EQ(dev.proximity, before.proximity);
  EXPECT_EQ(dev.light, before.light);
  EXPECT_EQ(dev.rab_range, before.rab_range);
}

const char* kAttractStop =
    "--fsm-config --nstates 2 --s0 14 --att0 5 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1.0 "
    "--s1 11 --n1 1 --n1x0 0 --c1x0 11 --p1x0 0.1";

/// A run's score and trace.
std::pair<double, std::string> traced(Simulation& simulation, std::uint64_t seed, const RobotModel* model) {
  std::ostringstream trace;
  TraceWriter writer(trace);
  const double score = simulation.run(seed, &writer, model);
  return {score, trace.str()};
}

TEST(RobotKnobs, DrawingDeviationsLeavesTheRunsOwnDrawsAlone) {
  // A light gain on software that never reads light changes nothing, but makes the
  // deviations active and drawn: the run must be the design model's, draw for draw.
  const Mission mission = load_mission("aac");
  const ControlSoftware software = parse_control_software(std::string(kAttractStop));
  Simulation simulation(mission, software);
  RobotModel model = mission.robot;
  model.light_deviation = 0.3;
  for (const std::uint64_t seed : {1u, 2u}) {
    const auto design = traced(simulation, seed, nullptr);
    const auto deviated = traced(simulation, seed, &model);
    EXPECT_EQ(design.first, deviated.first) << "seed " << seed;
    EXPECT_TRUE(design.second == deviated.second) << "seed " << seed << ": the traces differ";
  }
}

TEST(RobotKnobs, ProximityAndLightGainsScaleEachRobotsReadings) {
  ArenaModel arena;
  arena.lights.push_back({{1.0, 0.5, 0.3}, 1.0});
  arena.compile();
  // A row 10 cm apart: each robot's rays meet its neighbours' bodies (readings about 0.25).
  SwarmState s = robots({{{0.0, 0.0}, 0.0}, {{0.1, 0.0}, 0.0}, {{0.2, 0.0}, 0.0}, {{0.3, 0.0}, kPi}, {{0.4, 0.02}, 0.0}});
  Rng rng(1);
  const RobotModel model = noiseless();
  sense_proximity(arena, model, s, rng);
  sense_light(arena, model, s, rng);
  const std::vector<std::array<double, 8>> proximity = s.proximity, light = s.light;
  RobotModel deviated = model;
  deviated.proximity_deviation = 0.2;
  deviated.light_deviation = 0.3;
  s.deviations.draw(deviated, s.size, 11);
  sense_proximity(arena, deviated, s, rng);
  sense_light(arena, deviated, s, rng);
  int lit = 0, touched = 0;
  for (std::size_t i = 0; i < static_cast<std::size_t>(s.size); ++i) {
    for (std::size_t k = 0; k < 8; ++k) {
      ASSERT_LT(proximity[i][k] * 1.2, 1.0);  // no clamping hides the gain
      ASSERT_LT(light[i][k] * 1.3, 1.0);
      EXPECT_DOUBLE_EQ(s.proximity[i][k], proximity[i][k] * s.deviations.proximity[i]) << i << ", " << k;
      EXPECT_DOUBLE_EQ(s.light[i][k], light[i][k] * s.deviations.light[i]) << i << ", " << k;
      touched += proximity[i][k] > 0.0 ? 1 : 0;
      lit += light[i][k] > 0.0 ? 1 : 0;
    }
  }
  EXPECT_GT(touched, 4);
  EXPECT_GE(lit, 12);
}

TEST(RobotKnobs, RabRangeDeviationLetsAPacketReachAsFarAsItsSendersRange) {
  ArenaModel arena;
  arena.compile();
  RobotModel model = noiseless();
  model.rab_range = 0.7;
  model.rab_range_deviation = 0.2;
  Rng distances(1), rng(2);
  int one_way = 0, both = 0, neither = 0;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    const double d = distances.uniform(0.7 * 0.8, 0.7 * 1.2);
    SwarmState s = robots({{{0, 0}, 0.0}, {{d, 0.0}, 0.0}});
    s.deviations.draw(model, 2, seed);
    sense_range_and_bearing(arena, model, s, rng);
    const bool to0 = s.rab_count[0] == 1, to1 = s.rab_count[1] == 1;
    EXPECT_EQ(to0, d < s.deviations.rab_range[1]) << "seed " << seed;  // robot 1's packet
    EXPECT_EQ(to1, d < s.deviations.rab_range[0]) << "seed " << seed;
    one_way += to0 != to1 ? 1 : 0;
    both += to0 && to1 ? 1 : 0;
    neither += !to0 && !to1 ? 1 : 0;
  }
  EXPECT_GT(one_way, 200);
  EXPECT_GT(both, 200);
  EXPECT_GT(neither, 200);
}

// ---- The design model: the new knobs at 0 run exactly as the code did before them.

TEST(RobotKnobs, AtZeroTheNewNoisesDrawNothingFromTheRunsRng) {
  // What a design-model run draws must not depend on the new knobs' code: with rab_noise 0
  // the range-and-bearing sensor draws the same whether packets arrive or not (its loss
  // draws only), and with camera_noise 0 the camera draws nothing even when given the Rng.
  ArenaModel arena;
  arena.compile();
  auto draws_after_rab = [&](double noise, double loss) {
    RobotModel model = noiseless();
    model.rab_noise = noise;
    model.rab_loss = loss;
    SwarmState s = robots({{{0, 0}, 0.0}, {{0.3, 0.0}, 1.0}, {{0.0, 0.4}, 2.0}, {{0.3, 0.4}, 3.0}});
    Rng rng(8);
    for (int t = 0; t < 10; ++t) sense_range_and_bearing(arena, model, s, rng);
    return rng.next();
  };
  EXPECT_EQ(draws_after_rab(0.0, 0.0), draws_after_rab(0.0, 1.0));
  EXPECT_NE(draws_after_rab(0.05, 0.0), draws_after_rab(0.05, 1.0));  // noise draws per packet

  SwarmState s = robots({{{0, 0}, 0.0}, {{0.2, 0.0}, 0.0}});
  s.led[1] = 0x00ff00;
  RobotModel model;
  model.camera_noise = 0.0;
  Rng rng(8), untouched(8);
  sense_camera(arena, model, s, &rng);
  ASSERT_EQ(s.blob_count[0], 1);
  EXPECT_EQ(rng.next(), untouched.next());
}

TEST(RobotKnobs, TheDesignModelRunsBitForBitWhateverWayItIsGiven) {
  const char* kPhototaxis = "--fsm-config --nstates 2 --s0 12 --n0 1 --n0x0 0 --c0x0 15 --p0x0 0.2 --s1 14 --att1 3 --n1 0";
  const char* kTutti =
      "--fsm-config --nstates 2 --s0 20 --rwm0 30 --cle0 4 --n0 1 --n0x0 0 --c0x0 27 --p0x0 0.7 --l0x0 2 "
      "--s1 28 --vel1 1 --cle1 5 --clr1 3 --n1 1 --n1x0 0 --c1x0 25 --p1x0 0.1";
  // Each with the knob of the sensor it exercises: set slightly, that knob changes the run,
  // so the equalities below are not those of a run the knobs never reach.
  const struct {
    const char* mission;
    const char* software;
    double RobotModel::*knob;
  } runs[] = {{"aac", kPhototaxis, &RobotModel::light_deviation},
              {"tutti-aggregation", kTutti, &RobotModel::camera_noise},
              {"lcn", kAttractStop, &RobotModel::rab_noise}};
  for (const auto& run : runs) {
    const Mission mission = load_mission(run.mission);
    const ControlSoftware software = parse_control_software(std::string(run.software));
    Simulation simulation(mission, software);
    RobotModel zeros = mission.robot;
    zeros.rab_noise = zeros.camera_noise = 0.0;
    zeros.wheel_deviation = zeros.proximity_deviation = zeros.light_deviation = zeros.rab_range_deviation = 0.0;
    const std::uint64_t seed = 3;
    const auto own = traced(simulation, seed, nullptr);
    const auto given = traced(simulation, seed, &mission.robot);
    const auto explicit_zeros = traced(simulation, seed, &zeros);
    EXPECT_EQ(own.first, given.first) << run.mission;
    EXPECT_EQ(own.first, explicit_zeros.first) << run.mission;
    EXPECT_TRUE(own.second == given.second) << run.mission << ": the traces differ";
    EXPECT_TRUE(own.second == explicit_zeros.second) << run.mission << ": the traces differ";
    EXPECT_EQ(own.first, evaluate(mission, software, seed)) << run.mission;
    RobotModel slight = zeros;
    slight.*run.knob = 0.01;
    EXPECT_FALSE(own.second == traced(simulation, seed, &slight).second) << run.mission << ": the knob changes nothing";
  }
}

}  // namespace
}  // namespace sd
