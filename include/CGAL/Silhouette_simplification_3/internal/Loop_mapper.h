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
  int tied_side = 0;                 ///< 1 (2): the left (right) side had no boundary and was tied at representative faces
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
    balance_.assign(fine->points.size(), 0);
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
        for(std::uint32_t c : m->coarse_touched_) m->coarse_label_[c] = 0;
        for(std::uint32_t g : m->touched_) m->outside_[g] = 0;
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
    solve(LEFT_COARSE, weight_factor, engine, report);
    if(!balanced()) {
      report.fine_labelling = true;
      solve(LEFT_FINE, weight_factor, engine, report);
    }
    report.first_output_loop = out.size();
    decompose_(fm, chain_, loops_);
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

  enum Labelling { LEFT_COARSE, LEFT_FINE };

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
    stack_.assign(1, g0);
    while(!stack_.empty()) {
      const std::uint32_t g = stack_.back();
      stack_.pop_back();
      for(std::uint32_t j = 0; j < 3; ++j) {
        const std::uint32_t x = m.face(m.opposite[3 * g + j]);
        if(x == NONE || in_band[x] != 0 || label[x] != 0) continue;
        label[x] = side;
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
    } else {
      for(std::uint32_t f : fine_band_) { seed_side_.push_back(side_[fmap[f]]); fine_in_band_[f] = 1; }
      flood(fm, fine_border_faces_, fine_band_, seed_side_, fine_in_band_, outside_, touched_);
    }
    network_.clear();
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
          g != NONE && (labelling == LEFT_COARSE ? coarse_label_[fmap[g]] : outside_[g]) == LEFT;
        if(source_terminal) {
          network_.add_source_facet(node_[f], w, h);
          ++report.source_arcs;
        } else {
          network_.add_sink_facet(node_[f], w, h);
          ++report.sink_arcs;
        }
      }
    }
    for(std::uint32_t c : coarse_touched_) coarse_label_[c] = 0;
    coarse_touched_.clear();
    for(std::uint32_t g : touched_) outside_[g] = 0;
    touched_.clear();
    if(labelling == LEFT_FINE) for(std::uint32_t f : fine_band_) fine_in_band_[f] = 0;

    // A side without outside faces (a small loop whose band covers all of one side): tie to that
    // terminal the representative fine face of each coarse face on that side of a loop edge.
    const Indexed_mesh<Point_3>& cm = *coarse_;
    report.tied_side = report.source_arcs == 0 ? LEFT : report.sink_arcs == 0 ? RIGHT : 0;
    if(report.source_arcs == 0 || report.sink_arcs == 0)
      for(std::uint32_t h : loop_->halfedges) {
        const std::uint32_t c = report.source_arcs == 0 ? cm.face(h) : cm.face(cm.opposite[h]);
        if(c == NONE) continue;
        const std::uint32_t f = (*representative_)[c];
        if(node_[f] == NONE) continue; // a coarse face without fine faces (user-given map)
        if(report.source_arcs == 0) network_.add_source_facet(node_[f], network_.infinity(), 3 * f);
        else network_.add_sink_facet(node_[f], network_.infinity(), 3 * f);
      }
    chain_.clear();
    report.cut_value = 0;
    if(network_.number_of_source_facets() > 0 && network_.number_of_sink_facets() > 0) {
      const auto cut = CGAL::Min_cut::solve_min_cut(network_, engine);
      report.cut_value = cut.value;
      for(const auto& c : cut.chain) {
        const std::uint32_t h = c.id;
        // Directed with the source side (left of the coarse loop) on the left.
        chain_.push_back(cut.on_source_side[node_[h / 3]] != 0 ? h : fm.opposite[h]);
      }
    }
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
  std::vector<Silhouette_loop<std::uint32_t>> loops_;
  CGAL::Min_cut::Flow_network<double> network_;
  Loop_decomposer decompose_;
};

} // namespace internal
} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_LOOP_MAPPER_H
