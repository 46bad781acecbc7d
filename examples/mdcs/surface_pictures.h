// The pictures of `mdcs surface`: an oblique, height-coloured view of a surface (SVG) and the histogram of the
// local descents' energies against the global result (--descents). Written through checked files.
#ifndef MDCS_CLI_SURFACE_PICTURES_H
#define MDCS_CLI_SURFACE_PICTURES_H

#include "cli_output.h"

#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace mdcs_cli {

namespace VM3 = CGAL::Variational_minimization;

// An oblique view of a triangulated surface, painter's order, coloured by height and shaded; the boundary in red.
inline void write_surface_svg(const std::string& path, const VM3::Minimal_surface_3& s, const VM3::Surface_problem_3& p,
                              const std::string& title, const std::vector<std::string>& caption)
{
  const double az = 0.6, el = 0.55;
  const double sx = p.domain.xmax() - p.domain.xmin(), sy = p.domain.ymax() - p.domain.ymin(), sz = p.zmax - p.zmin;
  auto norm = [&](const std::array<double, 3>& q) {
    return std::array<double, 3>{{(q[0] - p.domain.xmin()) / sx - 0.5, (q[1] - p.domain.ymin()) / sy - 0.5,
                                  (q[2] - p.zmin) / sz * 0.7 - 0.35}};
  };
  auto project = [&](const std::array<double, 3>& q, double& u, double& v, double& depth) {
    const auto n = norm(q);
    const double a = std::cos(az) * n[0] - std::sin(az) * n[1];
    const double b = std::sin(az) * n[0] + std::cos(az) * n[1];
    u = 400 + 420 * a;
    v = 380 - 420 * (n[2] * std::cos(el) + b * std::sin(el));
    depth = b * std::cos(el) - n[2] * std::sin(el);
  };
  struct Tri { double depth; std::string svg; };
  std::vector<Tri> tris;
  for(const auto& t : s.triangles) {
    double u[3], v[3], d[3];
    double zc = 0;
    for(int k = 0; k < 3; ++k) {
      project(s.points[t[k]], u[k], v[k], d[k]);
      zc += s.points[t[k]][2] / 3;
    }
    // Height colour (blue -> green -> yellow) and Lambert shading from the normal in normalised coordinates.
    const auto a = norm(s.points[t[0]]), b = norm(s.points[t[1]]), c = norm(s.points[t[2]]);
    double nx = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
    double ny = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
    double nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
    if(len == 0) continue;
    if(nz < 0) { nx = -nx; ny = -ny; nz = -nz; }
    const double shade = 0.55 + 0.45 * std::max(0.0, (-0.4 * nx - 0.3 * ny + 0.87 * nz) / len);
    const double h = std::min(1.0, std::max(0.0, (zc - p.zmin) / sz));
    const double r = (h < 0.5 ? 0.15 + 0.3 * h : 0.3 + 1.3 * (h - 0.5)) , g = 0.25 + 0.6 * h, bl = 0.65 - 0.5 * h;
    auto c255 = [&](double x) { return int(std::min(255.0, std::max(0.0, 255 * x * shade))); };
    std::ostringstream o;
    o << std::fixed << std::setprecision(1) << "<polygon points='" << u[0] << ',' << v[0] << ' ' << u[1] << ','
      << v[1] << ' ' << u[2] << ',' << v[2] << "' fill='rgb(" << c255(r) << ',' << c255(g) << ',' << c255(bl)
      << ")' stroke='rgb(" << c255(r * 0.9) << ',' << c255(g * 0.9) << ',' << c255(bl * 0.9)
      << ")' stroke-width='0.25'/>\n";
    tris.push_back({(d[0] + d[1] + d[2]) / 3, o.str()});
  }
  std::sort(tris.begin(), tris.end(), [](const Tri& a, const Tri& b) { return a.depth > b.depth; });
  Output_file file(path);
  std::ostream& out = file.stream();
  out.precision(6);
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='800' height='" << 700 + 18 * caption.size()
      << "' viewBox='0 0 800 " << 700 + 18 * caption.size() << "'>\n<rect width='100%' height='100%' fill='white'/>\n";
  out << "<text x='20' y='28' font-family='sans-serif' font-size='18'>" << title << "</text>\n";
  // The domain's floor outline, then the surface, then the boundary curve.
  std::vector<std::array<double, 2>> outline = p.domain_polygon;
  if(!p.is_polygonal())
    outline = {{{p.domain.xmin(), p.domain.ymin()}}, {{p.domain.xmax(), p.domain.ymin()}},
               {{p.domain.xmax(), p.domain.ymax()}}, {{p.domain.xmin(), p.domain.ymax()}}};
  {
    out << "<polygon fill='none' stroke='#bbb' stroke-dasharray='4,3' points='";
    for(const auto& c : outline) {
      double u, v, d;
      project({{c[0], c[1], p.zmin}}, u, v, d);
      out << u << ',' << v << ' ';
    }
    out << "'/>\n";
  }
  for(const Tri& t : tris) out << t.svg;
  if(!p.is_relaxed()) {
    out << "<polyline fill='none' stroke='#d62728' stroke-width='2' points='";
    const int m = 100;
    for(std::size_t e = 0; e <= outline.size(); ++e) {
      const auto& a = outline[e % outline.size()];
      const auto& b = outline[(e + 1) % outline.size()];
      for(int i = 0; i < (e == outline.size() ? 1 : m); ++i) {
        const double f = double(i) / m, x = a[0] + f * (b[0] - a[0]), y = a[1] + f * (b[1] - a[1]);
        double u, v, d;
        project({{x, y, p.lower_boundary(x, y)}}, u, v, d);
        out << u << ',' << v << ' ';
      }
    }
    out << "'/>\n";
  }
  for(std::size_t i = 0; i < caption.size(); ++i)
    out << "<text x='20' y='" << 700 + 18 * i << "' font-family='sans-serif' font-size='13'>" << caption[i] << "</text>\n";
  out << "</svg>\n";
  file.commit();
}

// The histogram of the local descents' relaxed energies, the global result's energy marked (NAME_histogram.svg).
inline void write_descent_histogram_svg(const std::string& path, const std::vector<double>& energies, double global,
                                        const std::string& title)
{
  const int bins = 12;
  double lo = global, hi = global;
  for(double e : energies) { lo = (std::min)(lo, e); hi = (std::max)(hi, e); }
  if(!(hi > lo)) hi = lo + 1e-9 * (1 + std::abs(lo));
  const double width = (hi - lo) / bins;
  std::vector<int> count(bins, 0);
  for(double e : energies) ++count[std::size_t((std::min)(bins - 1, int((e - lo) / width)))];
  const int top = (std::max)(1, *std::max_element(count.begin(), count.end()));
  const double W = 720, H = 400, L = 60, R = 45, T = 50, B = 70, pw = W - L - R, ph = H - T - B;
  Output_file file(path);
  std::ostream& f = file.stream();
  f << std::setprecision(6) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << title << "</text>\n";
  for(int b = 0; b < bins; ++b) {
    const double h = ph * count[std::size_t(b)] / top, x = L + pw * b / bins;
    f << "<rect x=\"" << x + 1 << "\" y=\"" << T + ph - h << "\" width=\"" << pw / bins - 2 << "\" height=\"" << h
      << "\" fill=\"#7a9cc6\"/>\n";
    if(count[std::size_t(b)] > 0)
      f << "<text x=\"" << x + pw / bins / 2 << "\" y=\"" << T + ph - h - 4 << "\" text-anchor=\"middle\">"
        << count[std::size_t(b)] << "</text>\n";
  }
  f << "<line x1=\"" << L << "\" y1=\"" << T + ph << "\" x2=\"" << L + pw << "\" y2=\"" << T + ph
    << "\" stroke=\"black\"/>\n<line x1=\"" << L << "\" y1=\"" << T << "\" x2=\"" << L << "\" y2=\"" << T + ph
    << "\" stroke=\"black\"/>\n";
  for(int k = 0; k <= 4; ++k) {
    const double e = lo + (hi - lo) * k / 4, x = L + pw * k / 4;
    f << "<text x=\"" << x << "\" y=\"" << T + ph + 16 << "\" text-anchor=\"middle\">" << e << "</text>\n";
  }
  const double gx = L + pw * (global - lo) / (hi - lo);
  f << "<line x1=\"" << gx << "\" y1=\"" << T - 6 << "\" x2=\"" << gx << "\" y2=\"" << T + ph
    << "\" stroke=\"#c0392b\" stroke-width=\"3\"/>\n<text x=\"" << gx + 6 << "\" y=\"" << T - 10
    << "\" fill=\"#c0392b\">global (min-cut) " << global << "</text>\n"
    << "<text x=\"" << L + pw / 2 << "\" y=\"" << H - 28
    << "\" text-anchor=\"middle\">relaxed energy (L-BFGS on 20^2, 40^2 grids); bars: " << energies.size()
    << " local descents from random starts</text>\n"
    << "<text x=\"14\" y=\"" << T + ph / 2 << "\" transform=\"rotate(-90 14 " << T + ph / 2
    << ")\" text-anchor=\"middle\">runs</text>\n</svg>\n";
  file.commit();
}

} // namespace mdcs_cli

#endif // MDCS_CLI_SURFACE_PICTURES_H
