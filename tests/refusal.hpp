#pragma once
// What a reader says when it refuses an input: the message of the `Error` it throws, or
// "(accepted)" when it throws nothing, so that a test can compare the one-line error exactly.
// Any other exception escapes and fails the test.
#include <string>

namespace sd::test {

template <class Error, class Read>
std::string refusal_of(Read&& read) {
  try {
    (void)read();
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace sd::test
