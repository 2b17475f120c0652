#include "statistics/sign_test.hpp"

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <stdexcept>

namespace sd::statistics {

double sign_test_p_value(int successes, int trials) {
  if (trials < 0 || successes < 0 || successes > trials) throw std::invalid_argument("sign test: 0 <= successes <= trials");
  if (trials == 0) return 1.0;
  const boost::math::binomial b(trials, 0.5);
  const int k = std::min(successes, trials - successes);
  return std::min(1.0, 2.0 * boost::math::cdf(b, k));
}

}  // namespace sd::statistics
