// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A temporal-coherence metric for silhouettes over a moving view.

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_TEMPORAL_COHERENCE_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_TEMPORAL_COHERENCE_H

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief The relative change between two edge sets: `|A xor B| / (|A| + |B|)` over undirected edges
  (given as canonical edge ids, e.g. `Indexed_mesh::edge()`), in [0, 1]; 0 when both are empty.
*/
inline double relative_edge_set_change(std::vector<std::uint32_t> a, std::vector<std::uint32_t> b)
{
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  if(a.empty() && b.empty()) return 0;
  std::vector<std::uint32_t> x;
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(x));
  return double(x.size()) / double(a.size() + b.size());
}

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief Temporal incoherence of a simplified silhouette over a frame sequence.

  For consecutive frames `t, t+1`, the relative change of the simplified edge set `S` is divided by
  the relative change of the true (fine) silhouette `F`; the result is the ratio of the sums:
  `sum_t change(S_t, S_t+1) / sum_t change(F_t, F_t+1)`. Below 1 the simplified silhouette flickers less
  than the true one, above 1 more. `simplified[t]` and `fine[t]` hold canonical edge ids.
*/
inline double temporal_incoherence(const std::vector<std::vector<std::uint32_t>>& simplified,
                                   const std::vector<std::vector<std::uint32_t>>& fine)
{
  double s = 0, f = 0;
  for(std::size_t t = 0; t + 1 < simplified.size() && t + 1 < fine.size(); ++t) {
    s += relative_edge_set_change(simplified[t], simplified[t + 1]);
    f += relative_edge_set_change(fine[t], fine[t + 1]);
  }
  return f > 0 ? s / f : (s > 0 ? 1e300 : 0);
}

} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_TEMPORAL_COHERENCE_H
