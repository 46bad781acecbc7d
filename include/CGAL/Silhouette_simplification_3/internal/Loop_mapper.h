// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Method B (thesis 5.2.3): a coarse silhouette loop is mapped to the minimal-weight closed loop of fine
// edges that separates the internal and external boundaries of the fine band, by a minimum cut of the
// band's dual graph (CGAL::Min_cut).

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_LOOP_MAPPER_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_LOOP_MAPPER_H

#include <CGAL/Silhouette_simplification_3/internal/silhouette_extraction.h>
#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/solve_min_cut.h>

#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/// \ingroup PkgSilhouetteSimplification3Ref
/// Parameters of loop mapping (method B).
struct Loop_mapping_options
{
  /// Weight factor of fine edges that lie on the fine silhouette (thesis: 0.1). Must be in (0, 1].
  double alpha = 0.1;
  /// Temporal-coherence remedy: weight factor of fine edges that the previous frame's mapped
  /// silhouette used (1 = no bias). Must be in (0, 1].
  double previous_bias = 1.0;
};

/// \ingroup PkgSilhouetteSimplification3Ref
/// What loop mapping measured for one coarse loop.
struct Mapped_loop_report
{
  std::size_t coarse_loop = 0;       ///< index of the coarse loop
  std::size_t band_coarse_faces = 0; ///< coarse faces sharing a vertex with the loop
  std::size_t band_fine_faces = 0;   ///< fine faces mapped to them (nodes of the dual graph)
  std::size_t source_arcs = 0;       ///< fine edges of the internal boundary
  std::size_t sink_arcs = 0;         ///< fine edges of the external boundary
  std::size_t side_conflicts = 0;    ///< coarse band faces seen on both sides of the loop (first side kept)
  double cut_value = 0;              ///< minimum cut value = weight of the mapped edges
  bool fine_labelling = false;       ///< outside regions had to be labelled on the fine mesh
  /// the band's boundary was labelled by the side of the band face along each boundary edge (a loop whose two
  /// sides meet beyond the band, e.g. around a handle; see `tied_side`)
  bool adjacent_labelling = false;
  /// the cut split the loop (one side of the band fell into pieces): fine faces tied along paths that join the
  /// pieces, 0 when not needed
  std::size_t joined_faces = 0;
  /// 1 (2): the left (right) side had no outside faces; a connected set of its fine faces (`tied_faces` of
  /// them) was tied to the source (sink): the representative fine faces of its coarse faces along the loop,
  /// joined by shortest paths of fine faces on that side; 3: both sides (the band covers a whole component)
  int tied_side = 0;
  std::size_t tied_faces = 0;
  std::size_t first_output_loop = 0, number_of_output_loops = 0; ///< the fine loops it produced
};

namespace internal {

template <class Point_3>
class Loop_mapper
{
public:
  // Fine halfedge weights (edge length, same for both halfedges) are given once.
  Loop_mapper(const Indexed_mesh<Point_3>* fine, const Indexed_mesh<Point_3>* coarse,
              const std::vector<std::uint32_t>* cf_begin, const std::vector<std::uint32_t>* cf,
              const std::vector<double>* length)
    : fine_(fine), coarse_(coarse), cf_begin_(cf_begin), cf_(cf), length_(length)
  {
    side_.assign(coarse->faces.size(), 0);
    node_.assign(fine->faces.size(), NONE);
    outside_.assign(fine->faces.size(), 0);
    fine_in_band_.assign(fine->faces.size(), 0);
    coarse_label_.assign(coarse->faces.size(), 0);
    coarse_region_.assign(coarse->faces.size(), -1);
    fine_region_.assign(fine->faces.size(), -1);
    balance_.assign(fine->points.size(), 0);
    parent_.assign(fine->faces.size(), NONE);
    tie_mark_.assign(fine->faces.size(), 0);
    for(std::uint32_t h = std::uint32_t(fine->number_of_interior_halfedges()); h < fine->number_of_halfedges(); ++h)
      fine_border_faces_.push_back(fine->face(fine->opposite[h]));
    for(std::uint32_t h = std::uint32_t(coarse->number_of_interior_halfedges()); h < coarse->number_of_halfedges(); ++h)
      coarse_border_faces_.push_back(coarse->face(coarse->opposite[h]));
  }

  // Maps one coarse loop (coarse halfedge indices). `weight_factor[h]` multiplies the length of each
  // fine halfedge (silhouette and previous-frame factors). Appends the fine loops to `out`.
  template <class Engine>
  Mapped_loop_report map(const Silhouette_loop<std::uint32_t>& loop, const std::vector<double>& weight_factor,
                         Engine engine, std::vector<Silhouette_loop<std::uint32_t>>& out)
  {
    const Indexed_mesh<Point_3>& cm = *coarse_;
    const Indexed_mesh<Point_3>& fm = *fine_;
    Mapped_loop_report report;
    // Scratch marks are cleared on every exit, exceptions (cancellation, engine limits) included.
    struct Cleanup
    {
      Loop_mapper* m;
      ~Cleanup()
      {
        for(std::uint32_t f : m->fine_band_) { m->node_[f] = NONE; m->fine_in_band_[f] = 0; }
        for(std::uint32_t c : m->band_) m->side_[c] = 0;
        for(std::uint32_t c : m->coarse_touched_) { m->coarse_label_[c] = 0; m->coarse_region_[c] = -1; }
        for(std::uint32_t g : m->touched_) { m->outside_[g] = 0; m->fine_region_[g] = -1; }
        m->coarse_touched_.clear();
        m->touched_.clear();
      }
    } cleanup{this};
    band_.clear();
    const std::size_t n = loop.halfedges.size();
    // Coarse band, split by the loop: rotate around each loop vertex from the outgoing loop edge,
    // counter-clockwise (left of the loop) until the reversed incoming edge, then on the right.
    for(std::size_t i = 0; i < n && loop.closed; ++i) {
      const std::uint32_t hin = loop.halfedges[(i + n - 1) % n], hout = loop.halfedges[i];
      const std::uint32_t stop = cm.opposite[hin];
      rotate(hout, stop, LEFT, report);
      rotate(stop, hout, RIGHT, report);
    }
    report.band_coarse_faces = band_.size();

    // Fine band and its dual graph.
    fine_band_.clear();
    for(std::uint32_t c : band_)
      for(std::uint32_t k = (*cf_begin_)[c]; k < (*cf_begin_)[c + 1]; ++k) {
        const std::uint32_t f = (*cf_)[k];
        node_[f] = std::uint32_t(fine_band_.size());
        fine_band_.push_back(f);
      }
    report.band_fine_faces = fine_band_.size();
    // The cut chain is the boundary of the source side together with the outside faces that feed
    // source arcs; it is a cycle when every connected region of faces outside the band has one side.
    // Outside regions are labelled on the coarse mesh first (cheap), by the side of the first band
    // face that touches them; if the chain is not balanced (fine regions that the coarse labelling
    // splits), the labelling is redone on the fine mesh. The mesh border counts as the sink side.
    loop_ = &loop;
    labelling_ = LEFT_COARSE;
    solve(LEFT_COARSE, weight_factor, engine, report);
    if(!balanced()) {
      report.fine_labelling = true;
      labelling_ = LEFT_FINE;
      solve(LEFT_FINE, weight_factor, engine, report);
    }
    decompose_(fm, chain_, loops_);
    // One coarse loop, one mapped loop: the two remedies below run only when the cut gave several loops (or none).
    if(loop.closed && loops_.size() != 1) try_adjacent_labelling(weight_factor, engine, report);
    if(loop.closed && loops_.size() > 1) join_pieces(weight_factor, engine, report);
    report.first_output_loop = out.size();
    for(auto& l : loops_) out.push_back(std::move(l));
    report.number_of_output_loops = out.size() - report.first_output_loop;
    return report;
  }

  void set_face_map(const std::vector<std::uint32_t>* face_map, const std::vector<std::uint32_t>* representative)
  {
    face_map_ = face_map;
    representative_ = representative;
  }

  // The last network and the fine band (for tests).
  const CGAL::Min_cut::Flow_network<double>& network() const { return network_; }
  const std::vector<std::uint32_t>& fine_band() const { return fine_band_; }
  const std::vector<std::uint32_t>& chain() const { return chain_; }

private:
  enum { LEFT = 1, RIGHT = 2 };

  enum Labelling { LEFT_COARSE, LEFT_FINE, ADJACENT };

  // The loop does not separate the mesh (it runs around a handle: CGAL's elephant has genus 3), or its two sides
  // meet beyond the band: then one outside region touches both sides of the band and gets one label, so that one
  // side has terminals of both kinds, or none (then a connected tie on that side makes two loops, one along each
  // side of the tie). The band is an annulus between the two sides: label its boundary by the side of the band face
  // each boundary edge bounds, so that the cut separates the left boundary from the right one: one loop around the
  // core. Kept when its chain is a cycle that decomposes into fewer loops.
  template <class Engine>
  void try_adjacent_labelling(const std::vector<double>& weight_factor, Engine engine, Mapped_loop_report& report)
  {
    Mapped_loop_report trial = report;
    save_solution();
    solve(ADJACENT, weight_factor, engine, trial);
    bool better = false;
    if(trial.source_arcs > 0 && trial.sink_arcs > 0 && trial.tied_side == 0 && balanced()) {
      decompose_(*fine_, chain_, trial_loops_);
      better = !trial_loops_.empty() && trial_loops_.size() < loops_.size();
    }
    if(!better) { restore_solution(); return; }
    trial.adjacent_labelling = true;
    report = trial;
    loops_.swap(trial_loops_);
    labelling_ = ADJACENT;
  }

  // The cut still splits the loop: the source side (or the sink side) of the band falls into pieces, where the
  // coarse loop's side is narrower than the band (a thin limb, a neck) and cutting across is cheaper than going
  // around; or one side is an annulus (bridge_loops()). Join the pieces: tie to their terminal the shortest path of
  // band faces (on that side of the coarse loop where possible) from the largest piece to each other piece, and
  // cut again; source pieces first, then sink pieces, then bridges; a few rounds at most, each from the last one
  // (joining source pieces can enclose a sink piece, which the next round joins). The round with the fewest loops
  // (a cycle) is kept.
  template <class Engine>
  void join_pieces(const std::vector<double>& weight_factor, Engine engine, Mapped_loop_report& report)
  {
    save_solution();   // the best solution so far
    best_loops_ = loops_;
    Mapped_loop_report best = report;
    for(int round = 0; round < 8 && best_loops_.size() > 1; ++round) {
      const std::size_t before = extra_ties_.size();
      if(!join_components(true) && !join_components(false) && !bridge_loops(true)) bridge_loops(false);
      if(extra_ties_.size() == before) break;   // nothing left to join or bridge
      Mapped_loop_report trial = report;
      solve(labelling_, weight_factor, engine, trial);
      if(!balanced()) break;
      decompose_(*fine_, chain_, trial_loops_);
      if(trial_loops_.empty()) break;
      loops_.swap(trial_loops_);   // the state the next round starts from
      if(loops_.size() < best_loops_.size()) {
        trial.joined_faces = extra_ties_.size();
        best = trial;
        best_loops_ = loops_;
        save_solution();
      }
    }
    restore_solution();
    report = best;
    loops_.swap(best_loops_);
    extra_ties_.clear();
  }

  // Ties paths that join the pieces of the source side (`source`) or the sink side of the last cut: a piece is a
  // connected set of band faces on that side together with the outside regions of that side's terminal arcs that
  // they touch (a region touched by no face on that side, a pocket enclosed by the other side, is a piece of its
  // own). From the largest piece, breadth-first searches over band faces (those on the coarse loop's matching side
  // first) reach each other piece, or a face with an arc into it, and the path is tied to the terminal. False when
  // there is one piece or none could be joined.
  bool join_components(bool source)
  {
    const Indexed_mesh<Point_3>& fm = *fine_;
    const std::vector<std::uint32_t>& fmap = *face_map_;
    const std::size_t n = fine_band_.size();
    if(node_side_.size() != n) return false;
    const char want = source ? 1 : 0;
    // union-find over band nodes [0, n) and regions [n, n + regions)
    region_index_.clear();
    for(const Terminal_arc& t : terminal_arcs_)
      if(t.source == source) region_index_.emplace(t.region, int(region_index_.size()));
    const std::size_t total = n + region_index_.size();
    piece_.resize(total);
    for(std::size_t i = 0; i < total; ++i) piece_[i] = int(i);
    auto find = [this](int x) {
      while(piece_[x] != x) x = piece_[x] = piece_[piece_[x]];
      return x;
    };
    auto unite = [&](int a, int b) { piece_[find(a)] = find(b); };
    for(std::size_t i = 0; i < n; ++i) {
      if(node_side_[i] != want) continue;
      for(std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t g = fm.face(fm.opposite[3 * fine_band_[i] + k]);
        if(g != NONE && node_[g] != NONE && node_side_[node_[g]] == want) unite(int(i), int(node_[g]));
      }
    }
    for(const Terminal_arc& t : terminal_arcs_)
      if(t.source == source && node_side_[t.node] == want) unite(int(t.node), int(n) + region_index_[t.region]);
    // the pieces, and the largest by band faces
    std::vector<int>& size = piece_size_;
    size.assign(total, 0);
    std::size_t pieces = 0;
    for(std::size_t i = 0; i < total; ++i) {
      if(i < n && node_side_[i] != want) continue;
      if(find(int(i)) == int(i)) ++pieces;
      if(i < n) ++size[find(int(i))];
    }
    if(pieces <= 1) return false;
    int largest = -1;
    for(std::size_t i = 0; i < n; ++i)
      if(node_side_[i] == want && (largest < 0 || size[find(int(i))] > size[largest])) largest = find(int(i));
    if(largest < 0) return false;
    // the piece a band face leads into: its own (on that side) or the region of one of its arcs of that kind
    node_arcs_.assign(n, -1);
    for(const Terminal_arc& t : terminal_arcs_)
      if(t.source == source) node_arcs_[t.node] = int(n) + region_index_[t.region];
    auto piece_of = [&](std::uint32_t x) {
      if(node_side_[x] == want) return find(int(x));
      return node_arcs_[x] >= 0 ? find(node_arcs_[x]) : -1;
    };
    const char coarse_side = source ? LEFT : RIGHT;
    bool added = false;
    for(std::size_t joined = 1; joined < pieces;) {
      bool found = false;
      for(int pass = 0; pass < 2 && !found; ++pass) {   // pass 0: faces on the coarse loop's side only
        node_parent_.assign(n, NONE);
        visited_.clear();
        for(std::size_t i = 0; i < n; ++i)
          if(node_side_[i] == want && find(int(i)) == largest) { node_parent_[i] = std::uint32_t(i); visited_.push_back(std::uint32_t(i)); }
        for(std::size_t head = 0; head < visited_.size() && !found; ++head) {
          const std::uint32_t x = visited_[head];
          for(std::uint32_t k = 0; k < 3 && !found; ++k) {
            const std::uint32_t g = fm.face(fm.opposite[3 * fine_band_[x] + k]);
            if(g == NONE || node_[g] == NONE) continue;
            const std::uint32_t y = node_[g];
            if(node_parent_[y] != NONE || node_tie_[y] == (source ? 2 : 1)) continue;   // tied to the other terminal
            const int p = piece_of(y);
            if(p == largest) continue;
            if(pass == 0 && side_[fmap[g]] != coarse_side && p < 0) continue;
            node_parent_[y] = x;
            if(p >= 0) {
              // another piece: tie the path up to and including y, and merge the piece into the largest
              extra_ties_.emplace_back(fine_band_[y], source);
              for(std::uint32_t z = x; !(node_side_[z] == want && find(int(z)) == largest); z = node_parent_[z])
                extra_ties_.emplace_back(fine_band_[z], source);
              piece_[p] = largest;
              found = added = true;
            } else {
              visited_.push_back(y);
            }
          }
        }
      }
      if(!found) break;
      ++joined;
    }
    return added;
  }

  // Both sides are one piece each, yet their common boundary is several loops: one side is an annulus (a band around
  // a handle or a tube: on a thin tube the fine front strip closes where the coarse one is broken, knot1 of CGAL's
  // data). Cut that side open: the shortest path of band faces on that side (`source`) from the faces along the
  // longest loop to the faces along another loop is tied to the other terminal, so that the two loops become one.
  bool bridge_loops(bool source)
  {
    const Indexed_mesh<Point_3>& fm = *fine_;
    const std::size_t n = fine_band_.size();
    if(node_side_.size() != n || loops_.size() < 2) return false;
    const char want = source ? 1 : 0;
    std::size_t main = 0;
    for(std::size_t i = 1; i < loops_.size(); ++i)
      if(loops_[i].halfedges.size() > loops_[main].halfedges.size()) main = i;
    // the band face along halfedge h on that side (the chain has the source side on its left)
    auto along = [&](std::uint32_t h) {
      const std::uint32_t f = source ? fm.face(h) : fm.face(fm.opposite[h]);
      return f == NONE || node_[f] == NONE || node_side_[node_[f]] != want ? NONE : node_[f];
    };
    node_parent_.assign(n, NONE);
    piece_.assign(n, -1);   // the loop a target face lies along
    for(std::size_t i = 0; i < loops_.size(); ++i)
      if(i != main)
        for(std::uint32_t h : loops_[i].halfedges)
          if(along(h) != NONE) piece_[along(h)] = int(i);
    visited_.clear();
    for(std::uint32_t h : loops_[main].halfedges) {
      const std::uint32_t x = along(h);
      if(x == NONE || node_parent_[x] != NONE || node_tie_[x] == (source ? 1 : 2)) continue;
      if(piece_[x] >= 0) continue;   // a face along two loops: no path needed, but no bridge either
      node_parent_[x] = x;
      visited_.push_back(x);
    }
    for(std::size_t head = 0; head < visited_.size(); ++head) {
      const std::uint32_t x = visited_[head];
      for(std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t g = fm.face(fm.opposite[3 * fine_band_[x] + k]);
        if(g == NONE || node_[g] == NONE) continue;
        const std::uint32_t y = node_[g];
        if(node_side_[y] != want || node_parent_[y] != NONE || node_tie_[y] == (source ? 1 : 2)) continue;
        node_parent_[y] = x;
        if(piece_[y] >= 0) {
          for(std::uint32_t z = y;; z = node_parent_[z]) {
            extra_ties_.emplace_back(fine_band_[z], !source);
            if(node_parent_[z] == z) break;
          }
          return true;
        }
        visited_.push_back(y);
      }
    }
    return false;
  }

  void save_solution()
  {
    saved_chain_ = chain_;
    saved_network_ = network_;
    saved_node_side_ = node_side_;
    saved_node_tie_ = node_tie_;
    saved_terminal_arcs_ = terminal_arcs_;
  }

  void restore_solution()
  {
    chain_.swap(saved_chain_);
    std::swap(network_, saved_network_);
    node_side_.swap(saved_node_side_);
    node_tie_.swap(saved_node_tie_);
    terminal_arcs_.swap(saved_terminal_arcs_);
  }


  // Floods the regions outside the band (coarse or fine faces): first the regions that touch the
  // mesh border (sink side, like the border itself), then the others with the side of the band face
  // that first touches them.
  template <class Mesh_>
  void flood(const Mesh_& m, const std::vector<std::uint32_t>& border_faces, const std::vector<std::uint32_t>& seeds,
             const std::vector<char>& seed_side, const std::vector<char>& in_band,
             std::vector<char>& label, std::vector<std::uint32_t>& touched)
  {
    for(std::uint32_t g : border_faces) flood_region(m, g, RIGHT, in_band, label, touched);
    for(std::size_t i = 0; i < seeds.size(); ++i)
      for(std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t g = m.face(m.opposite[3 * seeds[i] + k]);
        if(g != NONE) flood_region(m, g, seed_side[i], in_band, label, touched);
      }
  }

  template <class Mesh_>
  void flood_region(const Mesh_& m, std::uint32_t g0, char side, const std::vector<char>& in_band,
                    std::vector<char>& label, std::vector<std::uint32_t>& touched)
  {
    if(in_band[g0] != 0 || label[g0] != 0) return;
    label[g0] = side;
    touched.push_back(g0);
    std::vector<std::int64_t>& region = &label == &coarse_label_ ? coarse_region_ : fine_region_;
    const std::int64_t id = next_region_++;
    region[g0] = id;
    stack_.assign(1, g0);
    while(!stack_.empty()) {
      const std::uint32_t g = stack_.back();
      stack_.pop_back();
      for(std::uint32_t j = 0; j < 3; ++j) {
        const std::uint32_t x = m.face(m.opposite[3 * g + j]);
        if(x == NONE || in_band[x] != 0 || label[x] != 0) continue;
        label[x] = side;
        region[x] = id;
        touched.push_back(x);
        stack_.push_back(x);
      }
    }
  }

  template <class Engine>
  void solve(Labelling labelling, const std::vector<double>& weight_factor, Engine engine, Mapped_loop_report& report)
  {
    const Indexed_mesh<Point_3>& fm = *fine_;
    const std::vector<std::uint32_t>& fmap = *face_map_;
    seed_side_.clear();
    if(labelling == LEFT_COARSE) {
      for(std::uint32_t c : band_) seed_side_.push_back(side_[c]);
      flood(*coarse_, coarse_border_faces_, band_, seed_side_, side_, coarse_label_, coarse_touched_);
    } else if(labelling == LEFT_FINE) {
      for(std::uint32_t f : fine_band_) { seed_side_.push_back(side_[fmap[f]]); fine_in_band_[f] = 1; }
      flood(fm, fine_border_faces_, fine_band_, seed_side_, fine_in_band_, outside_, touched_);
    }
    network_.clear();
    terminal_arcs_.clear();
    report.source_arcs = report.sink_arcs = 0;
    if(!fine_band_.empty()) network_.add_nodes(fine_band_.size());
    for(std::uint32_t f : fine_band_) {
      for(std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t h = 3 * f + k, o = fm.opposite[h];
        const double w = (*length_)[h] * weight_factor[fm.edge(h)];
        const std::uint32_t g = fm.face(o);
        if(g != NONE && node_[g] != NONE) {
          if(h < o) network_.add_facet(node_[f], node_[g], w, w, h);
          continue;
        }
        const bool source_terminal =
          g != NONE && (labelling == LEFT_COARSE ? coarse_label_[fmap[g]]
                        : labelling == LEFT_FINE ? outside_[g]
                                                 : side_[fmap[f]]) == LEFT;   // ADJACENT: the band face's side
        if(source_terminal) {
          network_.add_source_facet(node_[f], w, h);
          ++report.source_arcs;
        } else {
          network_.add_sink_facet(node_[f], w, h);
          ++report.sink_arcs;
        }
        // the outside region behind the arc (join_components()): -1 the mesh border, a region of the labelling,
        // or (adjacent labelling) the outside face itself
        const std::int64_t region = g == NONE                ? -1
                                    : labelling == LEFT_COARSE ? coarse_region_[fmap[g]]
                                    : labelling == LEFT_FINE   ? fine_region_[g]
                                                               : std::int64_t(g);
        terminal_arcs_.push_back(Terminal_arc{node_[f], region, source_terminal});
      }
    }
    for(std::uint32_t c : coarse_touched_) { coarse_label_[c] = 0; coarse_region_[c] = -1; }
    coarse_touched_.clear();
    for(std::uint32_t g : touched_) { outside_[g] = 0; fine_region_[g] = -1; }
    touched_.clear();
    if(labelling == LEFT_FINE) for(std::uint32_t f : fine_band_) fine_in_band_[f] = 0;

    // A side without outside faces (a small loop, or a thin feature, whose band covers all of one side): tie a
    // connected set of that side's fine faces to its terminal, so that the cut encloses one region and gives one
    // loop. (Tying the representative fine faces alone, as before, let the cut enclose each of them by a tiny
    // loop of its own: CGAL's elephant, 1000 coarse faces, turned 14 coarse loops into 50 mapped loops.)
    // Neither side has outside faces (the band covers a whole small component of the mesh): both sides are tied.
    report.tied_side = (report.source_arcs == 0 ? LEFT : 0) | (report.sink_arcs == 0 ? RIGHT : 0);
    report.tied_faces = 0;
    node_tie_.assign(fine_band_.size(), 0);
    for(char side : {char(LEFT), char(RIGHT)}) {
      if(!(report.tied_side & side)) continue;
      connected_tie_set(side);
      report.tied_faces += tied_.size();
      for(std::uint32_t f : tied_) {
        node_tie_[node_[f]] = side == LEFT ? 1 : 2;
        if(side == LEFT) network_.add_source_facet(node_[f], network_.infinity(), 3 * f);
        else network_.add_sink_facet(node_[f], network_.infinity(), 3 * f);
      }
    }
    // paths that join the pieces of one side (join_pieces())
    for(const auto& t : extra_ties_) {
      node_tie_[node_[t.first]] = t.second ? 1 : 2;
      if(t.second) network_.add_source_facet(node_[t.first], network_.infinity(), 3 * t.first);
      else network_.add_sink_facet(node_[t.first], network_.infinity(), 3 * t.first);
    }
    chain_.clear();
    node_side_.clear();
    report.cut_value = 0;
    if(network_.number_of_source_facets() > 0 && network_.number_of_sink_facets() > 0) {
      const auto cut = CGAL::Min_cut::solve_min_cut(network_, engine);
      report.cut_value = cut.value;
      // (never infinite with one terminal's ties; a tie of each kind on one face would make it so: no chain then)
      if(!cut.is_finite) return;
      node_side_ = cut.on_source_side;
      for(const auto& c : cut.chain) {
        const std::uint32_t h = c.id;
        // Directed with the source side (left of the coarse loop) on the left.
        chain_.push_back(cut.on_source_side[node_[h / 3]] != 0 ? h : fm.opposite[h]);
      }
    }
  }

  // The faces to tie on side `side` (LEFT or RIGHT) of the loop when that side has no outside faces: the
  // representative fine faces of the coarse faces on that side of the loop edges (central in their coarse face),
  // joined in loop order by shortest paths of fine faces whose coarse faces are on that side. The minimum cut's
  // side of that terminal then contains one connected tied set, so its boundary is one loop (isolated tied faces
  // were cut off one by one by 3-edge loops). Where no such path exists (the side's fine faces are not
  // connected), the pieces stay apart.
  void connected_tie_set(char side)
  {
    const Indexed_mesh<Point_3>& cm = *coarse_;
    const Indexed_mesh<Point_3>& fm = *fine_;
    const std::vector<std::uint32_t>& fmap = *face_map_;
    tied_.clear();
    seeds_.clear();
    for(std::uint32_t h : loop_->halfedges) {
      const std::uint32_t c = side == LEFT ? cm.face(h) : cm.face(cm.opposite[h]);
      if(c == NONE) continue;
      const std::uint32_t f = (*representative_)[c];
      if(node_[f] == NONE) continue;   // a coarse face without fine faces (user-given map)
      if(side_[c] != side) continue;   // a face seen on both sides: kept on the other
      if(seeds_.empty() || seeds_.back() != f) seeds_.push_back(f);
    }
    if(seeds_.size() > 1 && seeds_.front() == seeds_.back()) seeds_.pop_back();
    if(seeds_.empty()) {
      // every face on that side of the loop edges is also on the other: tie their representatives as before
      for(std::uint32_t h : loop_->halfedges) {
        const std::uint32_t c = side == LEFT ? cm.face(h) : cm.face(cm.opposite[h]);
        if(c != NONE && node_[(*representative_)[c]] != NONE) mark_tied((*representative_)[c]);
      }
    }
    for(std::uint32_t f : seeds_) mark_tied(f);
    // Breadth-first search from each seed to the next one, over fine band faces of that side.
    for(std::size_t i = 0; seeds_.size() > 1 && i < seeds_.size(); ++i) {
      const std::uint32_t from = seeds_[i], to = seeds_[(i + 1) % seeds_.size()];
      if(i + 1 == seeds_.size() && seeds_.size() == 2) break;   // two seeds: one path joins them
      if(from == to) continue;
      parent_[from] = from;
      visited_.assign(1, from);
      std::size_t head = 0;
      bool found = false;
      while(head < visited_.size() && !found) {
        const std::uint32_t g = visited_[head++];
        for(std::uint32_t k = 0; k < 3 && !found; ++k) {
          const std::uint32_t x = fm.face(fm.opposite[3 * g + k]);
          if(x == NONE || node_[x] == NONE || parent_[x] != NONE || side_[fmap[x]] != side) continue;
          parent_[x] = g;
          visited_.push_back(x);
          found = x == to;
        }
      }
      if(found)
        for(std::uint32_t x = parent_[to]; x != from; x = parent_[x]) mark_tied(x);
      for(std::uint32_t g : visited_) parent_[g] = NONE;
    }
    for(std::uint32_t f : tied_) tie_mark_[f] = 0;
  }

  void mark_tied(std::uint32_t f)
  {
    if(tie_mark_[f]) return;
    tie_mark_[f] = 1;
    tied_.push_back(f);
  }

  // Whether every vertex has as many incoming as outgoing chain edges.
  bool balanced()
  {
    const Indexed_mesh<Point_3>& fm = *fine_;
    bool ok = true;
    for(std::uint32_t h : chain_) { ++balance_[fm.source[h]]; --balance_[fm.target(h)]; }
    for(std::uint32_t h : chain_) {
      if(balance_[fm.source[h]] != 0) ok = false;
      balance_[fm.source[h]] = 0;
      balance_[fm.target(h)] = 0;
    }
    return ok;
  }

  void rotate(std::uint32_t h, std::uint32_t stop, char side, Mapped_loop_report& report)
  {
    const Indexed_mesh<Point_3>& cm = *coarse_;
    for(std::size_t guard = 0; guard <= cm.number_of_halfedges(); ++guard) {
      const std::uint32_t f = cm.face(h);
      if(f == NONE) return; // mesh border: the fan ends here
      if(side_[f] == 0) {
        side_[f] = side;
        band_.push_back(f);
      } else if(side_[f] != side) {
        ++report.side_conflicts;
      }
      h = cm.opposite[3 * f + (h % 3 + 2) % 3]; // next outgoing halfedge counter-clockwise
      if(h == stop) return;
    }
    throw std::logic_error("MDCS: Loop_mapper: vertex fan does not close");
  }

  const Indexed_mesh<Point_3>* fine_;
  const Indexed_mesh<Point_3>* coarse_;
  const std::vector<std::uint32_t>* cf_begin_;
  const std::vector<std::uint32_t>* cf_;
  const std::vector<double>* length_;
  const std::vector<std::uint32_t>* face_map_ = nullptr;
  const std::vector<std::uint32_t>* representative_ = nullptr;
  const Silhouette_loop<std::uint32_t>* loop_ = nullptr;
  std::vector<char> side_, outside_, fine_in_band_, coarse_label_, seed_side_;
  std::vector<int> balance_;
  std::vector<std::uint32_t> coarse_touched_, stack_, fine_border_faces_, coarse_border_faces_;
  std::vector<std::uint32_t> node_, band_, fine_band_, chain_, touched_;
  std::vector<std::uint32_t> seeds_, tied_, parent_, visited_;   // connected_tie_set(); parent_ is NONE between calls
  std::vector<char> tie_mark_;                                    // 0 between calls
  std::vector<Silhouette_loop<std::uint32_t>> loops_;
  std::vector<Silhouette_loop<std::uint32_t>> trial_loops_, best_loops_;
  std::vector<std::uint32_t> saved_chain_, node_parent_;
  std::vector<char> node_side_, saved_node_side_, node_tie_, saved_node_tie_;   // node_tie_: 1 tied to the source, 2 to the sink           // per band node: on the source side of the last cut
  std::vector<int> piece_, piece_size_, node_arcs_;
  struct Terminal_arc
  {
    std::uint32_t node;
    std::int64_t region;
    bool source;
  };
  std::vector<Terminal_arc> terminal_arcs_, saved_terminal_arcs_;   // finite terminal arcs of the last solve()
  std::unordered_map<std::int64_t, int> region_index_;
  std::vector<std::int64_t> coarse_region_, fine_region_;   // outside region of a labelled face, -1 otherwise
  std::int64_t next_region_ = 0;
  std::vector<std::pair<std::uint32_t, bool>> extra_ties_;  // (fine face, to the source) of join_pieces()
  Labelling labelling_ = LEFT_COARSE;
  CGAL::Min_cut::Flow_network<double> saved_network_;
  CGAL::Min_cut::Flow_network<double> network_;
  Loop_decomposer decompose_;
};

} // namespace internal
} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_LOOP_MAPPER_H
