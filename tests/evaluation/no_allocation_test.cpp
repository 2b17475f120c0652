// A tick never touches the heap (issue: "no heap allocation inside the tick loop"): every
// buffer of a run is sized when the Simulation is built. Checked by counting calls to the
// global operator new, which this executable replaces, while a run steps from reset to its
// last tick, for every mission of the catalogue and control software of every flavour and
// both architectures.
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>
#include <set>
#include <string>
#include <vector>

#include "control/config_string.hpp"
#include "core/rng.hpp"
#include "design/design_space.hpp"
#include "design/sampling.hpp"
#include "evaluation/simulation.hpp"
#include "missions/catalogue.hpp"

namespace {
// Only the test's own thread counts, and only inside a CountingAllocations scope.
thread_local bool counting = false;
thread_local long allocations = 0;

void* allocate(std::size_t size, std::size_t alignment) {
  if (counting) ++allocations;
  if (size == 0) size = 1;
  void* p = alignment > alignof(std::max_align_t) ? std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment)
                                                  : std::malloc(size);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

class CountingAllocations {
 public:
  CountingAllocations() {
    allocations = 0;
    counting = true;
  }
  ~CountingAllocations() { counting = false; }
  long count() const { return allocations; }
};
}  // namespace

void* operator new(std::size_t size) { return allocate(size, alignof(std::max_align_t)); }
void* operator new[](std::size_t size) { return allocate(size, alignof(std::max_align_t)); }
void* operator new(std::size_t size, std::align_val_t a) { return allocate(size, static_cast<std::size_t>(a)); }
void* operator new[](std::size_t size, std::align_val_t a) { return allocate(size, static_cast<std::size_t>(a)); }
// The nothrow forms too: a library that does not route them through the forms above (ASan's
// runtime does not) would otherwise hand std::free memory its own operator new made.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size, alignof(std::max_align_t));
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void* operator new(std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  try {
    return allocate(size, static_cast<std::size_t>(a));
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t& tag) noexcept { return operator new(size, a, tag); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace sd {
namespace {

TEST(NoAllocation, TheCounterSeesAnAllocation) {
  std::vector<int> v;
  CountingAllocations scope;
  v.push_back(1);
  EXPECT_EQ(scope.count(), 1);
}

/// Control software of every flavour and architecture: uniform samples of the whole design
/// space, a Chocolate FSM and a Maple tree written out, and an EvoStick network.
std::vector<std::string> control_software_lines() {
  const design::ParameterSpace space = design::build_design_space(design::resolve_design_space({}));
  Rng rng(7);
  std::vector<std::string> lines = {
      "--fsm-config --nstates 2 --s0 14 --att0 5 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1.0 --s1 11 --n1 1 --n1x0 0 --c1x0 11 "
      "--p1x0 0.1",
      "--bt-config --nroot 3 --nchildroot 2 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 1 --n01 5 --a01 44 --att01 5 "
      "--p01 0 --n1 0 --nchild1 2 --n10 6 --c10 41 --p10 0.1 --n11 5 --a11 41 --p11 0"};
  for (int k = 0; k < 12; ++k) lines.push_back(space.render(design::sample_uniform(space, rng)));
  std::string network = "--nn-config";
  for (int o = 0; o < 2; ++o)
    for (int i = 0; i < 25; ++i) network += " --w" + std::to_string(o) + "x" + std::to_string(i) + " " + std::to_string((i % 5 - 2) * (o + 1));
  lines.push_back(network);
  return lines;
}

TEST(NoAllocation, NoTickOfAnyMissionAllocates) {
  const std::vector<std::string> lines = control_software_lines();
  std::vector<ControlSoftware> software;
  for (const std::string& line : lines) software.push_back(parse_control_software(line));
  std::set<Architecture> architectures;
  for (const ControlSoftware& s : software) architectures.insert(s.architecture);
  ASSERT_EQ(architectures.size(), 3u);

  const std::vector<MissionSummary> missions = list_missions();
  ASSERT_GE(missions.size(), 5u);
  for (std::size_t m = 0; m < missions.size(); ++m) {
    const Mission mission = load_mission(missions[m].name);
    // Two pieces of control software per mission, taking turns, so every one meets a few
    // missions and the suite stays short.
    for (std::size_t k = 0; k < 2; ++k) {
      const std::size_t index = (2 * m + k) % software.size();
      Simulation simulation(mission, software[index]);
      simulation.use_neighbour_grid(k == 1);  // both ways of finding pairs, whatever the swarm's size
      for (std::uint64_t seed = 1; seed <= 2; ++seed) {  // the second run reuses the buffers
        long ticks = 0;
        CountingAllocations scope;
        simulation.reset(seed);
        while (!simulation.finished()) {
          simulation.step();
          ++ticks;
        }
        const long count = scope.count();
        EXPECT_EQ(ticks, mission.ticks);
        EXPECT_EQ(count, 0) << missions[m].name << ", seed " << seed << (k == 1 ? ", neighbour grid" : "") << ": " << lines[index];
      }
    }
  }
}

TEST(NoAllocation, DemiurgesArlequinMachineryDoesNotAllocate) {
  // Set 6's A03: four states of modules 50-55, so the grey samples, the ground-input filter
  // and the buffer emptied on entry all run.
  const ControlSoftware software = parse_control_software(
      "--fsm-config --nstates 4 --s0 54 --n0 4 --n0x0 2 --c0x0 53 --p0x0 2 --w0x0 4.8 --n0x1 2 --c0x1 50 --p0x1 0.11 "
      "--n0x2 0 --c0x2 50 --p0x2 0.81 --n0x3 2 --c0x3 53 --p0x3 2 --w0x3 13.59 --s1 51 --n1 4 --n1x0 1 --c1x0 52 --p1x0 "
      "0.98 --n1x1 1 --c1x1 53 --p1x1 1 --w1x1 19.99 --n1x2 2 --c1x2 55 --p1x2 0.08 --n1x3 1 --c1x3 50 --p1x3 0.56 --s2 52 "
      "--n2 3 --n2x0 1 --c2x0 51 --p2x0 0.88 --n2x1 2 --c2x1 55 --p2x1 0.58 --n2x2 0 --c2x2 55 --p2x2 0.37 --s3 53 --n3 4 "
      "--n3x0 0 --c3x0 55 --p3x0 0.87 --n3x1 1 --c3x1 54 --p3x1 1 --w3x1 16.05 --n3x2 2 --c3x2 53 --p3x2 2 --w3x2 7.96 "
      "--n3x3 2 --c3x3 52 --p3x3 0.84");
  const Mission mission = with_arlequin_modules(load_mission("aac"), "demiurge");
  Simulation simulation(mission, software);
  CountingAllocations scope;
  simulation.reset(1);
  while (!simulation.finished()) simulation.step();
  EXPECT_EQ(scope.count(), 0);
}

}  // namespace
}  // namespace sd
