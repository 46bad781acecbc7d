// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact sorting of the intersection points along one line of Line_arrangement_2 (phases 2 and 3 of the
// construction): a filtered key sorts almost everything, exact arithmetic only resolves overlapping keys.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_SORTING_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_SORTING_H

#include <CGAL/Variational_minimization/internal/line_arrangement_predicates.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// A point along a line: enclosing interval of its parameter, the other line, and an auxiliary index.
struct Point_along_line
{
  double lo, hi;
  std::uint32_t other;
  std::uint32_t aux;
};

// Sorts the points along a base line exactly and reports the runs of equal parameters. Holds its
// scratch buffers, so that one sorter serves every line without reallocating.
class Points_along_line_sorter
{
public:
  // Sorting points along a base line: sort by the lower ends of the parameter intervals; then runs of
  // overlapping intervals ("clusters") are sorted exactly. Any element after a cluster has its lower end
  // above every upper end of the cluster, so the result is exactly sorted. Calls group(first, last) for
  // each run of exactly equal parameters.
  template <class Group>
  void sort_and_group(const Arr_line& base, const std::vector<Arr_line>& lines, std::vector<Point_along_line>& items,
                      Group group)
  {
    sort_by_lower_end(items);
    const std::size_t count = items.size();
    std::size_t k = 0;
    while(k < count) {
      std::size_t end = k + 1;
      double reach = items[k].hi;
      while(end < count && items[end].lo <= reach) {
        reach = (std::max)(reach, items[end].hi);
        ++end;
      }
      if(end == k + 1)
        group(k, end);
      else
        resolve_cluster(base, lines, items, k, end, group);
      k = end;
    }
  }

private:
  // A run of items whose parameter intervals overlap: exact parameters, computed once per item, then
  // sorted and grouped. The common cluster is a point where several lines meet, all equal: one pass.
  template <class Group>
  void resolve_cluster(const Arr_line& base, const std::vector<Arr_line>& lines, std::vector<Point_along_line>& items,
                       std::size_t first, std::size_t last, Group& group)
  {
    const std::size_t count = last - first;
    exact_keys_.resize(count);
    for(std::size_t i = 0; i < count; ++i)
      exact_key(base, lines[items[first + i].other], exact_keys_[i]);
    auto compare = [&](std::size_t a, std::size_t b) {
      return CGAL::sign(exact_keys_[a].first * exact_keys_[b].second - exact_keys_[b].first * exact_keys_[a].second);
    };
    std::size_t i = 1;
    while(i < count && compare(0, i) == CGAL::ZERO) ++i;
    if(i == count) {
      group(first, last);
      return;
    }
    permutation_.resize(count);
    for(std::size_t j = 0; j < count; ++j) permutation_[j] = j;
    std::sort(permutation_.begin(), permutation_.end(),
              [&](std::size_t a, std::size_t b) { return compare(a, b) == CGAL::NEGATIVE; });
    cluster_buffer_.assign(items.begin() + first, items.begin() + last);
    for(std::size_t j = 0; j < count; ++j) items[first + j] = cluster_buffer_[permutation_[j]];
    std::size_t g = 0;
    for(std::size_t j = 1; j <= count; ++j)
      if(j == count || compare(permutation_[g], permutation_[j]) != CGAL::ZERO) {
        group(first + g, first + j);
        g = j;
      }
  }

  // The exact parameter along base of its intersection with o, as n / d with d > 0. When o shares a
  // defining point with base (pencils are built that way), the parameter is 0 or 1 without arithmetic.
  static void exact_key(const Arr_line& base, const Arr_line& o, std::pair<Arr_exact_nt, Arr_exact_nt>& key)
  {
    auto is = [](double x, double y, double u, double v) { return x == u && y == v; };
    if(is(o.px, o.py, base.px, base.py) || is(o.qx, o.qy, base.px, base.py)) {
      key.first = Arr_exact_nt(0);
      key.second = Arr_exact_nt(1);
    } else if(is(o.px, o.py, base.qx, base.qy) || is(o.qx, o.qy, base.qx, base.qy)) {
      key.first = Arr_exact_nt(1);
      key.second = Arr_exact_nt(1);
    } else {
      exact_param(base, o, key.first, key.second);
      CGAL_assertion(CGAL::sign(key.second) != CGAL::ZERO);
      if(CGAL::sign(key.second) == CGAL::NEGATIVE) {
        key.first = -key.first;
        key.second = -key.second;
      }
    }
  }

  // Sorts by `lo`: a bucket sort with about one item per bucket between the smallest and the largest
  // key (the bucket index is monotone in the key, so only the buckets need sorting), which is linear
  // for the spread-out intersections of random lines; std::sort inside crowded buckets.
  void sort_by_lower_end(std::vector<Point_along_line>& items)
  {
    auto less = [](const Point_along_line& a, const Point_along_line& b) { return a.lo < b.lo; };
    const std::size_t n = items.size();
    if(n < 64) {
      std::sort(items.begin(), items.end(), less);
      return;
    }
    double lo = items[0].lo, hi = items[0].lo;
    for(const Point_along_line& k : items) {
      lo = (std::min)(lo, k.lo);
      hi = (std::max)(hi, k.lo);
    }
    const double scale = double(n) / (hi - lo);
    if(!(hi > lo) || !std::isfinite(scale)) {
      std::sort(items.begin(), items.end(), less);
      return;
    }
    auto bucket = [&](double key) { return (std::min)(n - 1, std::size_t((key - lo) * scale)); };
    bucket_start_.assign(n + 1, 0);
    for(const Point_along_line& k : items) ++bucket_start_[bucket(k.lo) + 1];
    for(std::size_t b = 0; b < n; ++b) bucket_start_[b + 1] += bucket_start_[b];
    sort_buffer_.resize(n);
    for(const Point_along_line& k : items) sort_buffer_[bucket_start_[bucket(k.lo)]++] = k;
    items.swap(sort_buffer_);
    // bucket_start_[b] is now the end of bucket b.
    std::size_t begin = 0;
    for(std::size_t b = 0; b < n; ++b) {
      const std::size_t end = bucket_start_[b];
      if(end - begin > 32)
        std::sort(items.begin() + begin, items.begin() + end, less);
      else
        for(std::size_t i = begin + 1; i < end; ++i)
          for(std::size_t j = i; j > begin && items[j].lo < items[j - 1].lo; --j)
            std::swap(items[j], items[j - 1]);
      begin = end;
    }
  }

  std::vector<Point_along_line> sort_buffer_, cluster_buffer_;
  std::vector<std::pair<Arr_exact_nt, Arr_exact_nt>> exact_keys_;
  std::vector<std::size_t> permutation_;
  std::vector<std::size_t> bucket_start_;
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_SORTING_H
