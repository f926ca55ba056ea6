// The winding-number oracle (see winding.hpp). [BRIEF §1, extended by issue 13]
// Preconditions: see winding.hpp.
#include "tests/oracle/winding.hpp"

namespace mk::oracle {

namespace {

// Sign of (b - a) x (q - a).
int side(const QPoint& a, const QPoint& b, const QPoint& q) {
  return sgn((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x));
}

}  // namespace

// A ray from q towards +x: an edge crossing q's horizontal line upwards with q on its left
// adds one, downwards with q on its right subtracts one (half-open in y, so a vertex on the
// line counts once).
int winding_number(const std::vector<QRing>& rings, const QPoint& q) {
  int w = 0;
  for (const QRing& ring : rings) {
    const std::size_t n = ring.size();
    if (n < 2) continue;
    for (std::size_t i = 0; i < n; ++i) {
      const QPoint& a = ring[i];
      const QPoint& b = ring[(i + 1) % n];
      if (a.y <= q.y) {
        if (b.y > q.y && side(a, b, q) > 0) ++w;
      } else if (b.y <= q.y && side(a, b, q) < 0) {
        --w;
      }
    }
  }
  return w;
}

bool is_on_any_ring(const std::vector<QRing>& rings, const QPoint& q) {
  for (const QRing& ring : rings) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (is_on_segment(ring[i], ring[(i + 1) % n], q)) return true;
    }
  }
  return false;
}

bool rule_accepts(Rule rule, int w) {
  switch (rule) {
    case Rule::evenodd: return w % 2 != 0;
    case Rule::nonzero: return w != 0;
    case Rule::positive: return w > 0;
    case Rule::negative: return w < 0;
  }
  return false;
}

const char* rule_name(Rule rule) {
  switch (rule) {
    case Rule::evenodd: return "evenodd";
    case Rule::nonzero: return "nonzero";
    case Rule::positive: return "positive";
    case Rule::negative: return "negative";
  }
  return "?";
}

}  // namespace mk::oracle
