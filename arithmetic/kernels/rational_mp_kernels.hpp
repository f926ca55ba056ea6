// The rational kernel over Boost.Multiprecision's rationals: mpq_rational (GMP's mpq_t
// behind Boost's number interface) and cpp_rational (header-only, no GMP). Same formulas,
// same exact results as RationalKernel; only the number type's cost differs. [MK89 §3.3]
// Preconditions: as rational_kernel.hpp.
#pragma once

#include <boost/multiprecision/cpp_int.hpp>
#include <boost/multiprecision/gmp.hpp>

#include <cstdint>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/nearest_double.hpp"

namespace mk {

namespace detail {

// The shared part of Boost's rationals: always reduced, compare() and sign() members, and
// str() in mpq_get_str's form ("p/q" or "p"). Constructing from a double is exact for both
// (mpq_set_d, and cpp_rational's exact binary conversion).
template <class Q>
struct BoostRationalNumber {
  static Q from_double(double v) { return Q(v); }
  static int compare(const Q& a, const Q& b) { return a.compare(b); }
  static int sign(const Q& a) { return a.sign(); }
  static void canonicalize(Q&) {}
  static std::string text(const Q& a) { return a.str(); }
};

// A cpp_int's value as an mpz (for rounding through MPFR): its magnitude's 64-bit words.
inline void to_mpz(const boost::multiprecision::cpp_int& v, mpz_class& out) {
  std::vector<std::uint64_t> words;
  boost::multiprecision::export_bits(v, std::back_inserter(words), 64);  // magnitude, big-endian words
  mpz_import(out.get_mpz_t(), words.size(), 1, sizeof(std::uint64_t), 0, 0, words.data());
  if (v.sign() < 0) out = -out;
}

}  // namespace detail

template <>
struct RationalNumber<boost::multiprecision::mpq_rational>
    : detail::BoostRationalNumber<boost::multiprecision::mpq_rational> {
  static constexpr std::string_view kernel_name = "rational-mp";
  static double nearest(const boost::multiprecision::mpq_rational& a) { return nearest_double(*a.backend().data()); }
};

template <>
struct RationalNumber<boost::multiprecision::cpp_rational>
    : detail::BoostRationalNumber<boost::multiprecision::cpp_rational> {
  static constexpr std::string_view kernel_name = "rational-cpp";
  static double nearest(const boost::multiprecision::cpp_rational& a) {
    mpq_class q;
    detail::to_mpz(boost::multiprecision::numerator(a), q.get_num());
    detail::to_mpz(boost::multiprecision::denominator(a), q.get_den());
    return nearest_double(q);  // already reduced, positive denominator
  }
};

// GMP's rationals through Boost's interface (expression templates over mpq_t).
using RationalMpKernel = BasicRationalKernel<boost::multiprecision::mpq_rational>;
// Boost's header-only rationals (cpp_int numerator and denominator).
using RationalCppKernel = BasicRationalKernel<boost::multiprecision::cpp_rational>;

}  // namespace mk
