// The frames of a rotation on several threads (issue 29 item 5): simplify_silhouette_frames() delivers, in view
// order and one at a time, exactly the frames of the sequential per-view calls, for 1, 2, 3 and 8 threads, with and
// without the previous-frame remedy, and with a bounded number of frames in flight; workspaces make the per-view
// calls const.
// Tagged [parallel]: the ThreadSanitizer build runs these cases alone.
#include <catch2/catch.hpp>

#include "silhouette_test_meshes.h"

#include <CGAL/Silhouette_simplification_3.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace silhouette_test;
namespace SS = CGAL::Silhouette_simplification_3;
typedef SS::View_3<K> View;
typedef SS::Silhouette_simplifier_3<Mesh> Simplifier;

namespace {

std::vector<View> rotation(std::size_t frames, double step)
{
  std::vector<View> views;
  for(std::size_t t = 0; t < frames; ++t) {
    const double a = step * double(t), e = 0.3, r = 4;
    views.push_back(t % 5 == 4 ? View::orthographic(K::Vector_3(-std::cos(a), -std::sin(a), -0.2))
                               : View::perspective(Point_3(r * std::cos(a) * std::cos(e), r * std::sin(a) * std::cos(e),
                                                           r * std::sin(e))));
  }
  return views;
}

bool same_loops(const std::vector<SS::Silhouette_frame::Loop>& a, const std::vector<SS::Silhouette_frame::Loop>& b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].halfedges != b[i].halfedges || a[i].closed != b[i].closed) return false;
  return true;
}

bool same_frame(const SS::Silhouette_frame& a, const SS::Silhouette_frame& b)
{
  bool reports = a.mapping_reports.size() == b.mapping_reports.size();
  for(std::size_t i = 0; reports && i < a.mapping_reports.size(); ++i)
    reports = a.mapping_reports[i].cut_value == b.mapping_reports[i].cut_value &&
              a.mapping_reports[i].band_fine_faces == b.mapping_reports[i].band_fine_faces;
  return a.fine_front == b.fine_front && a.coarse_front == b.coarse_front && a.fine_silhouette == b.fine_silhouette &&
         a.coarse_silhouette == b.coarse_silhouette && same_loops(a.fine_loops, b.fine_loops) &&
         same_loops(a.coarse_loops, b.coarse_loops) && a.picked == b.picked && a.picking_error == b.picking_error &&
         same_loops(a.mapped, b.mapped) && reports;
}

// The sequential reference: the per-view calls of one simplifier in a loop, previous frame passed along.
std::vector<SS::Silhouette_frame> reference(Simplifier& s, const std::vector<View>& views,
                                            const SS::Silhouette_frames_options& o)
{
  std::vector<SS::Silhouette_frame> out(views.size());
  for(std::size_t t = 0; t < views.size(); ++t) {
    s.extract(views[t], out[t]);
    const SS::Silhouette_frame* prev = t > 0 ? &out[t - 1] : nullptr;
    if(o.pick) s.pick_loops(out[t], o.picking, o.picking.previous_bias != 1.0 ? prev : nullptr);
    if(o.map) s.map_loops(out[t], o.mapping, o.mapping.previous_bias != 1.0 ? prev : nullptr);
  }
  return out;
}

} // namespace

TEST_CASE("simplify_silhouette_frames: the sequential frames, in order, for every thread count",
          "[silhouette][frames][parallel]")
{
  const Mesh fine = make<Mesh>(noisy_sphere(4, 0.06));
  SS::Coarse_mesh_options co;
  co.target_faces = 300;
  const SS::Coarse_mesh_3<Point_3> coarse = SS::build_coarse_mesh(fine, co);
  Simplifier s(fine, coarse.mesh, coarse.coarse_face_of_fine_face);
  const std::vector<View> views = rotation(10, 0.47);
  for(int remedy = 0; remedy < 2; ++remedy) {
    SS::Silhouette_frames_options o;
    if(remedy) {
      o.picking.previous_bias = 0.5;
      o.mapping.previous_bias = 0.6;
    }
    const std::vector<SS::Silhouette_frame> ref = reference(s, views, o);
    std::size_t picked = 0, mapped = 0;
    for(const auto& f : ref) {
      picked += f.picked.size();
      mapped += f.mapped.size();
    }
    REQUIRE(picked > 0);
    REQUIRE(mapped > 0);
    for(std::size_t t : {1u, 2u, 3u, 8u})
      for(std::size_t in_flight : {0u, 3u}) {
        INFO(t << " threads, " << in_flight << " in flight, remedy " << remedy);
        o.threads = t;
        o.frames_in_flight = in_flight;
        std::vector<std::size_t> order;
        std::vector<SS::Silhouette_frame> got;
        std::atomic<int> inside{0};
        bool alone = true;
        SS::simplify_silhouette_frames<CGAL::Parallel_tag>(s, views, o, [&](std::size_t i, SS::Silhouette_frame& f) {
          alone = alone && inside.fetch_add(1) == 0;
          order.push_back(i);
          got.push_back(std::move(f));
          inside.fetch_sub(1);
        });
        CHECK(alone); // never two outputs at a time
        REQUIRE(got.size() == views.size());
        bool in_order = true, equal = true;
        for(std::size_t i = 0; i < got.size(); ++i) {
          in_order = in_order && order[i] == i;
          equal = equal && same_frame(got[i], ref[i]);
        }
        CHECK(in_order);
        CHECK(equal);
      }
    // The convenience version and the sequential tag.
    const std::vector<SS::Silhouette_frame> all = SS::simplify_silhouette_frames(s, views, o);
    REQUIRE(all.size() == ref.size());
    for(std::size_t i = 0; i < all.size(); ++i) CHECK(same_frame(all[i], ref[i]));
  }
}

TEST_CASE("simplify_silhouette_frames: methods off, bad options, cancellation, no views",
          "[silhouette][frames][parallel]")
{
  const Mesh fine = make<Mesh>(torus(40, 16, 1, 0.4, 0.05));
  SS::Coarse_mesh_options co;
  co.target_faces = 200;
  const SS::Coarse_mesh_3<Point_3> coarse = SS::build_coarse_mesh(fine, co);
  const Simplifier s(fine, coarse.mesh, coarse.coarse_face_of_fine_face); // const: the frames need no mutable simplifier
  const std::vector<View> views = rotation(9, 0.5);
  SS::Silhouette_frames_options o;
  o.pick = false;
  o.threads = 3;
  const std::vector<SS::Silhouette_frame> frames = SS::simplify_silhouette_frames<CGAL::Parallel_tag>(s, views, o);
  for(const auto& f : frames) {
    CHECK(f.picked.empty());
    CHECK(!f.fine_silhouette.empty());
    CHECK(f.mapping_reports.size() == f.coarse_loops.size());
  }
  // One workspace per thread by hand: the const per-view calls give the same frame.
  Simplifier::Workspace ws = s.make_workspace();
  SS::Silhouette_frame f;
  s.extract(views[2], f, ws);
  s.map_loops(f, o.mapping, nullptr, CGAL::Min_cut::Default_max_flow_engine(), ws);
  CHECK(same_loops(f.mapped, frames[2].mapped));

  SS::Silhouette_frames_options bad;
  bad.mapping.alpha = 0;
  CHECK_THROWS_AS(SS::simplify_silhouette_frames<CGAL::Parallel_tag>(s, views, bad), std::invalid_argument);
  bad = SS::Silhouette_frames_options();
  bad.picking.previous_bias = 1.5;
  CHECK_THROWS_AS(SS::simplify_silhouette_frames<CGAL::Parallel_tag>(s, views, bad), std::invalid_argument);

  int calls = 0;
  o.threads = 2;
  o.frames_in_flight = 2;
  CHECK_THROWS_AS(SS::simplify_silhouette_frames<CGAL::Parallel_tag>(
                    s, views, o, [](std::size_t, SS::Silhouette_frame&) {}, CGAL::Min_cut::Default_max_flow_engine(),
                    [&](const char*, double) { return ++calls < 2; }), // the second report: a frame or the end
                  CGAL::MDCS::Operation_cancelled);
  CHECK(SS::simplify_silhouette_frames<CGAL::Parallel_tag>(s, std::vector<View>(), o).empty());
}
