// SVG pictures of a failing run: A, B and the exact result beside A, B and the kernel's
// result, and, when they differ at a scale too small to see, a zoomed panel around the
// first difference. [MK89 §3.3] (the rounded output can differ by an ulp)
// Preconditions: finite coordinates.
#pragma once

#include <optional>
#include <string>

#include "core/output.hpp"
#include "core/polygon.hpp"

namespace mk::experiments {

// A square window of the plane: centre and half-width.
struct Window {
  Point centre;
  double half_width = 0;
};

// A window around the first vertex where the kernel's rounded output and the exact
// result's differ, small enough to show the difference; empty when they have the same
// vertices or the difference is visible at full scale.
std::optional<Window> difference_window(const Output& exact, const Output& kernel);

// The picture: two panels (exact, kernel), plus a zoom panel when difference_window finds
// one. Without kernel output (error, crash, timeout) the right panel shows A and B only.
std::string failure_picture(const Polygon& a, const Polygon& b, const Output& exact, const std::string& exact_title,
                            const std::optional<Output>& kernel, const std::string& kernel_title);

}  // namespace mk::experiments
