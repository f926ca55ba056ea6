// WKT writer for multipolygons and Boolean results (with dangling edges and isolated
// points as LINESTRINGs and POINTs). [OGC06-103 §7] [OGC06-103 §6.1.11]
// Preconditions: finite coordinates; the result is bounded (checked, throws otherwise).
// Large outputs are formatted on several threads, byte for byte as on one.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "io/collection.hpp"
#include "io/ring_rules.hpp"
#include "io/text_util.hpp"
#include "io/wkt.hpp"

namespace mk {

namespace {

// Asks the kernel to back a large text's buffer with huge pages where it does so on request
// (Linux's transparent huge pages in "madvise" mode): writing 35 MB faulted in 4 KiB pages
// one by one took about a fifth of writing blob 1e6. Only a hint: nothing changes if refused.
void advise_huge_pages(std::string& text) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t{1} << 21;
  if (text.capacity() < 4 * huge) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(text.data()) + huge - 1) & ~(huge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(text.data()) + text.capacity()) & ~(huge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)text;
#endif
}

// "x y" at `at` (room for 2 kMaxDoubleText + 1 characters); returns its end.
char* put_point(char* at, const Point& p) {
  at = io_detail::put_double(at, p.x);
  *at++ = ' ';
  return io_detail::put_double(at, p.y);
}

void append_point(std::string& out, const Point& p) {
  char buf[2 * io_detail::kMaxDoubleText + 1];
  out.append(buf, put_point(buf, p));
}

// ", x y" at most (the separator, two doubles and a space).
constexpr std::size_t kMaxPointText = 2 + 2 * io_detail::kMaxDoubleText + 1;

// The text as a list of pieces: literal text, or a run of one closed ring's points (visits
// [from, to) of its n + 1 visits, the first vertex repeated at the end), each point but the
// ring's first after ", ". Runs are formatted apart, on several threads for a large output,
// then joined in order: the same bytes on any number of threads.
class WktText {
 public:
  explicit WktText(unsigned threads) : threads_(resolve_threads(threads)) {}

  void literal(std::string_view s) {
    start_literal();
    literals_ += s;
    pieces_.back().to = literals_.size();
  }
  void point(const Point& p) {
    start_literal();
    append_point(literals_, p);
    pieces_.back().to = literals_.size();
  }
  // A closed ring in the requested direction. The direction is decided exactly, so a
  // needle-thin shell is never written clockwise.
  void ring(const Ring& ring, bool counterclockwise) {
    literal("(");
    if (!ring.empty()) {
      const int orientation = io_detail::ring_orientation(ring);
      const bool reverse = orientation != 0 && (orientation > 0) != counterclockwise;
      const std::size_t visits = ring.size() + 1;
      for (std::size_t from = 0; from < visits; from += kRun) {
        pieces_.push_back({&ring, reverse, from, std::min(visits, from + kRun)});
      }
    }
    literal(")");
  }

  std::string str() {
    std::size_t points = 0;
    for (const Piece& p : pieces_) points += p.ring ? p.to - p.from : 0;
    const std::size_t literal_bytes = literals_.size();
    std::string out;
    // Room for the longest text (a point is at most two 24-byte doubles, a space and ", "),
    // and the final newline the command adds: never a reallocation (append_run makes room
    // for a run's longest text, which fits), and the pages never written are never touched.
    out.reserve(literal_bytes + points * kMaxPointText + 1);
    advise_huge_pages(out);
    if (points < kParallelPoints || threads_ <= 1) {
      for (const Piece& p : pieces_) append(out, p, literals_);
      return out;
    }
    // Groups of consecutive pieces of about kRun points (a literal counts as one), formatted
    // a wave of groups at a time on the threads into buffers reused two waves later (fresh
    // pages cost more than formatting into them); one task of each wave appends the previous
    // wave's buffers to the text, in order, while the others format.
    std::vector<std::size_t> group_end;
    for (std::size_t i = 0, weight = 0; i < pieces_.size(); ++i) {
      weight += pieces_[i].ring ? pieces_[i].to - pieces_[i].from : 1;
      if (weight >= kRun || i + 1 == pieces_.size()) {
        group_end.push_back(i + 1);
        weight = 0;
      }
    }
    const std::size_t wave = 4 * static_cast<std::size_t>(threads_);
    std::array<std::vector<std::string>, 2> buffers{std::vector<std::string>(wave), std::vector<std::string>(wave)};
    std::size_t pending = 0;  // buffers of the previous wave not yet appended
    const auto append_previous = [&](std::size_t w) {
      for (std::size_t j = 0; j < pending; ++j) out += buffers[(w + 1) % 2][j];
    };
    std::size_t w = 0;
    for (std::size_t first = 0; first < group_end.size(); first += wave, ++w) {
      const std::size_t count = std::min(wave, group_end.size() - first);
      std::vector<std::string>& mine = buffers[w % 2];
      run_tasks(threads_, count + 1, [&](std::size_t task) {
        if (task == 0) {
          append_previous(w);
          return;
        }
        const std::size_t j = task - 1, g = first + j;
        // A local string: mine[j] and mine[j + 1] share a cache line, and appending to both
        // from two threads made each append wait for the other thread's.
        std::string buffer = std::move(mine[j]);
        buffer.clear();
        for (std::size_t i = g == 0 ? 0 : group_end[g - 1]; i < group_end[g]; ++i) {
          append(buffer, pieces_[i], literals_);
        }
        mine[j] = std::move(buffer);
      });
      pending = count;
    }
    append_previous(w);
    return out;
  }

 private:
  // A run of a ring's visits [from, to), or (ring null) the literal text literals_[from, to):
  // all literal text in one string, not a string per piece (star 1e4's 60,737 rings made
  // as many small strings, copied again each time the list of pieces grew).
  struct Piece {
    const Ring* ring = nullptr;
    bool reverse = false;
    std::size_t from = 0, to = 0;
  };
  void start_literal() {
    if (pieces_.empty() || pieces_.back().ring) pieces_.push_back({nullptr, false, literals_.size(), literals_.size()});
  }
  static constexpr std::size_t kRun = 1 << 14;
  static constexpr std::size_t kParallelPoints = 1 << 16;

  // The run's points written straight into room made for the longest text, then cut to
  // what was written: one size change per run instead of two appends per double (the
  // appends' copies were a fifth of writing star 1e4's 60,737 small rings).
  static void append_run(std::string& out, const Piece& p) {
    const Ring& ring = *p.ring;
    const std::size_t n = ring.size();
    const std::size_t old = out.size();
    out.resize(old + (p.to - p.from) * kMaxPointText);
    char* at = out.data() + old;
    for (std::size_t i = p.from; i < p.to; ++i) {
      const std::size_t k = i % n;
      if (i > 0) {
        *at++ = ',';
        *at++ = ' ';
      }
      at = put_point(at, ring[p.reverse ? (n - k) % n : k]);
    }
    out.resize(static_cast<std::size_t>(at - out.data()));
  }
  static void append(std::string& out, const Piece& p, const std::string& literals) {
    if (p.ring) {
      append_run(out, p);
    } else {
      out.append(literals, p.from, p.to - p.from);
    }
  }

  unsigned threads_;
  std::vector<Piece> pieces_;
  std::string literals_;
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
