// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The min-cut duality on a grid of cells: the cheapest "function graph" separating the bottom row
// (source) from the top row (sink). Cutting a cell from the one above it costs 1 on a target curve
// and 5 elsewhere; the reverse direction is infinite, so every column is cut exactly once; each unit
// of vertical jump between neighbouring columns costs 0.5. Expected: the curve follows the target,
// value = 8 columns * 1 + 3 unit jumps * 0.5 = 9.5.

#include <CGAL/Min_cut.h>

#include <iostream>
#include <vector>

int main()
{
  namespace MC = CGAL::Min_cut;
  typedef MC::Flow_network<double> Network;
  const int width = 8, height = 7;
  const int target[width] = {2, 2, 3, 3, 4, 4, 3, 3};
  auto cell = [&](int x, int y) { return Network::Node_index(y * width + x); };

  Network network;
  network.add_nodes(width * height);
  Network::Facet_index id = 0; // facet ids: the caller's numbering of the primal edges
  for(int y = 0; y < height; ++y)
    for(int x = 0; x < width; ++x) {
      if(y + 1 < height) // horizontal primal edge between (x, y) and (x, y + 1)
        network.add_facet(cell(x, y), cell(x, y + 1), y == target[x] ? 1.0 : 5.0, Network::infinity(), id);
      ++id;
      if(x + 1 < width) // vertical primal edge between (x, y) and (x + 1, y)
        network.add_facet(cell(x, y), cell(x + 1, y), 0.5, 0.5, id);
      ++id;
    }
  for(int x = 0; x < width; ++x) {
    network.add_source_facet(cell(x, 0), Network::infinity(), id++);
    network.add_sink_facet(cell(x, height - 1), Network::infinity(), id++);
  }

  const MC::Min_cut_result<double> result = MC::solve_min_cut(network);
  if(!result.is_finite) {
    std::cout << "no finite cut: the constraints conflict\n";
    return 1;
  }
  std::cout << "min cut value: " << result.value << " (expected 9.5)\n";
  std::cout << "chain: " << result.chain.size() << " primal edges\n";

  // Height of the curve in each column = number of source cells from the bottom.
  bool follows_target = true;
  std::cout << "curve heights:";
  for(int x = 0; x < width; ++x) {
    int h = 0;
    while(h < height && result.on_source_side[cell(x, h)]) ++h;
    std::cout << ' ' << h - 1;
    follows_target = follows_target && h - 1 == target[x];
  }
  std::cout << "\nfollows the target curve: " << (follows_target ? "yes" : "no") << '\n';
  return follows_target && result.value == 9.5 ? 0 : 1;
}
