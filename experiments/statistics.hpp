// Rates with 95% Wilson score intervals, for every rate the report prints. [Wil27]
// (E. B. Wilson, "Probable inference, the law of succession, and statistical inference",
// JASA 22, 1927: the interval stays inside [0, 1] and is honest at 0 of n, unlike p ± 1.96 se)
// Preconditions: k <= n.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace mk::experiments {

// The 95% Wilson score interval (z = 1.96) of a proportion of k in n; (0, 1) when n is 0.
inline std::pair<double, double> wilson_interval(std::size_t k, std::size_t n) {
  if (n == 0) return {0.0, 1.0};
  constexpr double z = 1.959963984540054;
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(k) / nn;
  const double denom = 1 + z * z / nn;
  const double centre = (p + z * z / (2 * nn)) / denom;
  const double half = z * std::sqrt(p * (1 - p) / nn + z * z / (4 * nn * nn)) / denom;
  // At k = 0 and k = n the bound is exactly 0 or 1 (rounding would put it a hair off).
  return {k == 0 ? 0.0 : std::max(0.0, centre - half), k == n ? 1.0 : std::min(1.0, centre + half)};
}

}  // namespace mk::experiments

#include <cstdio>
#include <string>

namespace mk::experiments {

// A percentage with as many digits as it needs: 12%, 3.4%, 0.052%, 99.94%.
inline std::string percent(double fraction) {
  const double pct = 100 * fraction;
  char buf[32];
  if (pct > 99.5 && pct < 100) std::snprintf(buf, sizeof buf, "%.2f%%", pct);  // 99.94%, not 100%
  else if (pct == 0 || pct >= 10) std::snprintf(buf, sizeof buf, "%.0f%%", pct);
  else if (pct >= 0.1) std::snprintf(buf, sizeof buf, "%.1f%%", pct);
  else std::snprintf(buf, sizeof buf, "%.2g%%", pct);
  return buf;
}

// "3.4% (17) [2.1–5.3%]": the rate, the count, the 95% Wilson interval; "0 [0–0.35%]" for none.
inline std::string rate_with_interval(std::size_t k, std::size_t n) {
  const auto [lo, hi] = wilson_interval(k, n);
  const std::string interval = " [" + (lo == 0 ? std::string("0") : percent(lo)) + "–" + percent(hi) + "]";
  if (k == 0) return "0" + interval;
  return percent(static_cast<double>(k) / static_cast<double>(n)) + " (" + std::to_string(k) + ")" + interval;
}

// "96% [95%–97%] of 4544": a share of n without its count, for tables whose cells say what
// they count; 100% and 0% keep their interval too.
inline std::string share_with_interval(std::size_t k, std::size_t n) {
  const auto [lo, hi] = wilson_interval(k, n);
  return percent(static_cast<double>(k) / static_cast<double>(n)) + " [" + (lo == 0 ? std::string("0") : percent(lo)) +
         "–" + percent(hi) + "] of " + std::to_string(n);
}

// The median of the values (the mean of the middle two for an even count); NaN when empty.
inline double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : (v[m - 1] + v[m]) / 2;
}

}  // namespace mk::experiments
