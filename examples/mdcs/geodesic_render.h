// The pictures and files of `mdcs geodesics`: a shaded SVG of a distance field on a triangle mesh with
// iso-distance lines, sources, targets and shortest paths, and an ASCII PLY file with the distance of every
// vertex. Independent of the mesh type and of the method that computed the distances.
#ifndef MDCS_CLI_GEODESIC_RENDER_H
#define MDCS_CLI_GEODESIC_RENDER_H

#include "cli_output.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mdcs_cli {

typedef std::array<double, 3> Geo_vec;

// ------------------------------------------------------------------------------------------------------------
// Small vector helpers (doubles).
namespace geo_detail {

inline Geo_vec sub(const Geo_vec& a, const Geo_vec& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline double dot(const Geo_vec& a, const Geo_vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Geo_vec cross(const Geo_vec& a, const Geo_vec& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline Geo_vec normalized(const Geo_vec& a)
{
  const double l = std::sqrt(dot(a, a));
  return l > 0 ? Geo_vec{{a[0] / l, a[1] / l, a[2] / l}} : a;
}

// The colour map of distances in [0, 1]: "turbo" (Mikhailov, 2019, polynomial fit), lightened by 18% towards
// white so that the dark iso-lines stay readable at both ends.
inline std::array<double, 3> colour_map(double t)
{
  t = std::min(1.0, std::max(0.0, t));
  const double r = 0.13572138 + t * (4.61539260 + t * (-42.66032258 + t * (132.13108234 + t * (-152.94239396 + t * 59.28637943))));
  const double g = 0.09140261 + t * (2.19418839 + t * (4.84296658 + t * (-14.18503333 + t * (4.27729857 + t * 2.82956604))));
  const double b = 0.10667330 + t * (12.64194608 + t * (-60.58204836 + t * (110.36276771 + t * (-89.90310912 + t * 27.34824973))));
  std::array<double, 3> c = {{r, g, b}};
  for(double& x : c) x = 0.82 * std::min(1.0, std::max(0.0, x)) + 0.18;
  return c;
}

inline const std::array<double, 3>& unreachable_colour()
{
  static const std::array<double, 3> grey = {{0.74, 0.74, 0.74}};
  return grey;
}

inline std::string hex_colour(const std::array<double, 3>& c, double shade = 1.0)
{
  char buf[8];
  auto byte = [&](double x) { return int(std::lround(255.0 * std::min(1.0, std::max(0.0, x * shade)))); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c[0]), byte(c[1]), byte(c[2]));
  return buf;
}

// A round spacing (1, 2, 2.5 or 5 times a power of ten) for about `levels` lines below `range`.
inline double nice_spacing(double range, long levels)
{
  if(!(range > 0) || levels <= 0) return 0;
  const double raw = range / double(levels);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double best = p;
  for(double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if(std::abs(std::log(m * p / raw)) < std::abs(std::log(best / raw))) best = m * p;
  return best;
}

inline std::string number_text(double x, int digits = 4)
{
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

inline std::string xml_escape(const std::string& s)
{
  std::string r;
  for(char c : s) r += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return r;
}

} // namespace geo_detail

// ------------------------------------------------------------------------------------------------------------
// The picture: orthographic view, faces coloured by distance and shaded by their normal, painted back to front
// (hidden faces found with a software depth buffer are left out), iso-distance lines per face, the sources, and
// the shortest paths (dashed where hidden).

struct Geodesic_picture
{
  std::vector<Geo_vec> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<double> distance; // per point; +inf when unreachable
  double max_distance = 0;      // the top of the colour map
  std::vector<Geo_vec> sources;
  std::vector<std::vector<Geo_vec>> paths; // one polyline per target
  std::vector<Geo_vec> targets;
  Geo_vec view = {{1, 1, 1}}, up = {{0, 1, 0}};
  long levels = 20;
  std::string title;
  std::vector<std::string> caption_lines;
  // results of the writer
  double iso_spacing = 0;
  std::size_t drawn_faces = 0;
};

inline void write_geodesic_svg(const std::string& file, Geodesic_picture& pic)
{
  using namespace geo_detail;
  const double inf = std::numeric_limits<double>::infinity();
  // Camera frame.
  const Geo_vec d = normalized(pic.view);
  Geo_vec up = normalized(pic.up);
  if(!(std::abs(dot(up, d)) < 0.99)) up = std::abs(d[1]) < 0.9 ? Geo_vec{{0, 1, 0}} : Geo_vec{{0, 0, 1}};
  const Geo_vec right = normalized(cross(up, d));
  const Geo_vec screen_up = cross(d, right);
  const Geo_vec light = normalized({{0.8 * d[0] + 0.45 * screen_up[0] - 0.3 * right[0], 0.8 * d[1] + 0.45 * screen_up[1] - 0.3 * right[1],
                                     0.8 * d[2] + 0.45 * screen_up[2] - 0.3 * right[2]}});

  // Projection of the vertices used by faces.
  const std::size_t n = pic.points.size();
  std::vector<double> X(n), Y(n), Z(n);
  double xmin = inf, xmax = -inf, ymin = inf, ymax = -inf, zmin = inf, zmax = -inf;
  for(std::size_t i = 0; i < n; ++i) {
    X[i] = dot(pic.points[i], right);
    Y[i] = dot(pic.points[i], screen_up);
    Z[i] = dot(pic.points[i], d);
  }
  for(const auto& t : pic.triangles)
    for(std::size_t i : t) {
      xmin = std::min(xmin, X[i]), xmax = std::max(xmax, X[i]);
      ymin = std::min(ymin, Y[i]), ymax = std::max(ymax, Y[i]);
      zmin = std::min(zmin, Z[i]), zmax = std::max(zmax, Z[i]);
    }
  if(pic.triangles.empty()) xmin = ymin = zmin = 0, xmax = ymax = zmax = 1;
  const double diag = std::max(1e-300, std::sqrt((xmax - xmin) * (xmax - xmin) + (ymax - ymin) * (ymax - ymin) + (zmax - zmin) * (zmax - zmin)));
  const double pad = 0.03 * std::max(xmax - xmin, ymax - ymin) + 1e-12 * diag;
  xmin -= pad, xmax += pad, ymin -= pad, ymax += pad;

  // Layout (pixels).
  const double W = 1000, margin = 20, top = 48, max_plot_w = W - 2 * margin, max_plot_h = 760;
  const double scale = std::min(max_plot_w / (xmax - xmin), max_plot_h / (ymax - ymin));
  const double plot_w = (xmax - xmin) * scale, plot_h = (ymax - ymin) * scale;
  const double left = (W - plot_w) / 2;
  auto sx = [&](double x) { return left + (x - xmin) * scale; };
  auto sy = [&](double y) { return top + (ymax - y) * scale; };

  // Depth buffer, one sample per pixel, and the face owning each pixel.
  const int bw = std::max(1, int(std::ceil(plot_w))), bh = std::max(1, int(std::ceil(plot_h)));
  std::vector<double> zbuf(std::size_t(bw) * std::size_t(bh), -inf);
  std::vector<std::int64_t> owner(zbuf.size(), -1);
  for(std::size_t f = 0; f < pic.triangles.size(); ++f) {
    const auto& t = pic.triangles[f];
    const double x0 = sx(X[t[0]]) - left, y0 = sy(Y[t[0]]) - top, x1 = sx(X[t[1]]) - left, y1 = sy(Y[t[1]]) - top,
                 x2 = sx(X[t[2]]) - left, y2 = sy(Y[t[2]]) - top;
    const double area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if(!(std::abs(area) > 1e-12)) continue;
    const int i0 = std::max(0, int(std::floor(std::min({x0, x1, x2})))), i1 = std::min(bw - 1, int(std::ceil(std::max({x0, x1, x2}))));
    const int j0 = std::max(0, int(std::floor(std::min({y0, y1, y2})))), j1 = std::min(bh - 1, int(std::ceil(std::max({y0, y1, y2}))));
    for(int j = j0; j <= j1; ++j)
      for(int i = i0; i <= i1; ++i) {
        const double px = i + 0.5, py = j + 0.5;
        const double a = ((x1 - px) * (y2 - py) - (x2 - px) * (y1 - py)) / area;
        const double b = ((x2 - px) * (y0 - py) - (x0 - px) * (y2 - py)) / area;
        const double c = 1 - a - b;
        if(a < 0 || b < 0 || c < 0) continue;
        const double z = a * Z[t[0]] + b * Z[t[1]] + c * Z[t[2]];
        const std::size_t k = std::size_t(j) * std::size_t(bw) + std::size_t(i);
        if(z > zbuf[k]) zbuf[k] = z, owner[k] = std::int64_t(f);
      }
  }
  const double depth_tolerance = 3.0 / scale + 1e-6 * diag;
  // Whether a point (projected x, y, depth z) is in front of the surface around its pixel.
  auto visible = [&](double x, double y, double z) {
    const int i = int(std::floor(sx(x) - left)), j = int(std::floor(sy(y) - top));
    double back = inf;
    for(int dj = -1; dj <= 1; ++dj)
      for(int di = -1; di <= 1; ++di) {
        const int a = i + di, b = j + dj;
        if(a < 0 || b < 0 || a >= bw || b >= bh) return true;
        const double zb = zbuf[std::size_t(b) * std::size_t(bw) + std::size_t(a)];
        if(zb == -inf) return true; // next to the silhouette
        back = std::min(back, zb);
      }
    return z >= back - depth_tolerance;
  };

  // The faces to draw: those owning a pixel, and tiny ones whose centre is not hidden; back to front.
  std::vector<char> keep(pic.triangles.size(), 0);
  for(std::int64_t f : owner)
    if(f >= 0) keep[std::size_t(f)] = 1;
  std::vector<std::pair<double, std::size_t>> order;
  for(std::size_t f = 0; f < pic.triangles.size(); ++f) {
    const auto& t = pic.triangles[f];
    const double cz = (Z[t[0]] + Z[t[1]] + Z[t[2]]) / 3;
    if(!keep[f] && !visible((X[t[0]] + X[t[1]] + X[t[2]]) / 3, (Y[t[0]] + Y[t[1]] + Y[t[2]]) / 3, cz)) continue;
    order.emplace_back(cz, f);
  }
  std::sort(order.begin(), order.end());
  pic.drawn_faces = order.size();
  const bool seams = order.size() <= 60000; // a stroke in the face colour hides the anti-aliasing seams

  const double maxd = pic.max_distance;
  if(!std::isfinite(maxd)) throw std::logic_error("mdcs: write_geodesic_svg: the largest distance is not finite");
  const double spacing = maxd > 0 ? nice_spacing(maxd, pic.levels) : 0;
  pic.iso_spacing = spacing;
  // nice_spacing() keeps the number of levels within about 2.5 times those asked for; this is a hard bound.
  const double max_level = spacing > 0 ? std::min(std::floor(maxd / spacing), 3.0 * double(pic.levels) + 3) : 0;

  Output_file svg_file(file);
  std::ostream& out = svg_file.stream();
  out.precision(6);
  const double legend_top = top + plot_h + 16;
  const double H = legend_top + 58 + 19 * double(pic.caption_lines.size()) + 8;
  char buf[256];
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  std::snprintf(buf, sizeof buf, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n", W, H, W, H);
  out << buf;
  out << "<style>.i{fill:none;stroke:#111;stroke-width:0.7;stroke-opacity:0.65}"
         ".j{fill:none;stroke:#000;stroke-width:1.3;stroke-opacity:0.8}"
         ".h{fill:none;stroke:#fff;stroke-width:6;stroke-linejoin:round;stroke-linecap:round;stroke-opacity:0.9}"
         ".p{fill:none;stroke:#c2007a;stroke-width:3;stroke-linejoin:round;stroke-linecap:round}"
         ".q{fill:none;stroke:#c2007a;stroke-width:2;stroke-dasharray:6,4;stroke-opacity:0.9}"
         "text{font-family:Helvetica,Arial,sans-serif;fill:#222}</style>\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"" << W / 2 << "\" y=\"30\" font-size=\"18\" text-anchor=\"middle\">" << xml_escape(pic.title) << "</text>\n";

  // Faces and iso-lines, interleaved back to front so that nearer faces hide farther lines.
  out << "<g stroke-width=\"0.7\" stroke-linejoin=\"round\">\n";
  for(const auto& entry : order) {
    const auto& t = pic.triangles[entry.second];
    const Geo_vec& p0 = pic.points[t[0]];
    Geo_vec normal = normalized(cross(sub(pic.points[t[1]], p0), sub(pic.points[t[2]], p0)));
    if(dot(normal, d) < 0) normal = {{-normal[0], -normal[1], -normal[2]}}; // two-sided lighting
    const double shade = 0.62 + 0.38 * std::max(0.0, dot(normal, light));
    const double d0 = pic.distance[t[0]], d1 = pic.distance[t[1]], d2 = pic.distance[t[2]];
    const bool reached = std::isfinite(d0) && std::isfinite(d1) && std::isfinite(d2) && maxd > 0;
    const std::string colour = hex_colour(reached ? colour_map((d0 + d1 + d2) / (3 * maxd)) : unreachable_colour(), shade);
    std::snprintf(buf, sizeof buf, "<path d=\"M%.1f %.1fL%.1f %.1fL%.1f %.1fZ\" fill=\"%s\"", sx(X[t[0]]), sy(Y[t[0]]), sx(X[t[1]]),
                  sy(Y[t[1]]), sx(X[t[2]]), sy(Y[t[2]]), colour.c_str());
    out << buf;
    if(seams) out << " stroke=\"" << colour << "\"";
    out << "/>\n";
    if(!reached || !(spacing > 0)) continue;
    // Iso-lines: a segment per level crossing the face, by linear interpolation of the vertex distances.
    const double lo = std::min({d0, d1, d2}), hi = std::max({d0, d1, d2});
    std::string minor, major;
    const long k_last = long(std::min(std::floor(hi / spacing), max_level)); // bounded by the levels asked for
    for(long k = std::max(1L, long(std::ceil(std::min(lo / spacing, max_level + 1)))); k <= k_last; ++k) {
      const double level = double(k) * spacing;
      double ex[2], ey[2];
      int found = 0;
      for(int e = 0; e < 3 && found < 2; ++e) {
        const std::size_t a = t[std::size_t(e)], b = t[std::size_t((e + 1) % 3)];
        const double da = pic.distance[a], db = pic.distance[b];
        if((da >= level) == (db >= level)) continue;
        const double s = (level - da) / (db - da);
        ex[found] = sx(X[a] + s * (X[b] - X[a]));
        ey[found] = sy(Y[a] + s * (Y[b] - Y[a]));
        ++found;
      }
      if(found != 2) continue;
      std::snprintf(buf, sizeof buf, "M%.1f %.1fL%.1f %.1f", ex[0], ey[0], ex[1], ey[1]);
      (k % 5 == 0 ? major : minor) += buf;
    }
    if(!minor.empty()) out << "<path class=\"i\" d=\"" << minor << "\"/>\n";
    if(!major.empty()) out << "<path class=\"j\" d=\"" << major << "\"/>\n";
  }
  out << "</g>\n";

  // Shortest paths: solid where visible, dashed where hidden behind the surface.
  auto polyline = [&](const std::vector<std::pair<double, double>>& pts, const char* cls) {
    if(pts.size() < 2) return;
    out << "<polyline class=\"" << cls << "\" points=\"";
    for(const auto& q : pts) {
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", q.first, q.second);
      out << buf;
    }
    out << "\"/>\n";
  };
  std::vector<std::vector<std::pair<double, double>>> shown, hidden;
  for(const auto& path : pic.paths) {
    std::vector<std::pair<double, double>> run;
    bool run_visible = true;
    auto flush = [&] {
      if(run.size() >= 2) (run_visible ? shown : hidden).push_back(run);
      run.clear();
    };
    for(std::size_t i = 0; i + 1 < path.size(); ++i) {
      const Geo_vec& a = path[i];
      const Geo_vec& b = path[i + 1];
      const double ax = dot(a, right), ay = dot(a, screen_up), az = dot(a, d);
      const double bx = dot(b, right), by = dot(b, screen_up), bz = dot(b, d);
      const int pieces = std::max(1, int(std::ceil(std::hypot(bx - ax, by - ay) * scale / 2.0)));
      for(int k = 0; k < pieces; ++k) {
        const double s0 = double(k) / pieces, s1 = double(k + 1) / pieces, sm = (s0 + s1) / 2;
        const bool v = visible(ax + sm * (bx - ax), ay + sm * (by - ay), az + sm * (bz - az));
        const std::pair<double, double> q0(sx(ax + s0 * (bx - ax)), sy(ay + s0 * (by - ay)));
        const std::pair<double, double> q1(sx(ax + s1 * (bx - ax)), sy(ay + s1 * (by - ay)));
        if(run.empty() || v != run_visible) {
          flush();
          run_visible = v;
          run.push_back(q0);
        }
        run.push_back(q1);
      }
    }
    flush();
  }
  out << "<g id=\"paths\">\n";
  for(const auto& r : hidden) polyline(r, "q");
  for(const auto& r : shown) polyline(r, "h");
  for(const auto& r : shown) polyline(r, "p");
  out << "</g>\n";

  // Targets and sources (hollow where hidden).
  out << "<g id=\"markers\" font-size=\"13\">\n";
  for(std::size_t i = 0; i < pic.targets.size(); ++i) {
    const Geo_vec& p = pic.targets[i];
    const double x = sx(dot(p, right)), y = sy(dot(p, screen_up));
    const bool v = visible(dot(p, right), dot(p, screen_up), dot(p, d));
    std::snprintf(buf, sizeof buf, "<rect x=\"%.1f\" y=\"%.1f\" width=\"9\" height=\"9\" transform=\"rotate(45 %.1f %.1f)\" fill=\"%s\" stroke=\"#000\" stroke-width=\"1.2\"/>\n",
                  x - 4.5, y - 4.5, x, y, v ? "#c2007a" : "none");
    out << buf;
    std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">T%zu</text>\n", x + 8, y - 6, i + 1);
    out << buf;
  }
  for(std::size_t i = 0; i < pic.sources.size(); ++i) {
    const Geo_vec& p = pic.sources[i];
    const double x = sx(dot(p, right)), y = sy(dot(p, screen_up));
    const bool v = visible(dot(p, right), dot(p, screen_up), dot(p, d));
    std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"6.5\" fill=\"%s\" stroke=\"#000\" stroke-width=\"2\"%s/>\n", x, y,
                  v ? "#fff" : "none", v ? "" : " stroke-dasharray=\"3,2\"");
    out << buf;
    std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"2.5\" fill=\"#000\"/>\n", x, y);
    out << buf;
    if(pic.sources.size() > 1) {
      std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">S%zu</text>\n", x + 9, y + 15, i);
      out << buf;
    }
  }
  out << "</g>\n";

  // Legend: the colour bar with the major iso values, the unreachable grey, the path and source symbols.
  const double bar_x = margin + 10, bar_w = 360, bar_y = legend_top + 16;
  out << "<defs><linearGradient id=\"cmap\">";
  for(int k = 0; k <= 16; ++k) out << "<stop offset=\"" << k / 16.0 << "\" stop-color=\"" << hex_colour(colour_map(k / 16.0)) << "\"/>";
  out << "</linearGradient></defs>\n";
  out << "<g font-size=\"12\">\n";
  std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\">geodesic distance%s</text>\n", bar_x, legend_top + 10,
                spacing > 0 ? (", iso-lines every " + number_text(spacing) + " (bold every " + number_text(5 * spacing) + ")").c_str() : "");
  out << buf;
  std::snprintf(buf, sizeof buf, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"12\" fill=\"url(#cmap)\" stroke=\"#555\" stroke-width=\"0.6\"/>\n", bar_x, bar_y, bar_w);
  out << buf;
  if(maxd > 0) {
    std::vector<double> ticks = {0};
    if(spacing > 0)
      for(long k = 5; double(k) <= max_level + 1e-9; k += 5) ticks.push_back(double(k) * spacing);
    if(ticks.size() < 3) ticks.push_back(maxd);
    for(double v : ticks) {
      const double x = bar_x + bar_w * v / maxd;
      std::snprintf(buf, sizeof buf, "<path d=\"M%.1f %.1fv5\" stroke=\"#333\"/><text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"11\">%s</text>\n",
                    x, bar_y + 12, x, bar_y + 28, number_text(v).c_str());
      out << buf;
    }
  }
  const double lx = bar_x + bar_w + 30;
  std::snprintf(buf, sizeof buf, "<rect x=\"%.1f\" y=\"%.1f\" width=\"18\" height=\"12\" fill=\"%s\" stroke=\"#555\" stroke-width=\"0.6\"/>"
                "<text x=\"%.1f\" y=\"%.1f\">unreachable</text>\n", lx, bar_y, hex_colour(unreachable_colour()).c_str(), lx + 24, bar_y + 10);
  out << buf;
  std::snprintf(buf, sizeof buf, "<path class=\"p\" d=\"M%.1f %.1fh24\"/><path class=\"q\" d=\"M%.1f %.1fh24\"/>"
                "<text x=\"%.1f\" y=\"%.1f\">shortest path (dashed: hidden)</text>\n", lx + 115, bar_y + 3, lx + 115, bar_y + 11, lx + 145, bar_y + 10);
  out << buf;
  std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"6\" fill=\"#fff\" stroke=\"#000\" stroke-width=\"2\"/><circle cx=\"%.1f\" cy=\"%.1f\" r=\"2.3\"/>"
                "<text x=\"%.1f\" y=\"%.1f\">source</text>\n", lx + 345, bar_y + 6, lx + 345, bar_y + 6, lx + 357, bar_y + 10);
  out << buf;
  out << "</g>\n";
  for(std::size_t i = 0; i < pic.caption_lines.size(); ++i)
    out << "<text x=\"" << bar_x << "\" y=\"" << legend_top + 62 + 19 * double(i) << "\" font-size=\"13\">" << xml_escape(pic.caption_lines[i]) << "</text>\n";
  out << "</svg>\n";
  svg_file.commit();
}


} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESIC_RENDER_H
