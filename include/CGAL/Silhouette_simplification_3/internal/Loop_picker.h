// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Method A (thesis 5.2.2): greedy choice of fine silhouette loops that approximate the coarse silhouette.

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_LOOP_PICKER_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_LOOP_PICKER_H

#include <CGAL/Silhouette_simplification_3/internal/silhouette_extraction.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/// \ingroup PkgSilhouetteSimplification3Ref
/// Parameters of loop picking (method A).
struct Loop_picking_options
{
  /// Fine loops with fewer edges are discarded before the search ("very short loops are pruned").
  std::size_t min_loop_edges = 8;
  /// Stop when the root-mean-square distance from the coarse silhouette vertices to the picked loops
  /// falls below `threshold` times the diagonal of the fine mesh's bounding box.
  double threshold = 0.004;
  /// Also stop when the best loop lowers the error by less than this fraction of the current error.
  double min_relative_gain = 0.002;
  /// Temporal-coherence remedy (hysteresis, 1 = none, must be in (0, 1]): for the greedy choices and the
  /// stopping tests, the distances of a fine loop that shares a fraction s of its edges with the previous
  /// frame's picked loops are multiplied by 1 - (1 - previous_bias) s; once the search stops, the loops
  /// with s >= 1/2 that still lower this biased error by `min_relative_gain` are kept too. The reported
  /// `picking_error` uses the true distances.
  double previous_bias = 1.0;
};

namespace internal {

// `coarse_points`: the coarse silhouette vertices; `loops`: the fine loops (halfedge indices of `fine`).
// Writes the indices of the picked loops in picking order; returns the final sum of squared distances.
template <class Point_3>
double pick_loops(const Indexed_mesh<Point_3>& fine, const std::vector<Point_3>& coarse_points,
                  const std::vector<Silhouette_loop<std::uint32_t>>& loops, double diagonal,
                  const Loop_picking_options& options, const std::vector<char>* previous_edge_flag,
                  std::vector<std::uint32_t>& picked, std::vector<float>& table)
{
  picked.clear();
  const std::size_t nc = coarse_points.size();
  std::vector<std::uint32_t> candidates;
  for(std::uint32_t l = 0; l < loops.size(); ++l)
    if(loops[l].halfedges.size() >= options.min_loop_edges) candidates.push_back(l);
  const double cap = diagonal * diagonal;
  if(nc == 0 || candidates.empty()) return double(nc) * cap;

  // table[i * nc + c]: squared distance from coarse vertex c to the closest vertex of candidate i.
  const std::size_t nl = candidates.size();
  table.assign(nl * nc, float(cap));
  std::vector<double> cx(nc), cy(nc), cz(nc);
  for(std::size_t c = 0; c < nc; ++c) {
    cx[c] = CGAL::to_double(coarse_points[c].x());
    cy[c] = CGAL::to_double(coarse_points[c].y());
    cz[c] = CGAL::to_double(coarse_points[c].z());
  }
  // Temporal-coherence remedy: the distances of loop i are scaled by scale[i] <= 1 for the choices; the
  // reported error uses the true distances.
  std::vector<double> share(nl, 0.0), scale(nl, 1.0);
  for(std::size_t i = 0; i < nl; ++i) {
    float* row = &table[i * nc];
    const auto& loop = loops[candidates[i]];
    std::size_t shared = 0;
    for(std::uint32_t h : loop.halfedges) {
      if(previous_edge_flag && (*previous_edge_flag)[fine.edge(h)]) ++shared;
      const Point_3& p = fine.points[fine.source[h]];
      const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
      for(std::size_t c = 0; c < nc; ++c) {
        const double dx = x - cx[c], dy = y - cy[c], dz = z - cz[c];
        const float d = float(dx * dx + dy * dy + dz * dz);
        if(d < row[c]) row[c] = d;
      }
    }
    share[i] = double(shared) / double(loop.halfedges.size());
    if(previous_edge_flag && shared > 0) {
      scale[i] = 1 - (1 - options.previous_bias) * share[i];
      for(std::size_t c = 0; c < nc; ++c) row[c] = float(row[c] * scale[i]);
    }
  }

  std::vector<double> best(nc, cap), true_best(nc, cap);
  std::vector<char> taken(nl, 0);
  double error = double(nc) * cap;
  const double goal = double(nc) * (options.threshold * diagonal) * (options.threshold * diagonal);
  auto gain_of = [&](std::size_t i) {
    const float* row = &table[i * nc];
    double gain = 0;
    for(std::size_t c = 0; c < nc; ++c)
      if(row[c] < best[c]) gain += best[c] - row[c];
    return gain;
  };
  auto take = [&](std::size_t i) {
    taken[i] = 1;
    picked.push_back(candidates[i]);
    const float* row = &table[i * nc];
    error = 0;
    for(std::size_t c = 0; c < nc; ++c) {
      best[c] = std::min(best[c], double(row[c]));
      true_best[c] = std::min(true_best[c], double(row[c]) / scale[i]);
      error += best[c];
    }
  };
  while(error > goal) {
    double best_gain = 0;
    std::size_t best_i = nl;
    for(std::size_t i = 0; i < nl; ++i) {
      if(taken[i]) continue;
      const double gain = gain_of(i);
      if(gain > best_gain) { best_gain = gain; best_i = i; }
    }
    if(best_i == nl || best_gain < options.min_relative_gain * error) break;
    take(best_i);
  }
  // Hysteresis: once the search stops, keep the loops that were mostly picked in the previous frame and
  // still lower the (biased) error by `min_relative_gain`.
  if(previous_edge_flag && options.previous_bias < 1)
    for(bool added = true; added;) {
      added = false;
      for(std::size_t i = 0; i < nl; ++i)
        if(!taken[i] && share[i] >= 0.5) {
          const double gain = gain_of(i);
          if(gain > 0 && gain >= options.min_relative_gain * error) {
            take(i);
            added = true;
          }
        }
    }
  if(!previous_edge_flag) return error;
  error = 0;
  for(std::size_t c = 0; c < nc; ++c) error += true_best[c];
  return error;
}

} // namespace internal
} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_LOOP_PICKER_H
