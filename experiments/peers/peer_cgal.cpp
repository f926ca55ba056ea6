// CGAL as a back end of the harness: Polygon_set_2 over Exact_predicates_exact_constructions_kernel
// (Boolean_set_operations_2, exact constructions), with its exact result as rationals.
// Inputs with an OGC form of simple rings go in as users give them (Polygon_with_holes_2
// joined into a set); any other polygon of the paper's model (rings touching themselves,
// hole-type polygons) is built as the symmetric difference of its rings' simple loops,
// complemented for a hole. [BRIEF §6] (CGAL 5.5 Epeck) [MK89 §2.2] (nesting-parity regions)
// Preconditions: see peers.hpp. CGAL's preconditions are compiled out in Release builds:
// an input outside its domain may crash or hang, which the harness records.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/version.h>
#include <pthread.h>

#include <exception>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

#include "experiments/ogc.hpp"
#include "experiments/peers/peers.hpp"

namespace mk::experiments {

namespace {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<Epeck>;
using CgalPolygonWithHoles = CGAL::Polygon_with_holes_2<Epeck>;
using CgalSet = CGAL::Polygon_set_2<Epeck>;

template <class T>
mpq_class to_mpq(const T& v) {
  const auto& e = CGAL::exact(v);
  using E = std::decay_t<decltype(e)>;
  if constexpr (std::is_same_v<E, mpq_class>) {
    return e;
  } else {
    return mpq_class(e.mpq());  // CGAL::Gmpq
  }
}

CgalPolygon to_cgal(const Ring& r, bool counterclockwise) {
  CgalPolygon p;
  for (const Point& q : r) p.push_back(Epeck::Point_2(q.x, q.y));
  if (p.size() >= 3 && p.is_simple() && (p.orientation() == CGAL::COUNTERCLOCKWISE) != counterclockwise) {
    p.reverse_orientation();
  }
  return p;
}

bool all_simple(const MultiPolygon& mp) {
  for (const OgcPolygon& p : mp) {
    if (p.shell.size() < 3 || !to_cgal(p.shell, true).is_simple()) return false;
    for (const Ring& h : p.holes) {
      if (h.size() < 3 || !to_cgal(h, false).is_simple()) return false;
    }
  }
  return true;
}

// A ring split into loops at its repeated vertices (each loop visits a vertex once): the
// parity region of the ring is the symmetric difference of its loops' regions.
std::vector<Ring> loops(const Ring& r) {
  std::vector<Ring> out;
  Ring stack;
  for (std::size_t i = 0; i <= r.size(); ++i) {
    const Point& p = r[i % r.size()];
    std::size_t k = 0;
    while (k < stack.size() && !(stack[k] == p)) ++k;
    if (k < stack.size()) {
      out.emplace_back(stack.begin() + static_cast<std::ptrdiff_t>(k), stack.end());
      stack.resize(k);
    }
    if (i < r.size()) stack.push_back(p);
  }
  return out;
}

CgalSet to_set(const PeerInput& in) {
  CgalSet s;
  if (in.ogc != nullptr && in.polygon->type == PolygonType::island && all_simple(*in.ogc)) {
    for (const OgcPolygon& p : *in.ogc) {
      std::vector<CgalPolygon> holes;
      for (const Ring& h : p.holes) holes.push_back(to_cgal(h, false));
      s.join(CgalPolygonWithHoles(to_cgal(p.shell, true), holes.begin(), holes.end()));
    }
    return s;
  }
  for (const Ring& r : in.polygon->rings) {
    if (r.size() < 3) continue;  // points and two-sided rings bound no area
    // A vertex inside the ring's own edge becomes a vertex of that edge, so the loops
    // between repeated vertices are simple.
    for (const Ring& loop : loops(vertex_complete({r}).front())) {
      if (loop.size() < 3) continue;
      const CgalPolygon p = to_cgal(loop, true);
      if (!p.is_simple()) {
        // Outside Polygon_set_2's precondition (checked here: Release builds compile CGAL's checks out).
        throw PeerUnsupported("CGAL: a ring is not simple (Polygon_set_2 requires simple polygons)");
      }
      s.symmetric_difference(p);
    }
  }
  if (in.polygon->type == PolygonType::hole) s.complement();
  return s;
}

Ring rounded(const CgalPolygon& p) {
  Ring r;
  for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) r.push_back({CGAL::to_double(v->x()), CGAL::to_double(v->y())});
  return r;
}

std::vector<RationalPoint> exact_ring(const CgalPolygon& p) {
  std::vector<RationalPoint> r;
  for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) r.push_back({to_mpq(v->x()), to_mpq(v->y())});
  return r;
}

PeerOutput compute(const PeerInput& a, const PeerInput& b, Operation op) {
  CgalSet s = to_set(a);
  const CgalSet t = to_set(b);
  switch (op) {
    case Operation::intersection: s.intersection(t); break;
    case Operation::union_: s.join(t); break;
    case Operation::difference: s.difference(t); break;
    case Operation::symmetric_difference: s.symmetric_difference(t); break;
  }
  PeerOutput out;
  out.is_exact = true;
  std::vector<CgalPolygonWithHoles> result;
  s.polygons_with_holes(std::back_inserter(result));
  for (const auto& p : result) out.unbounded = out.unbounded || p.is_unbounded();
  if (out.unbounded) {
    // Reported through the complement, which is bounded.
    s.complement();
    result.clear();
    s.polygons_with_holes(std::back_inserter(result));
  }
  for (const auto& p : result) {
    OgcPolygon q;
    std::vector<std::vector<RationalPoint>> e;
    q.shell = rounded(p.outer_boundary());
    e.push_back(exact_ring(p.outer_boundary()));
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) {
      q.holes.push_back(rounded(*h));
      e.push_back(exact_ring(*h));
    }
    out.polygons.push_back(std::move(q));
    out.exact_rings.push_back(std::move(e));
  }
  return out;
}

// CGAL recurses deeply (the sweep, lazy-number DAGs) and overflows the default 8 MiB stack
// on large inputs: the operation runs in a thread with a 1 GiB stack (address space only).
PeerOutput on_big_stack(const PeerInput& a, const PeerInput& b, Operation op) {
  struct Job {
    const PeerInput* a;
    const PeerInput* b;
    Operation op;
    PeerOutput out;
    std::exception_ptr error;
  } job{&a, &b, op, {}, nullptr};
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, std::size_t{1} << 30);
  pthread_t thread;
  const int rc = pthread_create(
      &thread, &attr,
      [](void* p) -> void* {
        auto* j = static_cast<Job*>(p);
        try {
          j->out = compute(*j->a, *j->b, j->op);
        } catch (...) {
          j->error = std::current_exception();
        }
        return nullptr;
      },
      &job);
  pthread_attr_destroy(&attr);
  if (rc != 0) return compute(a, b, op);
  pthread_join(thread, nullptr);
  if (job.error) std::rethrow_exception(job.error);
  return std::move(job.out);
}

}  // namespace

PeerOutput cgal_overlay(const PeerInput& a, const PeerInput& b, Operation op) {
  try {
    return on_big_stack(a, b, op);
  } catch (const CGAL::Failure_exception& e) {
    throw PeerException(std::string("CGAL: ") + e.what());
  }
}

std::string cgal_version() {
  constexpr long nr = CGAL_VERSION_NR;  // 1MMmmbiiii
  return "CGAL " + std::to_string(nr / 10000000 % 100) + "." + std::to_string(nr / 100000 % 100) + "." +
         std::to_string(nr / 10000 % 10);
}

}  // namespace mk::experiments
