#pragma once
// How many password checks this server runs at once. Each Argon2id check takes 64 MiB for its
// ~0.1 s of one core (storage/passwords.hpp): unbounded, N sign-ins sent at once cost N x 64 MiB
// before the first failure is even counted (bench/load_bench: 20 tabs signing in took the server
// past 600 MiB). Bounded, the others wait their turn, which on a machine of a few cores is hardly
// slower: the checks compete for the same cores either way.
#include <condition_variable>
#include <mutex>

namespace sd::web {

class PasswordSlots {
 public:
  explicit PasswordSlots(int slots) : free_(slots) {}

  /// A slot, held until destroyed.
  class Held {
   public:
    explicit Held(PasswordSlots& slots) : slots_(slots) {}
    ~Held() { slots_.release(); }
    Held(const Held&) = delete;
    Held& operator=(const Held&) = delete;

   private:
    PasswordSlots& slots_;
  };

  /// Waits for a free slot.
  [[nodiscard]] Held take();
  /// The most slots held at once so far.
  int peak() const;

 private:
  void release();

  mutable std::mutex mutex_;
  std::condition_variable freed_;
  int free_;
  int held_ = 0, peak_ = 0;
};

}  // namespace sd::web
