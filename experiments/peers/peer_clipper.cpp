// Clipper 6.4 (Debian's libpolyclipping) as a back end of the harness: coordinates scaled by
// a power of two to 64-bit integers, the operation with the even-odd fill rule (the paper's
// nesting-parity regions), the result read from a PolyTree and scaled back.
// [BRIEF §6] (Clipper 6.4)
// Preconditions: see peers.hpp. The scale is the largest power of two that keeps every
// scaled coordinate within 2^53: Clipper's integers are then exactly doubles, so the exact
// checks apply to its output as it is; Clipper's own limit (hiRange, 2^62) would only refine
// the grid below the double resolution of the largest input coordinate.
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "experiments/peers/peers.hpp"

namespace mk::experiments {

namespace {

int scale_exponent(const MultiPolygon& a, const MultiPolygon& b) {
  double max_abs = 0;
  for (const auto* mp : {&a, &b}) {
    for (const OgcPolygon& p : *mp) {
      for (const Point& q : p.shell) max_abs = std::max({max_abs, std::abs(q.x), std::abs(q.y)});
      for (const Ring& h : p.holes) {
        for (const Point& q : h) max_abs = std::max({max_abs, std::abs(q.x), std::abs(q.y)});
      }
    }
  }
  if (max_abs == 0) return 0;
  int e = 0;
  std::frexp(max_abs, &e);  // max_abs < 2^e
  return std::clamp(53 - e, -1000, 1000);  // max_abs * 2^(53 - e) < 2^53
}

ClipperLib::Paths to_paths(const MultiPolygon& mp, int exponent) {
  ClipperLib::Paths paths;
  const auto path = [&](const Ring& r) {
    ClipperLib::Path out;
    for (const Point& p : r) out.emplace_back(std::llround(std::ldexp(p.x, exponent)), std::llround(std::ldexp(p.y, exponent)));
    return out;
  };
  for (const OgcPolygon& p : mp) {
    paths.push_back(path(p.shell));
    for (const Ring& h : p.holes) paths.push_back(path(h));
  }
  return paths;
}

ClipperLib::ClipType clip_type(Operation op) {
  switch (op) {
    case Operation::intersection: return ClipperLib::ctIntersection;
    case Operation::union_: return ClipperLib::ctUnion;
    case Operation::difference: return ClipperLib::ctDifference;
    case Operation::symmetric_difference: return ClipperLib::ctXor;
  }
  return ClipperLib::ctIntersection;
}

Ring from_path(const ClipperLib::Path& p, int exponent) {
  Ring r;
  for (const auto& q : p) {
    r.push_back({std::ldexp(static_cast<double>(q.X), -exponent), std::ldexp(static_cast<double>(q.Y), -exponent)});
  }
  return r;
}

// Outer rings of the tree are shells, their children holes, the holes' children shells again.
void read_tree(const ClipperLib::PolyNode& node, int exponent, PeerOutput& out) {
  for (const ClipperLib::PolyNode* child : node.Childs) {
    OgcPolygon p;
    p.shell = from_path(child->Contour, exponent);
    for (const ClipperLib::PolyNode* hole : child->Childs) {
      p.holes.push_back(from_path(hole->Contour, exponent));
      read_tree(*hole, exponent, out);
    }
    out.polygons.push_back(std::move(p));
  }
}

}  // namespace

PeerOutput clipper_overlay(const MultiPolygon& a, const MultiPolygon& b, Operation op) {
  const int exponent = scale_exponent(a, b);
  ClipperLib::Clipper clipper;
  ClipperLib::PolyTree tree;
  try {
    clipper.AddPaths(to_paths(a, exponent), ClipperLib::ptSubject, true);
    clipper.AddPaths(to_paths(b, exponent), ClipperLib::ptClip, true);
    if (!clipper.Execute(clip_type(op), tree, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd)) {
      throw PeerException("Clipper: Execute returned false");
    }
  } catch (const ClipperLib::clipperException& e) {
    throw PeerException(std::string("Clipper: ") + e.what());
  }
  PeerOutput out;
  out.grid = std::ldexp(1.0, -exponent);
  read_tree(tree, exponent, out);
  return out;
}

std::string clipper_version() { return std::string("Clipper ") + CLIPPER_VERSION; }

}  // namespace mk::experiments
