#pragma once
// Whether this test (and so the swarmdesign binary of its tree) is built under a sanitizer.
// Work sized to last a while in Release lasts about ten times longer there: the design tests'
// missions are shorter there (workflow/design_helpers.hpp), and a test that needs a design
// still running can ask for fewer runs and still check that it was.

namespace sd::test {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

}  // namespace sd::test
