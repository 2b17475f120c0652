#pragma once
// The two-sided sign test: do successes and failures come as often as a fair coin gives them?

namespace sd::statistics {

/// R's binom.test(successes, trials, 0.5)$p.value: twice the smaller tail, capped at 1; 1 when
/// trials is 0. Throws std::invalid_argument unless 0 <= successes <= trials.
double sign_test_p_value(int successes, int trials);

}  // namespace sd::statistics
