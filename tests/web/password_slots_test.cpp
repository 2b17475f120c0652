// The server's bound on password checks at once (web/password_slots.hpp): however many sign-ins
// arrive together, no more than the slots hash at once (64 MiB of Argon2id each), and every one
// gets its turn.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "web/password_slots.hpp"

namespace sd::test {
namespace {

TEST(PasswordSlots, SixteenAtOnceHoldNoMoreThanTheSlotsAndAllGetTheirTurn) {
  web::PasswordSlots slots(4);
  std::atomic<int> inside{0}, most{0}, done{0};
  std::vector<std::thread> sign_ins;
  for (int i = 0; i < 16; ++i)
    sign_ins.emplace_back([&] {
      const web::PasswordSlots::Held held = slots.take();
      const int now = ++inside;
      for (int seen = most.load(); now > seen && !most.compare_exchange_weak(seen, now);) {
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a check's work, held
      --inside;
      ++done;
    });
  for (auto& t : sign_ins) t.join();
  EXPECT_EQ(done.load(), 16);
  EXPECT_LE(most.load(), 4);
  EXPECT_LE(slots.peak(), 4);
  EXPECT_GE(slots.peak(), 1);
}

TEST(PasswordSlots, ASlotIsGivenBackWhenTheCheckThrows) {
  web::PasswordSlots slots(1);
  try {
    const web::PasswordSlots::Held held = slots.take();
    throw std::runtime_error("wrong user name or password");
  } catch (const std::runtime_error&) {
  }
  const web::PasswordSlots::Held again = slots.take();  // would wait for ever if it were kept
  EXPECT_EQ(slots.peak(), 1);
}

}  // namespace
}  // namespace sd::test
