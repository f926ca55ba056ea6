// Overlay benchmark adapter for Clipper 6.4 (libpolyclipping): integer coordinates.
// [BRIEF §6] (Clipper 6.4 anchor)
// Preconditions: as peers.hpp. Coordinates are scaled by a power of two and rounded to
// 64-bit integers outside the timed region; areas are scaled back.
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bench/peers/peers.hpp"

namespace mk::bench {

namespace {

// The largest power of two that keeps every scaled coordinate within Clipper's loRange
// (2^30 - 1): inside it Clipper multiplies in 64 bits, beyond it in 128 bits, which is
// slower. At coordinates near 100 this keeps about 23 bits of fraction, enough to keep
// neighbouring blob vertices at n = 1e6 (0.0006 apart) distinct. A power of two makes the
// scaling itself exact; only the rounding to integers loses information.
double choose_scale(const MultiPolygon& a, const MultiPolygon& b) {
  double max_abs = 1;
  for (const auto* mp : {&a, &b}) {
    for (const OgcPolygon& p : *mp) {
      for (const Point& q : p.shell) max_abs = std::max({max_abs, std::abs(q.x), std::abs(q.y)});
      for (const Ring& h : p.holes) {
        for (const Point& q : h) max_abs = std::max({max_abs, std::abs(q.x), std::abs(q.y)});
      }
    }
  }
  return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(static_cast<double>(ClipperLib::loRange) / max_abs))));
}

ClipperLib::Path to_path(const Ring& r, double scale) {
  ClipperLib::Path path;
  path.reserve(r.size());
  for (const Point& p : r) path.emplace_back(std::llround(p.x * scale), std::llround(p.y * scale));
  return path;
}

ClipperLib::Paths to_paths(const MultiPolygon& mp, double scale) {
  ClipperLib::Paths paths;
  for (const OgcPolygon& p : mp) {
    paths.push_back(to_path(p.shell, scale));
    for (const Ring& h : p.holes) paths.push_back(to_path(h, scale));
  }
  return paths;
}

// Both inputs, scaled and rounded once, outside the timed region (both Clipper runners).
struct ClipperInputs {
  double scale;
  ClipperLib::Paths a, b;
};

ClipperInputs clipper_inputs(const MultiPolygon& a, const MultiPolygon& b) {
  const double scale = choose_scale(a, b);
  return {scale, to_paths(a, scale), to_paths(b, scale)};
}

ClipperLib::ClipType clip_type(Operation op) {
  switch (op) {
    case Operation::intersection: return ClipperLib::ctIntersection;
    case Operation::union_: return ClipperLib::ctUnion;
    case Operation::difference: return ClipperLib::ctDifference;
    case Operation::symmetric_difference: return ClipperLib::ctXor;
  }
  throw std::invalid_argument("unknown operation");
}

}  // namespace

template <>
struct PeerOverlay<Clipper>::Impl : ClipperInputs {};

template <>
PeerOverlay<Clipper>::PeerOverlay(const MultiPolygon& a, const MultiPolygon& b)
    : impl_(std::make_unique<Impl>(Impl{clipper_inputs(a, b)})) {}

template <>
PeerOverlay<Clipper>::~PeerOverlay() = default;

template <>
OverlayResult PeerOverlay<Clipper>::run(Operation op) const {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(impl_->a, ClipperLib::ptSubject, true);
  clipper.AddPaths(impl_->b, ClipperLib::ptClip, true);
  ClipperLib::Paths solution;
  // Shells run counterclockwise and holes clockwise, so non-zero winding is the region.
  if (!clipper.Execute(clip_type(op), solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero)) {
    throw std::runtime_error("Clipper: Execute failed");
  }
  OverlayResult out;
  // Output outer rings and holes have opposite orientations: their signed areas add up.
  for (const auto& path : solution) {
    out.area += ClipperLib::Area(path);
    out.vertices += path.size();
  }
  out.area /= impl_->scale * impl_->scale;
  return out;
}

template <>
std::string PeerOverlay<Clipper>::version() {
  return CLIPPER_VERSION;
}

template class PeerOverlay<Clipper>;

// The same operation with its result as a PolyTree: Clipper then assigns every hole to its
// outer ring, as GEOS and Boost.Geometry return polygons with their holes.
template <>
struct PeerOverlay<ClipperPolyTree>::Impl : ClipperInputs {};

template <>
PeerOverlay<ClipperPolyTree>::PeerOverlay(const MultiPolygon& a, const MultiPolygon& b)
    : impl_(std::make_unique<Impl>(Impl{clipper_inputs(a, b)})) {}

template <>
PeerOverlay<ClipperPolyTree>::~PeerOverlay() = default;

template <>
OverlayResult PeerOverlay<ClipperPolyTree>::run(Operation op) const {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(impl_->a, ClipperLib::ptSubject, true);
  clipper.AddPaths(impl_->b, ClipperLib::ptClip, true);
  ClipperLib::PolyTree tree;
  if (!clipper.Execute(clip_type(op), tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero)) {
    throw std::runtime_error("Clipper: Execute failed");
  }
  OverlayResult out;
  for (const ClipperLib::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
    out.area += ClipperLib::Area(node->Contour);  // holes run opposite to their outer rings
    out.vertices += node->Contour.size();
  }
  out.area /= impl_->scale * impl_->scale;
  return out;
}

template <>
std::string PeerOverlay<ClipperPolyTree>::version() {
  return CLIPPER_VERSION;
}

template class PeerOverlay<ClipperPolyTree>;

}  // namespace mk::bench
