// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Safe decisions of the dynamic programs, which add edge lengths in double precision:
//
// 1. `Length_sum_error_bound`: a forward error bound. A length computed as sqrt(dx*dx + dy*dy) from double
//    coordinates (dx, dy rounded once; |dx| + |dy| for L1, max for Linf) has a relative error below 3u
//    (u = 2^-53) unless dx*dx underflows, where the absolute error is below 2^-536. A sum of at most S such
//    lengths, added in any order (all terms positive), has a relative error below (S + 2) u (1 + 0.01) for
//    S u < 0.01. With gamma = (S + 4) 2^-52, twice that, the exact sums a*, b* of computed sums a <= b
//    satisfy a* < b* whenever b - a > gamma (a + b) + S 2^-500 (the last term covers underflow; it and the
//    rounding of the test itself are far below the factor 2 of slack). Such a decision is the exact one;
//    otherwise it is ambiguous and goes to 2.
// 2. `compare_length_sums`: the exact sign of sum(A) - sum(B) for two lists of segments (double endpoints,
//    taken as exact rationals). Common segments cancel; for L1/Linf the sums are rational (GMP). For L2, an
//    interval evaluation at 128 and 256 bits straight from the doubles (MPFR, directed rounding) decides
//    non-zero differences; otherwise the squared lengths become exact rationals, equal radicands are merged
//    and the sign of sum c_i sqrt(r_i) is sought at 128 to 4,096 bits. When it is still unknown, the
//    radicands are grouped into classes whose ratios are rational squares (sqrt(r_i) = q sqrt(r_c), q
//    rational): square roots of distinct square-free integers are linearly independent over Q, so the sum
//    is zero exactly when every class coefficient is zero; a non-zero sum is refined until its sign is known.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_EXACT_LENGTH_SUM_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_EXACT_LENGTH_SUM_2_H

#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>
#include <CGAL/Gmpq.h>

#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

/// Forward error bound of sums of at most `terms` computed lengths (see the file comment).
class Length_sum_error_bound
{
public:
  explicit Length_sum_error_bound(std::size_t terms)
    : gamma_((double(terms) + 4) * 2.220446049250313e-16), absolute_(double(terms) * 3.054936363499605e-151) {}

  /// Whether the exact value of the sum computed as `a` is certainly smaller than that of `b`.
  bool certainly_less(double a, double b) const { return b - a > gamma_ * (a + b) + absolute_; }

private:
  double gamma_, absolute_;
};

/// A segment with double endpoints (x0, y0, x1, y1).
typedef std::array<double, 4> Length_segment;

namespace exact_sum_detail {

inline Length_segment normalized(const Length_segment& s)
{
  if(std::make_pair(s[0], s[1]) <= std::make_pair(s[2], s[3])) return s;
  return Length_segment{{s[2], s[3], s[0], s[1]}};
}

inline int qsign(const CGAL::Gmpq& q) { return mpq_sgn(q.mpq()); }

// c * sqrt(r), c and r rationals, r > 0
struct Term
{
  CGAL::Gmpq c, r;
};

// [lo, hi] enclosure of sum c_i sqrt(r_i) at `bits` of precision; returns -1, +1, or 0 (unknown)
inline int mpfr_sign(const std::vector<Term>& t, long bits)
{
  mpfr_t lo, hi, s, a;
  mpfr_inits2(bits, lo, hi, s, a, (mpfr_ptr)nullptr);
  mpfr_set_zero(lo, 1);
  mpfr_set_zero(hi, 1);
  for(const Term& x : t) {
    const bool pos = qsign(x.c) > 0;
    // lower end of c sqrt(r): sqrt(r) rounded down if c > 0, up if c < 0
    mpfr_set_q(s, x.r.mpq(), pos ? MPFR_RNDD : MPFR_RNDU);
    mpfr_sqrt(s, s, pos ? MPFR_RNDD : MPFR_RNDU);
    mpfr_mul_q(a, s, x.c.mpq(), MPFR_RNDD);
    mpfr_add(lo, lo, a, MPFR_RNDD);
    mpfr_set_q(s, x.r.mpq(), pos ? MPFR_RNDU : MPFR_RNDD);
    mpfr_sqrt(s, s, pos ? MPFR_RNDU : MPFR_RNDD);
    mpfr_mul_q(a, s, x.c.mpq(), MPFR_RNDU);
    mpfr_add(hi, hi, a, MPFR_RNDU);
  }
  const int r = mpfr_sgn(lo) > 0 ? 1 : (mpfr_sgn(hi) < 0 ? -1 : 0);
  mpfr_clears(lo, hi, s, a, (mpfr_ptr)nullptr);
  return r;
}

// [lo, hi] enclosure of sum_i s_i |segment_i| (s_i = +-1) at `bits` of precision, straight from the doubles
// (directed rounding everywhere); returns -1, +1, or 0 (unknown)
inline int mpfr_sign_from_doubles(const std::vector<std::pair<Length_segment, int>>& d, long bits)
{
  mpfr_t lo, hi, a, b, q, r;
  mpfr_inits2(bits, lo, hi, a, b, q, r, (mpfr_ptr)nullptr);
  mpfr_set_zero(lo, 1);
  mpfr_set_zero(hi, 1);
  for(const auto& x : d) {
    const Length_segment& g = x.first;
    // enclosure [q, r] of dx^2 + dy^2: |dx| = max - min of the two doubles, rounded down and up
    mpfr_set_zero(q, 1);
    mpfr_set_zero(r, 1);
    for(int c = 0; c < 2; ++c) {
      const double u = (std::max)(g[c], g[c + 2]), v = (std::min)(g[c], g[c + 2]);
      mpfr_set_d(a, u, MPFR_RNDN);   // exact: bits >= 53
      mpfr_sub_d(a, a, v, MPFR_RNDD);
      mpfr_sqr(a, a, MPFR_RNDD);
      mpfr_add(q, q, a, MPFR_RNDD);
      mpfr_set_d(b, u, MPFR_RNDN);
      mpfr_sub_d(b, b, v, MPFR_RNDU);
      mpfr_sqr(b, b, MPFR_RNDU);
      mpfr_add(r, r, b, MPFR_RNDU);
    }
    mpfr_sqrt(q, q, MPFR_RNDD);
    mpfr_sqrt(r, r, MPFR_RNDU);
    if(x.second > 0) { mpfr_add(lo, lo, q, MPFR_RNDD); mpfr_add(hi, hi, r, MPFR_RNDU); }
    else { mpfr_sub(lo, lo, r, MPFR_RNDD); mpfr_sub(hi, hi, q, MPFR_RNDU); }
  }
  const int res = mpfr_sgn(lo) > 0 ? 1 : (mpfr_sgn(hi) < 0 ? -1 : 0);
  mpfr_clears(lo, hi, a, b, q, r, (mpfr_ptr)nullptr);
  return res;
}

// whether the rational q is the square of a rational; then *root = sqrt(q)
inline bool rational_square_root(const CGAL::Gmpq& q, CGAL::Gmpq* root)
{
  if(qsign(q) < 0) return false;
  const mpq_srcptr m = q.mpq();
  if(!mpz_perfect_square_p(mpq_numref(m)) || !mpz_perfect_square_p(mpq_denref(m))) return false;
  mpz_t a, b;
  mpz_inits(a, b, (mpz_ptr)nullptr);
  mpz_sqrt(a, mpq_numref(m));
  mpz_sqrt(b, mpq_denref(m));
  mpq_t r;
  mpq_init(r);
  mpq_set_num(r, a);
  mpq_set_den(r, b);
  mpq_canonicalize(r);
  *root = CGAL::Gmpq(r);
  mpq_clear(r);
  mpz_clears(a, b, (mpz_ptr)nullptr);
  return true;
}

} // namespace exact_sum_detail

/// Exact sign (-1, 0, +1) of the total length of `A` minus that of `B` in `metric`, the endpoints' doubles
/// taken as exact rationals.
inline int compare_length_sums(std::vector<Length_segment> A, std::vector<Length_segment> B, Edge_metric metric = Edge_metric::L2)
{
  using namespace exact_sum_detail;
  for(auto& s : A) s = normalized(s);
  for(auto& s : B) s = normalized(s);
  std::sort(A.begin(), A.end());
  std::sort(B.begin(), B.end());
  // segments of A \ B (+1) and of B \ A (-1), as multisets
  std::vector<Length_segment> aa, bb;
  std::set_difference(A.begin(), A.end(), B.begin(), B.end(), std::back_inserter(aa));
  std::set_difference(B.begin(), B.end(), A.begin(), A.end(), std::back_inserter(bb));
  std::vector<std::pair<Length_segment, int>> d;
  for(const auto& s : aa) d.emplace_back(s, 1);
  for(const auto& s : bb) d.emplace_back(s, -1);
  if(d.empty()) return 0;
  if(metric != Edge_metric::L2) {
    CGAL::Gmpq sum(0);
    for(const auto& x : d) {
      const CGAL::Gmpq dx = CGAL::abs(CGAL::Gmpq(x.first[2]) - CGAL::Gmpq(x.first[0]));
      const CGAL::Gmpq dy = CGAL::abs(CGAL::Gmpq(x.first[3]) - CGAL::Gmpq(x.first[1]));
      const CGAL::Gmpq l = metric == Edge_metric::L1 ? dx + dy : (dx < dy ? dy : dx);
      if(x.second > 0) sum += l;
      else sum -= l;
    }
    return qsign(sum);
  }
  // non-zero differences are usually decided at 128 or 256 bits straight from the doubles
  for(long bits = 128; bits <= 256; bits *= 2)
    if(const int r = mpfr_sign_from_doubles(d, bits)) return r;
  // squared lengths as exact rationals, equal radicands merged
  std::vector<Term> t;
  t.reserve(d.size());
  for(const auto& x : d) {
    const CGAL::Gmpq dx = CGAL::Gmpq(x.first[2]) - CGAL::Gmpq(x.first[0]);
    const CGAL::Gmpq dy = CGAL::Gmpq(x.first[3]) - CGAL::Gmpq(x.first[1]);
    t.push_back(Term{CGAL::Gmpq(x.second), dx * dx + dy * dy});
  }
  std::sort(t.begin(), t.end(), [](const Term& a, const Term& b) { return a.r < b.r; });
  std::vector<Term> m;
  for(const Term& x : t) {
    if(!m.empty() && m.back().r == x.r) m.back().c += x.c;
    else m.push_back(x);
  }
  m.erase(std::remove_if(m.begin(), m.end(), [](const Term& x) { return qsign(x.c) == 0; }), m.end());
  if(m.empty()) return 0;
  for(long bits = 128; bits <= 4096; bits *= 2)
    if(const int r = mpfr_sign(m, bits)) return r;
  // classes of radicands with rational-square ratios: sqrt(r) = q sqrt(r_c)
  std::vector<Term> cls;
  for(const Term& x : m) {
    bool merged = false;
    for(Term& c : cls) {
      CGAL::Gmpq root;
      if(rational_square_root(x.r * c.r, &root)) {   // sqrt(x.r) = sqrt(x.r c.r) / c.r * sqrt(c.r)
        c.c += x.c * root / c.r;
        merged = true;
        break;
      }
    }
    if(!merged) cls.push_back(x);
  }
  cls.erase(std::remove_if(cls.begin(), cls.end(), [](const Term& x) { return qsign(x.c) == 0; }), cls.end());
  if(cls.empty()) return 0;
  for(long bits = 8192; bits <= (1L << 24); bits *= 2)
    if(const int r = mpfr_sign(cls, bits)) return r;
  throw std::runtime_error("compare_length_sums: precision limit reached (internal error)");
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_EXACT_LENGTH_SUM_2_H
