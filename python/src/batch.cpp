// Many operations in one call: the pairs run in C++ threads with the GIL released, each
// thread taking the next pair, and the results come back in the order of the pairs.
// [MK89 §3.2] (one polygonoperation per pair)
// Preconditions: mk::compute is safe to run concurrently on different inputs: it keeps no
// shared mutable state (predicate counters and crossing-rounding counts are thread_local,
// MPFR's exponent range is per thread when MPFR is built thread-safe, the rounding-mode
// guard changes the calling thread's floating-point environment only). Without a
// thread-safe MPFR the pairs run in the calling thread, one after the other.
#include <mpfr.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <new>
#include <thread>
#include <vector>

#include "module.hpp"

namespace mk::python {

namespace {

// The error of one pair, kept as the kind and message the exception translator would give.
struct PairError {
  std::string kind;  // "InvalidInput", "KernelFailure", "UsageError", "MemoryError", "Error"
  std::string message;
};

PairError error_of(const std::exception_ptr& p) {
  try {
    std::rethrow_exception(p);
  } catch (const InvalidInput& e) {
    return {"InvalidInput", e.what()};
  } catch (const KernelFailure& e) {
    return {"KernelFailure", kernel_failure_message(e)};
  } catch (const std::invalid_argument& e) {
    return {"UsageError", e.what()};
  } catch (const std::bad_alloc&) {
    return {"MemoryError", "out of memory"};
  } catch (const std::exception& e) {
    return {"Error", e.what()};
  } catch (...) {
    return {"Error", "unknown error"};
  }
}

int thread_count(int asked, std::size_t pairs) {
  if (mpfr_buildopt_tls_p() == 0) return 1;
  int n = asked > 0 ? asked : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(n), std::max<std::size_t>(pairs, 1)));
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def(
      "compute_many",
      [](const std::string& op, const std::vector<InputPolygon>& as, const std::vector<InputPolygon>& bs,
         const std::string& kernel, bool regular, bool area_exact, bool exact, int threads, const std::string& fill_rule,
         const std::string& grid, const std::string& rounding) {
        if (as.size() != bs.size() && as.size() != 1 && bs.size() != 1) {
          throw std::invalid_argument("the sequences of A and B have different lengths (" + std::to_string(as.size()) +
                                      " and " + std::to_string(bs.size()) + "); give equal lengths or one polygon");
        }
        Request request{operation_named(op), {}, {}};
        request.name = std::string(operation_name(request.op));
        request.options = make_options(request.op, kernel, regular, area_exact, exact, fill_rule, grid, rounding);
        // No pair when either side is an empty sequence (one polygon is broadcast only
        // against a sequence that has pairs to make).
        const std::size_t n = as.empty() || bs.empty() ? 0 : std::max(as.size(), bs.size());
        const auto a_at = [&](std::size_t i) -> const InputPolygon& { return as.size() == 1 ? as[0] : as[i]; };
        const auto b_at = [&](std::size_t i) -> const InputPolygon& { return bs.size() == 1 ? bs[0] : bs[i]; };
        std::vector<std::optional<BooleanOutput>> outputs(n);
        std::vector<std::exception_ptr> errors(n);
        const int workers = thread_count(threads, n);
        {
          py::gil_scoped_release release;
          std::atomic<std::size_t> next{0};
          const auto work = [&] {
            for (std::size_t i = next++; i < n; i = next++) {
              try {
                outputs[i] = compute_inputs(a_at(i), b_at(i), request.options);
              } catch (...) {
                errors[i] = std::current_exception();
              }
            }
          };
          std::vector<std::thread> pool;
          for (int t = 1; t < workers; ++t) pool.emplace_back(work);
          work();
          for (auto& t : pool) t.join();
        }
        py::list out;
        for (std::size_t i = 0; i < n; ++i) {
          if (outputs[i]) {
            out.append(py::cast(Result(a_at(i), b_at(i), request, std::move(*outputs[i]))));
          } else {
            const PairError e = error_of(errors[i]);
            out.append(py::make_tuple(e.kind, e.message));
          }
        }
        return out;
      },
      py::arg("op"), py::arg("a"), py::arg("b"), py::arg("kernel") = "", py::arg("regular") = true,
      py::arg("area_exact") = false, py::arg("exact") = false, py::arg("threads") = 0, py::arg("fill_rule") = "",
      py::arg("grid") = "", py::arg("rounding") = "certified");
}

}  // namespace mk::python
