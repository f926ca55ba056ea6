// SVG pictures of a failing run: A, B and the exact result beside A, B and the kernel's
// result, and, when they differ at a scale too small to see, a zoomed panel around the
// first difference; the same two panels and zoom show a result rounded to the nearest
// doubles beside its snap rounding. [MK89 §3.3] (the rounded output can differ by an ulp)
// [Ho99] (snap rounding onto a grid)
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

// What the zoom panel calls the two outputs (left panel's, right panel's), the least
// half-width of its window, the spacing of a grid whose points it marks (0: none; a power
// of two, so that its points are doubles), and whether to zoom even where the difference
// would show at the outputs' own scale (the panels are scaled to A and B as well).
struct ZoomOptions {
  std::string left_name = "exact result";
  std::string right_name = "kernel result";
  double min_half_width = 0;
  double grid = 0;
  bool always = false;
};

// A window around the first vertex where the kernel's rounded output and the exact
// result's differ, small enough to show the difference but at least min_half_width wide
// on each side; empty when they have the same vertices or (unless `always`) the difference
// is visible at full scale.
std::optional<Window> difference_window(const Output& exact, const Output& kernel, const ZoomOptions& options = {});

// The picture: two panels (exact, kernel), plus a zoom panel when difference_window finds
// one. Without kernel output (error, crash, timeout) the right panel shows A and B only.
std::string failure_picture(const Polygon& a, const Polygon& b, const Output& exact, const std::string& exact_title,
                            const std::optional<Output>& kernel, const std::string& kernel_title,
                            const ZoomOptions& zoom = {});

}  // namespace mk::experiments
