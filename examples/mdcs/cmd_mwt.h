// `mdcs mwt`: Minimum weight triangulation of a point set (issue 5): triangle LP over the diamond-test
// candidates, certificate, branch and bound for fractional optima; writes OFF, CSV, SVG and a report.
#ifndef MDCS_CLI_CMD_MWT_H
#define MDCS_CLI_CMD_MWT_H

#include "cli_common.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MDCS/IO/read_points.h>
#include <CGAL/Minimum_weight_triangulation_2.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace mdcs_cli {

namespace mwt_detail {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
namespace MWT = CGAL::Minimum_weight_triangulation_2;

// The points file of `mdcs mwt` through the library's distrustful reader (CGAL::MDCS::IO::read_points_2): one
// point per line, "x y", "x,y" or "x;y", '#' comments, an optional header line of words; anything else (a
// third coordinate, nan, inf, trailing text) exits 3 with the line. A file without points is refused too.
inline std::vector<Point> read_points(const std::string& path)
{
  std::vector<Point> p;
  try {
    CGAL::MDCS::IO::read_points_2(path, p);
  } catch(const CGAL::MDCS::IO::Read_error& e) {
    throw Input_error(e.what());
  }
  if(p.empty()) throw Input_error(path + ": the file holds no point");
  return p;
}

inline std::vector<Point> random_points(long n, const std::string& distribution, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> nd(0, 1);
  std::vector<Point> p;
  p.reserve(std::size_t(n));
  if(distribution == "uniform") {
    for(long i = 0; i < n; ++i) p.emplace_back(u(g), u(g));
  } else if(distribution == "normal") {
    for(long i = 0; i < n; ++i) p.emplace_back(nd(g), nd(g));
  } else if(distribution == "clustered") {
    const int clusters = int(std::max(1L, n / 100));
    std::vector<Point> c;
    for(int i = 0; i < clusters; ++i) c.emplace_back(u(g), u(g));
    const double sigma = 0.3 / std::sqrt(double(clusters));
    for(long i = 0; i < n; ++i) {
      const Point& q = c[std::size_t(g() % clusters)];
      p.emplace_back(q.x() + sigma * nd(g), q.y() + sigma * nd(g));
    }
  } else {
    throw Usage_error("--distribution must be uniform, clustered or normal");
  }
  return p;
}

inline std::vector<Point> wheel(long k)
{
  std::vector<Point> p{Point(0, 0)};
  for(long i = 0; i < k; ++i) p.emplace_back(std::cos(2 * M_PI * i / k), std::sin(2 * M_PI * i / k));
  return p;
}

// mwt.off (the triangulation), mwt_edges.csv (every edge: i,j,length,xi,yi,xj,yj with 17 significant digits) and,
// unless `picture` is false, mwt.svg (.png); every write checked. Returns the files written.
inline std::vector<std::string> write_outputs(const std::filesystem::path& folder, const std::string& stem, const std::vector<Point>& p,
                                              const MWT::Mwt_result& r, bool picture)
{
  std::vector<std::string> files;
  {
    Output_file off((folder / (stem + ".off")).string());
    off << "OFF\n" << p.size() << " " << r.triangles.size() << " 0\n";
    for(const Point& q : p) off << q.x() << " " << q.y() << " 0\n";
    for(const auto& t : r.triangles) off << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    off.commit();
    files.push_back(off.path());
  }
  std::set<std::pair<int, int>> edges;
  for(const auto& t : r.triangles)
    for(int i = 0; i < 3; ++i) edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
  {
    Output_file csv((folder / (stem + "_edges.csv")).string());
    csv << "i,j,length,xi,yi,xj,yj\n";
    for(const auto& e : edges) {
      const Point &a = p[std::size_t(e.first)], &b = p[std::size_t(e.second)];
      csv << e.first << "," << e.second << "," << std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))) << "," << a.x() << ","
          << a.y() << "," << b.x() << "," << b.y() << "\n";
    }
    csv.commit();
    files.push_back(csv.path());
  }
  if(!picture) return files;
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  for(const Point& q : p) { x0 = std::min(x0, q.x()); x1 = std::max(x1, q.x()); y0 = std::min(y0, q.y()); y1 = std::max(y1, q.y()); }
  const double size = 800, margin = 10, s = (size - 2 * margin) / std::max({x1 - x0, y1 - y0, 1e-300});
  auto X = [&](const Point& q) { return margin + (q.x() - x0) * s; };
  auto Y = [&](const Point& q) { return size - margin - (q.y() - y0) * s; };
  const std::string svg_path = (folder / (stem + ".svg")).string();
  Output_file file(svg_path);
  std::ostream& svg = file.stream();
  const double stroke = p.size() > 3000 ? 0.3 : (p.size() > 500 ? 0.6 : 1.2);
  svg << std::setprecision(6) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\"" << size << "\" viewBox=\"0 0 "
      << size << " " << size << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<g stroke=\"#1f4e9a\" stroke-width=\""
      << stroke << "\">\n";
  for(const auto& e : edges)
    svg << "<line x1=\"" << X(p[e.first]) << "\" y1=\"" << Y(p[e.first]) << "\" x2=\"" << X(p[e.second]) << "\" y2=\""
        << Y(p[e.second]) << "\"/>\n";
  svg << "</g>\n<g fill=\"#c0392b\">\n";
  const double radius = p.size() > 3000 ? 0.6 : (p.size() > 500 ? 1.2 : 2.5);
  for(const Point& q : p) svg << "<circle cx=\"" << X(q) << "\" cy=\"" << Y(q) << "\" r=\"" << radius << "\"/>\n";
  svg << "</g>\n</svg>\n";
  file.commit();
  files.push_back(svg_path);
  if(svg_to_png(svg_path)) files.push_back((folder / (stem + ".png")).string());
  return files;
}

// Refuses a triangulation whose weight or bounds are not finite numbers (an LP that returned NaN, points so far
// out that the lengths overflow).
inline void check_mwt_result(const MWT::Mwt_result& r)
{
  if(!r.has_triangulation()) return;
  if(!std::isfinite(r.weight) || r.weight < 0)
    throw Result_error("the triangulation's weight is " + std::to_string(r.weight) + " (not a finite number >= 0); status " +
                       MWT::to_string(r.status));
  if(std::isnan(r.lower_bound) || r.lower_bound > r.weight * (1 + 1e-9) + 1e-300)
    throw Result_error("the lower bound " + std::to_string(r.lower_bound) + " is not below the weight " + std::to_string(r.weight) +
                       "; status " + std::string(MWT::to_string(r.status)));
}

inline std::string report(const MWT::Mwt_result& r)
{
  const auto& s = r.statistics;
  std::ostringstream o;
  o << std::setprecision(12) << "points            " << s.points << " (" << s.hull_points << " on the hull)\n"
    << "status            " << MWT::to_string(r.status) << "\n"
    << "message           " << r.message << "\n"
    << "weight            " << r.weight << "\n"
    << "lower bound       " << r.lower_bound << "\n"
    << "LP optimum        " << r.lp_objective << (r.lp_integral ? " (integral)" : " (fractional)") << "\n"
    << "solver            " << r.solver
    << (!r.lp_exact ? "" : r.solver == "qp-solver" ? " (exact LP optimum: simplex in rational arithmetic)"
                                                   : " (verified in rational arithmetic)") << "\n"
    << "candidate edges   " << s.candidate_edges << "\n"
    << "empty triangles   " << s.empty_triangles << " (LP columns " << s.lp_columns << ", rows " << s.lp_rows << ")\n"
    << std::setprecision(4) << "time [s]          setup " << s.time_setup << ", candidates " << s.time_candidates
    << ", triangles " << s.time_triangles
    << ", LP build " << s.time_lp_build << ", LP solve " << s.time_lp_solve << ", certificate " << s.time_certificate
    << ", branch and bound " << s.time_branch_and_bound << ", total " << s.time_total << "\n";
  if(s.lmt_certain_edges > 0)
    o << "LMT-skeleton      " << s.lmt_certain_edges << " certain, " << s.lmt_possible_edges << " possible edges; "
      << s.lmt_solved_faces << " of " << s.lmt_faces << " faces by the dynamic program (" << s.dp_triangles
      << " triangles, " << s.dp_exact_faces << " faces with " << s.dp_exact_decisions
      << " decisions taken exactly); time " << s.time_lmt << " + " << s.time_face_dp << " s\n";
  return o.str();
}

} // namespace mwt_detail

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_MWT_H
