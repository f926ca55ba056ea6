// The classroom examples of Kettner, Mehlhorn, Pion, Schirra and Yap: orient2d(p', q, r)
// for p' on a 256 x 256 grid of neighbouring doubles around p, where the naive formula
// gives wrong and inconsistent signs. [KMPSY08 §4] Used by tests, bench/grid_image and
// experiments (generator ulp_perturbation).
// Preconditions: none.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace mk::classroom {

inline constexpr int grid_size = 256;

// orient2d(p + (i ulp_x, j ulp_y), q, r) for 0 <= i, j < grid_size.
struct Grid {
  std::string_view name;
  double px, py, qx, qy, rx, ry;
};

// Three points on the line y = x; p moves off it by up to 255 ulps in each coordinate.
inline constexpr Grid grid_a{"a", 0.5, 0.5, 12.0, 12.0, 24.0, 24.0};
// A nearly collinear triple whose line has no simple slope.
inline constexpr Grid grid_b{"b",
                             0.50000000000002531,
                             0.5000000000000171,
                             17.300000000000001,
                             17.300000000000001,
                             24.00000000000005,
                             24.0000000000000517765};
inline constexpr std::array<Grid, 2> grids{grid_a, grid_b};

// x, then the next grid_size - 1 doubles above it (std::nextafter stepped i times).
inline std::array<double, grid_size> ulp_steps(double x) {
  std::array<double, grid_size> steps{};
  for (std::size_t i = 0; i < steps.size(); ++i) {
    steps[i] = x;
    x = std::nextafter(x, HUGE_VAL);
  }
  return steps;
}

// The three ways a computed sign can differ from the exact one.
enum class SignError : std::uint8_t { none, sign_flipped, zero_reported_nonzero, nonzero_reported_zero };

constexpr SignError classify(int computed, int exact) {
  if (computed == exact) return SignError::none;
  if (exact == 0) return SignError::zero_reported_nonzero;
  if (computed == 0) return SignError::nonzero_reported_zero;
  return SignError::sign_flipped;
}

struct SignErrorCounts {
  std::size_t sign_flipped = 0;
  std::size_t zero_reported_nonzero = 0;
  std::size_t nonzero_reported_zero = 0;

  std::size_t total() const { return sign_flipped + zero_reported_nonzero + nonzero_reported_zero; }
  void add(int computed, int exact) {
    switch (classify(computed, exact)) {
      case SignError::none: break;
      case SignError::sign_flipped: ++sign_flipped; break;
      case SignError::zero_reported_nonzero: ++zero_reported_nonzero; break;
      case SignError::nonzero_reported_zero: ++nonzero_reported_zero; break;
    }
  }
};

// Calls f(i, j, px', py') for every grid point, i along x and j along y.
template <class F>
void for_each_point(const Grid& g, F&& f) {
  const auto xs = ulp_steps(g.px);
  const auto ys = ulp_steps(g.py);
  for (int j = 0; j < grid_size; ++j) {
    for (int i = 0; i < grid_size; ++i) f(i, j, xs[static_cast<std::size_t>(i)], ys[static_cast<std::size_t>(j)]);
  }
}

}  // namespace mk::classroom
