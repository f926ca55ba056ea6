// WKT writer for multipolygons and Boolean results (with dangling edges and isolated
// points as LINESTRINGs and POINTs). [OGC06-103 §7] [OGC06-103 §6.1.11]
// Preconditions: finite coordinates; the result is bounded (checked, throws otherwise).
// Large outputs are formatted on several threads, byte for byte as on one.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "io/collection.hpp"
#include "io/ring_rules.hpp"
#include "io/text_util.hpp"
#include "io/wkt.hpp"

namespace mk {

namespace {

using io_detail::append_double;

void append_point(std::string& out, const Point& p) {
  append_double(out, p.x);
  out.push_back(' ');
  append_double(out, p.y);
}

// The text as a list of pieces: literal text, or a run of one closed ring's points (visits
// [from, to) of its n + 1 visits, the first vertex repeated at the end), each point but the
// ring's first after ", ". Runs are formatted apart, on several threads for a large output,
// then joined in order: the same bytes on any number of threads.
class WktText {
 public:
  explicit WktText(unsigned threads) : threads_(resolve_threads(threads)) {}

  void literal(std::string_view s) {
    if (pieces_.empty() || pieces_.back().ring) pieces_.push_back({});
    pieces_.back().text += s;
  }
  void point(const Point& p) {
    if (pieces_.empty() || pieces_.back().ring) pieces_.push_back({});
    append_point(pieces_.back().text, p);
  }
  // A closed ring in the requested direction. The direction is decided exactly, so a
  // needle-thin shell is never written clockwise.
  void ring(const Ring& ring, bool counterclockwise) {
    literal("(");
    if (!ring.empty()) {
      const int orientation = io_detail::ring_orientation(ring);
      const bool reverse = orientation != 0 && (orientation > 0) != counterclockwise;
      const std::size_t visits = ring.size() + 1;
      for (std::size_t from = 0; from < visits; from += kRun) pieces_.push_back({{}, &ring, reverse, from, std::min(visits, from + kRun)});
    }
    literal(")");
  }

  std::string str() {
    std::size_t points = 0;
    for (const Piece& p : pieces_) points += p.ring ? p.to - p.from : 0;
    const unsigned threads = points >= kParallelPoints ? threads_ : 1;
    if (threads > 1) run_tasks(threads, pieces_.size(), [&](std::size_t i) { format(pieces_[i]); });
    std::string out;
    if (threads > 1) {
      std::size_t size = 0;
      for (const Piece& p : pieces_) size += p.text.size();
      out.reserve(size + 1);  // and the final newline the command adds
    } else {
      out.reserve(points * 40);  // two shortest doubles and ", " take up to 45 bytes, often 38
    }
    for (Piece& p : pieces_) {
      if (threads > 1 || !p.ring) {
        out += p.text;
      } else {
        append_run(out, p);
      }
    }
    return out;
  }

 private:
  struct Piece {
    std::string text;
    const Ring* ring = nullptr;
    bool reverse = false;
    std::size_t from = 0, to = 0;
  };
  static constexpr std::size_t kRun = 1 << 14;
  static constexpr std::size_t kParallelPoints = 1 << 16;

  static void append_run(std::string& out, const Piece& p) {
    const Ring& ring = *p.ring;
    const std::size_t n = ring.size();
    for (std::size_t i = p.from; i < p.to; ++i) {
      const std::size_t k = i % n;
      if (i > 0) out += ", ";
      append_point(out, ring[p.reverse ? (n - k) % n : k]);
    }
  }
  static void format(Piece& p) {
    if (!p.ring) return;
    p.text.reserve((p.to - p.from) * 40);
    append_run(p.text, p);
  }

  unsigned threads_;
  std::vector<Piece> pieces_;
};

void append_polygon_text(WktText& out, const OgcPolygon& polygon) {
  out.literal("(");
  out.ring(polygon.shell, true);
  for (const Ring& hole : polygon.holes) {
    out.literal(", ");
    out.ring(hole, false);
  }
  out.literal(")");
}

// POLYGON, MULTIPOLYGON or nothing (for an empty multipolygon inside a collection).
void append_polygons(WktText& out, const MultiPolygon& polygons) {
  if (polygons.size() == 1) {
    out.literal("POLYGON ");
    append_polygon_text(out, polygons.front());
    return;
  }
  out.literal("MULTIPOLYGON (");
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (i > 0) out.literal(", ");
    append_polygon_text(out, polygons[i]);
  }
  out.literal(")");
}

}  // namespace

std::string write_wkt(const MultiPolygon& polygons, unsigned threads) {
  if (polygons.empty()) return "POLYGON EMPTY";
  WktText out(threads);
  append_polygons(out, polygons);
  return out.str();
}

std::string write_wkt(const Output& output, unsigned threads) {
  if (output.unbounded) {
    throw InvalidInput(
        "the result is unbounded (hole type) and cannot be written as WKT; use --format json");
  }
  if (output.dangling_edges.empty() && output.isolated_points.empty()) {
    return write_wkt(output.polygons, threads);
  }
  WktText out(threads);
  out.literal("GEOMETRYCOLLECTION (");
  io_detail::for_each_member(
      output, [&] { out.literal(", "); }, [&](const MultiPolygon& polygons) { append_polygons(out, polygons); },
      [&](const Point& a, const Point& b) {
        out.literal("LINESTRING (");
        out.point(a);
        out.literal(", ");
        out.point(b);
        out.literal(")");
      },
      [&](const Point& p) {
        out.literal("POINT (");
        out.point(p);
        out.literal(")");
      });
  out.literal(")");
  return out.str();
}

}  // namespace mk
