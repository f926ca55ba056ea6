// WKT writer for multipolygons and Boolean results (with dangling edges and isolated
// points as LINESTRINGs and POINTs). [OGC06-103 §7] [OGC06-103 §6.1.11]
// Preconditions: finite coordinates; the result is bounded (checked, throws otherwise).
// The text is planned as items (literals, runs of small polygons, runs of a large ring's
// points, non-regular parts) cut into chunks of about kChunkPoints points, formatted on
// several threads for a large output and joined in order: the same bytes on any number.
#include <algorithm>
#include <charconv>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "io/chunked_text.hpp"
#include "io/ring_rules.hpp"
#include "io/wkt.hpp"

namespace mk {

namespace {

// The longest shortest round-trip text of a double: "-2.2250738585072014e-308".
constexpr std::size_t kShortestDoubleMaxChars = 24;
// The bytes past a coordinate's start that writing it may touch (std::to_chars: its text).
constexpr std::size_t kShortestDoubleRoom = kShortestDoubleMaxChars;

// Shortest round-trip text of v at `out` (room for kShortestDoubleMaxChars bytes).
char* write_shortest(char* out, double v) { return std::to_chars(out, out + kShortestDoubleMaxChars, v).ptr; }

// Most bytes a point's text takes, with the ", " before it. A chunk's bound adds
// kShortestDoubleRoom: writing a coordinate may touch that far past its start.
constexpr std::size_t kVisitRoom = 2 + 2 * kShortestDoubleMaxChars + 1;
constexpr std::size_t kChunkPoints = 4096;      // about 160 kB of text: formatted in cache
constexpr std::size_t kParallelPoints = 1 << 16;  // below, one thread

// "-0" is written "0": the same coordinate, and "-0" only puzzles readers.
char* write_coordinate(char* out, double v) { return write_shortest(out, v == 0 ? 0.0 : v); }

char* write_point(char* out, const Point& p) {
  out = write_coordinate(out, p.x);
  *out++ = ' ';
  return write_coordinate(out, p.y);
}

char* write_literal(char* out, std::string_view s) {
  std::memcpy(out, s.data(), s.size());
  return out + s.size();
}

char* write_separator(char* out) {
  out[0] = ',';
  out[1] = ' ';
  return out + 2;
}

// The ring's direction, decided exactly, so that a needle-thin shell is never written clockwise.
bool is_reversed(const Ring& ring, bool counterclockwise, unsigned threads = 1) {
  const int orientation = io_detail::ring_orientation(ring, threads);
  return orientation != 0 && (orientation > 0) != counterclockwise;
}

// Visits [from, to) of the closed ring's n + 1 (its first vertex again at the end), each
// after ", " but the ring's first.
char* write_visits(char* out, const Ring& ring, bool reverse, std::size_t from, std::size_t to) {
  const std::size_t n = ring.size();
  for (std::size_t i = from; i < to; ++i) {
    if (i > 0) out = write_separator(out);
    const std::size_t k = i % n;
    out = write_point(out, ring[reverse ? (n - k) % n : k]);
  }
  return out;
}

char* write_ring(char* out, const Ring& ring, bool counterclockwise) {
  *out++ = '(';
  if (!ring.empty()) out = write_visits(out, ring, is_reversed(ring, counterclockwise), 0, ring.size() + 1);
  *out++ = ')';
  return out;
}

char* write_polygon(char* out, const OgcPolygon& polygon) {
  *out++ = '(';
  out = write_ring(out, polygon.shell, true);
  for (const Ring& hole : polygon.holes) {
    out = write_separator(out);
    out = write_ring(out, hole, false);
  }
  *out++ = ')';
  return out;
}

std::size_t ring_bound(const Ring& ring) { return (ring.size() + 1) * kVisitRoom + 2; }

std::size_t polygon_bound(const OgcPolygon& polygon) {
  std::size_t bound = 4 + ring_bound(polygon.shell);
  for (const Ring& hole : polygon.holes) bound += 2 + ring_bound(hole);
  return bound;
}

std::size_t polygon_points(const OgcPolygon& polygon) {
  std::size_t points = polygon.shell.size() + 1;
  for (const Ring& hole : polygon.holes) points += hole.size() + 1;
  return points;
}

// The text as items in order, and where the chunks start.
class WktPlan {
 public:
  WktPlan(const MultiPolygon* polygons, const Output* output, unsigned threads)
      : polygons_(polygons), output_(output), threads_(resolve_threads(threads)) {}

  void literal(std::string_view s) { add({Kind::literal, s}, 0, s.size()); }

  // POLYGON, MULTIPOLYGON or nothing (for an empty multipolygon inside a collection).
  void polygons() {
    const MultiPolygon& mp = *polygons_;
    if (mp.size() == 1) {
      literal("POLYGON ");
      polygon(0, false);
      return;
    }
    literal("MULTIPOLYGON (");
    for (std::size_t i = 0; i < mp.size(); ++i) polygon(i, i > 0);
    literal(")");
  }

  // Each after ", " but the first when nothing comes before it in the collection.
  void dangling_edges(bool after_others) {
    for (std::size_t i = 0; i < output_->dangling_edges.size(); ++i) {
      range(Kind::dangling_edges, i, i > 0 || after_others, 2, 16 + 2 * kVisitRoom);
    }
  }
  void isolated_points(bool after_others) {
    for (std::size_t i = 0; i < output_->isolated_points.size(); ++i) {
      range(Kind::isolated_points, i, i > 0 || after_others, 1, 10 + kVisitRoom);
    }
  }

  std::string str() {
    if (chunk_items_ > 0 || starts_.empty()) cut();
    const unsigned t = points_ >= kParallelPoints ? threads_ : 1;
    return io_detail::join_chunks(
        bounds_.size(), t, [&](std::size_t c) { return bounds_[c]; },
        [&](std::size_t c, char* out) {
          for (std::size_t i = starts_[c]; i < starts_[c + 1]; ++i) out = write(out, items_[i]);
          return out;
        });
  }

 private:
  enum class Kind : unsigned char { literal, polygons, ring_run, dangling_edges, isolated_points };
  struct Item {
    Kind kind;
    std::string_view literal;
    std::size_t first = 0, last = 0;  // polygons, edges, points: [first, last); ring_run: visits
    bool separated = false;           // ranges: ", " before the first one too
    bool reverse = false;             // ring_run
    const Ring* ring = nullptr;       // ring_run
  };

  void polygon(std::size_t i, bool separated) {
    const OgcPolygon& p = (*polygons_)[i];
    if (polygon_points(p) <= kChunkPoints) {
      range(Kind::polygons, i, separated, polygon_points(p), 2 + polygon_bound(p));
      return;
    }
    literal(separated ? ", (" : "(");
    ring_runs(p.shell, true);
    for (const Ring& hole : p.holes) {
      literal(", ");
      ring_runs(hole, false);
    }
    literal(")");
  }

  // A large ring in runs of kChunkPoints visits.
  void ring_runs(const Ring& ring, bool counterclockwise) {
    literal("(");
    const bool reverse = !ring.empty() && is_reversed(ring, counterclockwise, threads_);
    const std::size_t visits = ring.empty() ? 0 : ring.size() + 1;
    for (std::size_t from = 0; from < visits; from += kChunkPoints) {
      const std::size_t to = std::min(visits, from + kChunkPoints);
      Item item{Kind::ring_run, {}, from, to};
      item.reverse = reverse;
      item.ring = &ring;
      add(item, to - from, (to - from) * kVisitRoom);
    }
    literal(")");
  }

  // Element i of a kind written by ranges: joins the chunk's last item when it is the range
  // just before.
  void range(Kind kind, std::size_t i, bool separated, std::size_t points, std::size_t bound) {
    if (chunk_items_ > 0 && items_.back().kind == kind && items_.back().last == i) {
      ++items_.back().last;
      account(points, bound);
      return;
    }
    Item item{kind, {}, i, i + 1};
    item.separated = separated;
    add(item, points, bound);
  }

  void add(const Item& item, std::size_t points, std::size_t bound) {
    items_.push_back(item);
    ++chunk_items_;
    account(points, bound);
  }

  void account(std::size_t points, std::size_t bound) {
    chunk_points_ += points;
    chunk_bound_ += bound;
    points_ += points;
    if (chunk_points_ >= kChunkPoints) cut();
  }

  // Ends the current chunk.
  void cut() {
    if (starts_.empty()) starts_.push_back(0);
    starts_.push_back(items_.size());
    bounds_.push_back(chunk_bound_ + kShortestDoubleRoom);
    chunk_points_ = chunk_bound_ = chunk_items_ = 0;
  }

  char* write(char* out, const Item& item) const {
    switch (item.kind) {
      case Kind::literal: return write_literal(out, item.literal);
      case Kind::polygons:
        for (std::size_t i = item.first; i < item.last; ++i) {
          if (i > item.first || item.separated) out = write_separator(out);
          out = write_polygon(out, (*polygons_)[i]);
        }
        return out;
      case Kind::ring_run: return write_visits(out, *item.ring, item.reverse, item.first, item.last);
      case Kind::dangling_edges:
        for (std::size_t i = item.first; i < item.last; ++i) {
          out = write_literal(out, i > item.first || item.separated ? ", LINESTRING (" : "LINESTRING (");
          out = write_point(out, output_->dangling_edges[i].first);
          out = write_separator(out);
          out = write_point(out, output_->dangling_edges[i].second);
          *out++ = ')';
        }
        return out;
      case Kind::isolated_points:
        for (std::size_t i = item.first; i < item.last; ++i) {
          out = write_literal(out, i > item.first || item.separated ? ", POINT (" : "POINT (");
          out = write_point(out, output_->isolated_points[i]);
          *out++ = ')';
        }
        return out;
    }
    return out;
  }

  const MultiPolygon* polygons_;
  const Output* output_;
  unsigned threads_;
  std::vector<Item> items_;
  std::vector<std::size_t> starts_;  // the chunks' first items, and the end
  std::vector<std::size_t> bounds_;  // the chunks' most bytes
  std::size_t chunk_points_ = 0, chunk_bound_ = 0, chunk_items_ = 0, points_ = 0;
};

}  // namespace

std::string write_wkt(const MultiPolygon& polygons, unsigned threads) {
  if (polygons.empty()) return "POLYGON EMPTY";
  WktPlan plan(&polygons, nullptr, threads);
  plan.polygons();
  return plan.str();
}

std::string write_wkt(const Output& output, unsigned threads) {
  if (output.unbounded) {
    throw InvalidInput(
        "the result is unbounded (hole type) and cannot be written as WKT; use --format json");
  }
  if (output.dangling_edges.empty() && output.isolated_points.empty()) {
    return write_wkt(output.polygons, threads);
  }
  WktPlan plan(&output.polygons, &output, threads);
  plan.literal("GEOMETRYCOLLECTION (");
  if (!output.polygons.empty()) plan.polygons();
  plan.dangling_edges(!output.polygons.empty());
  plan.isolated_points(!output.polygons.empty() || !output.dangling_edges.empty());
  plan.literal(")");
  return plan.str();
}

}  // namespace mk
