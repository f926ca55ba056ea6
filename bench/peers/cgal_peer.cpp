// Overlay benchmark adapter for CGAL's Boolean_set_operations_2: Polygon_set_2 over
// Exact_predicates_exact_constructions_kernel (Epeck), exact constructions.
// [BRIEF §6] (CGAL 5.5 Epeck anchor)
// Preconditions: as peers.hpp. The parts of one input have disjoint interiors (they may
// share vertices), as Polygon_set_2::insert of a range requires.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/version.h>
#include <pthread.h>

#include <exception>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/peers/peers.hpp"

namespace mk::bench {

namespace {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<Epeck>;
using CgalPolygonWithHoles = CGAL::Polygon_with_holes_2<Epeck>;
using CgalPolygonSet = CGAL::Polygon_set_2<Epeck>;

// CGAL recurses deeply (the arrangement's sweep and the lazy-number DAGs of long sums), and
// at n = 1e6 overflows the default 8 MiB stack. Every run therefore happens in a thread
// with a 1 GiB stack (reserved address space; only the pages touched are committed). The
// thread costs tens of microseconds, small beside the operation even at n = 100.
constexpr std::size_t big_stack_bytes = std::size_t{1} << 30;

template <class F>
void run_on_big_stack(F& f) {
  struct Job {
    F* f;
    std::exception_ptr error;
  } job{&f, nullptr};
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, big_stack_bytes);
  pthread_t thread;
  const int rc = pthread_create(
      &thread, &attr,
      [](void* p) -> void* {
        auto* j = static_cast<Job*>(p);
        try {
          (*j->f)();
        } catch (...) {
          j->error = std::current_exception();
        }
        return nullptr;
      },
      &job);
  pthread_attr_destroy(&attr);
  if (rc != 0) throw std::runtime_error("CGAL: cannot start a thread with a 1 GiB stack");
  pthread_join(thread, nullptr);
  if (job.error) std::rethrow_exception(job.error);
}

CgalPolygon to_cgal(const Ring& r) {
  CgalPolygon p;
  for (const Point& q : r) p.push_back(Epeck::Point_2(q.x, q.y));
  return p;
}

std::vector<CgalPolygonWithHoles> to_cgal(const MultiPolygon& mp) {
  std::vector<CgalPolygonWithHoles> out;
  for (const OgcPolygon& p : mp) {
    std::vector<CgalPolygon> holes;
    for (const Ring& h : p.holes) holes.push_back(to_cgal(h));
    out.emplace_back(to_cgal(p.shell), holes.begin(), holes.end());
  }
  return out;
}

// Twice the signed area of a ring from its coordinates rounded to doubles: exact sums over
// lazy numbers would build a DAG as deep as the ring, and the peers' areas are all
// double-precision shoelaces too.
double twice_signed_area(const CgalPolygon& p) {
  double twice = 0;
  for (auto e = p.edges_begin(); e != p.edges_end(); ++e) {
    const double x0 = CGAL::to_double(e->source().x()), y0 = CGAL::to_double(e->source().y());
    const double x1 = CGAL::to_double(e->target().x()), y1 = CGAL::to_double(e->target().y());
    twice += x0 * y1 - x1 * y0;
  }
  return twice;
}

}  // namespace

template <>
struct PeerOverlay<CgalEpeck>::Impl {
  std::vector<CgalPolygonWithHoles> a, b;
};

template <>
PeerOverlay<CgalEpeck>::PeerOverlay(const MultiPolygon& a, const MultiPolygon& b)
    : impl_(std::make_unique<Impl>(Impl{to_cgal(a), to_cgal(b)})) {}

template <>
PeerOverlay<CgalEpeck>::~PeerOverlay() = default;

template <>
OverlayResult PeerOverlay<CgalEpeck>::run(Operation op) const {
  OverlayResult out;
  auto work = [&] {
    CgalPolygonSet s, t;
    s.insert(impl_->a.begin(), impl_->a.end());
    t.insert(impl_->b.begin(), impl_->b.end());
    switch (op) {
      case Operation::intersection: s.intersection(t); break;
      case Operation::union_: s.join(t); break;
      case Operation::difference: s.difference(t); break;
      case Operation::symmetric_difference: s.symmetric_difference(t); break;
    }
    std::vector<CgalPolygonWithHoles> result;
    s.polygons_with_holes(std::back_inserter(result));
    double twice = 0;
    for (const auto& p : result) {
      // Outer boundaries run counterclockwise and holes clockwise: signed areas add up.
      twice += twice_signed_area(p.outer_boundary());
      out.vertices += p.outer_boundary().size();
      for (auto h = p.holes_begin(); h != p.holes_end(); ++h) {
        twice += twice_signed_area(*h);
        out.vertices += h->size();
      }
    }
    out.area = twice / 2;
  };
  run_on_big_stack(work);
  return out;
}

template <>
std::string PeerOverlay<CgalEpeck>::version() {
  // CGAL_VERSION_NR is 1MMmmbiiii: major, minor, bug-fix release.
  constexpr long nr = CGAL_VERSION_NR;
  return std::to_string(nr / 10000000 % 100) + "." + std::to_string(nr / 100000 % 100) + "." + std::to_string(nr / 10000 % 10);
}

template class PeerOverlay<CgalEpeck>;

}  // namespace mk::bench
