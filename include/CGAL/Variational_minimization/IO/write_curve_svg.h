// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Standalone SVG pictures of a univariate problem: the grid (arrangement edges), the discrete solution, the
// analytic solution and further curves (e.g. a local-descent result).

#ifndef CGAL_VARIATIONAL_MINIMIZATION_IO_WRITE_CURVE_SVG_H
#define CGAL_VARIATIONAL_MINIMIZATION_IO_WRITE_CURVE_SVG_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <locale>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \defgroup PkgVariationalMinimizationIO SVG output of curves
*/

/*!
  \ingroup PkgVariationalMinimizationIO
  A point of a plotted curve, in problem coordinates (x, f).
*/
struct Svg_point
{
  double x = 0; ///< abscissa
  double y = 0; ///< function value
};

/*!
  \ingroup PkgVariationalMinimizationIO
  A grid segment (e.g. an arrangement edge), in problem coordinates.
*/
struct Svg_segment
{
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0; ///< end points
};

/*!
  \ingroup PkgVariationalMinimizationIO
  An additional curve with its legend entry.
*/
struct Svg_curve
{
  std::vector<Svg_point> points; ///< the polyline, in order
  std::string label;             ///< legend text
  std::string color = "#d95f02"; ///< any SVG colour
  bool dashed = false;           ///< dashed stroke
};

/*!
  \ingroup PkgVariationalMinimizationIO
  Everything `write_curve_svg()` draws.

  The picture's element structure is fixed, so that it can be checked mechanically: every drawn grid segment is
  one `<line>`, every non-empty curve (solution, analytic, extras) is one `<polyline>`; the frame, axes
  and legend samples use `<rect>`, `<path>` and `<text>` only.
*/
struct Svg_curve_plot
{
  /// The box shown, in problem coordinates; needs `xmin < xmax`, `ymin < ymax`.
  double xmin = 0, xmax = 1, ymin = 0, ymax = 1;
  /// Title line above the plot.
  std::string title;
  /// Caption lines below the plot (e.g. energy, number of lines).
  std::vector<std::string> caption_lines;
  /// Faint grid segments; at most `max_grid_segments` are drawn.
  std::vector<Svg_segment> grid_segments;
  /// Cap on the drawn grid segments. When exceeded, a deterministic, evenly spaced subsample (by index) is
  /// drawn and the caption says so. 0 draws none.
  std::size_t max_grid_segments = 20000;
  /// The discrete solution (bold).
  std::vector<Svg_point> solution;
  /// Legend text of the solution.
  std::string solution_label = "discrete minimum";
  /// Optional analytic solution, sampled (dashed); empty: not drawn.
  std::vector<Svg_point> analytic;
  /// Legend text of the analytic curve.
  std::string analytic_label = "analytic solution";
  /// Further curves, each with its own colour and legend entry.
  std::vector<Svg_curve> extra_curves;
  /// Size of the whole picture in pixels.
  double width = 800, height = 640;
  /// Margin around the plot area in pixels (room for labels; title and caption get extra room).
  double margin = 60;
  /// Same scale on both axes (the plot area shrinks in one direction), so slopes look right.
  bool preserve_aspect_ratio = true;
  /// Axis labels.
  std::string x_label = "x", y_label = "f";
  /// Corner of the plot area that holds the legend.
  enum Legend_position { TOP_RIGHT, BOTTOM_RIGHT, TOP_LEFT, BOTTOM_LEFT };
  /// See `Legend_position`.
  Legend_position legend_position = TOP_RIGHT;
};

namespace internal {

inline std::string svg_escape(const std::string& s)
{
  std::string out;
  out.reserve(s.size());
  for(char c : s) {
    switch(c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// Maps problem coordinates to pixels; the y axis is flipped so that f grows upwards.
struct Svg_viewport
{
  double left, top, plot_w, plot_h, xmin, ymax, sx, sy;

  double px(double x) const { return left + (x - xmin) * sx; }
  double py(double y) const { return top + (ymax - y) * sy; }
};

// Title and caption heights, in pixels, added to the margins.
constexpr double svg_line_height = 18;

inline Svg_viewport make_svg_viewport(const Svg_curve_plot& p, std::size_t caption_count)
{
  Svg_viewport v;
  const double top_extra = p.title.empty() ? 0 : svg_line_height;
  const double bottom_extra = svg_line_height * static_cast<double>(caption_count);
  v.left = p.margin;
  v.top = p.margin + top_extra;
  v.plot_w = p.width - 2 * p.margin;
  v.plot_h = p.height - 2 * p.margin - top_extra - bottom_extra;
  if(!(v.plot_w > 0) || !(v.plot_h > 0))
    throw std::invalid_argument("MDCS: write_curve_svg: the picture is too small for its margins and caption");
  v.xmin = p.xmin;
  v.ymax = p.ymax;
  v.sx = v.plot_w / (p.xmax - p.xmin);
  v.sy = v.plot_h / (p.ymax - p.ymin);
  if(p.preserve_aspect_ratio) {
    const double s = std::min(v.sx, v.sy);
    // Centre the shrunk plot area in the available one.
    v.left += 0.5 * (v.plot_w - s * (p.xmax - p.xmin));
    v.top += 0.5 * (v.plot_h - s * (p.ymax - p.ymin));
    v.plot_w = s * (p.xmax - p.xmin);
    v.plot_h = s * (p.ymax - p.ymin);
    v.sx = v.sy = s;
  }
  return v;
}

inline void check_svg_points(const std::vector<Svg_point>& pts, const char* what)
{
  for(const Svg_point& q : pts)
    if(!std::isfinite(q.x) || !std::isfinite(q.y))
      throw std::invalid_argument(std::string("MDCS: write_curve_svg: non-finite point in ") + what);
}

inline void write_svg_polyline(std::ostream& os, const Svg_viewport& v, const std::vector<Svg_point>& pts,
                               const std::string& color, double stroke_width, bool dashed)
{
  os << "<polyline fill=\"none\" stroke=\"" << svg_escape(color) << "\" stroke-width=\"" << stroke_width
     << "\" stroke-linejoin=\"round\"";
  if(dashed)
    os << " stroke-dasharray=\"8,5\"";
  os << " points=\"";
  for(std::size_t i = 0; i < pts.size(); ++i)
    os << (i ? " " : "") << v.px(pts[i].x) << ',' << v.py(pts[i].y);
  os << "\"/>\n";
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationIO
  Writes `plot` as a standalone SVG 1.1 document: the box with its extents as axis labels, the (possibly
  subsampled) grid in light grey, the analytic curve dashed, extra curves in their colours, the solution bold
  on top, a legend, the title and the caption. The y axis points up. Curves are clipped to the box.
  Numbers are written in the classic "C" locale whatever the stream's locale.
  \throws std::invalid_argument if the box is empty or not finite, a point or segment is not finite, or the
  picture is too small for its margins.
*/
inline void write_curve_svg(std::ostream& out, const Svg_curve_plot& plot)
{
  const Svg_curve_plot& p = plot;
  if(!std::isfinite(p.xmin) || !std::isfinite(p.xmax) || !std::isfinite(p.ymin) || !std::isfinite(p.ymax) ||
     !(p.xmin < p.xmax) || !(p.ymin < p.ymax))
    throw std::invalid_argument("MDCS: write_curve_svg: the box must be finite with xmin < xmax, ymin < ymax");
  if(!std::isfinite(p.width) || !std::isfinite(p.height) || !std::isfinite(p.margin) || p.margin < 0)
    throw std::invalid_argument("MDCS: write_curve_svg: width, height and margin must be finite");
  internal::check_svg_points(p.solution, "the solution");
  internal::check_svg_points(p.analytic, "the analytic curve");
  for(const Svg_curve& c : p.extra_curves)
    internal::check_svg_points(c.points, "an extra curve");
  for(const Svg_segment& s : p.grid_segments)
    if(!std::isfinite(s.x0) || !std::isfinite(s.y0) || !std::isfinite(s.x1) || !std::isfinite(s.y1))
      throw std::invalid_argument("MDCS: write_curve_svg: non-finite grid segment");

  // Subsampling indices floor(j * n / cap), j < cap: evenly spread over the input order, reproducible.
  const std::size_t n_grid = p.grid_segments.size();
  const std::size_t n_drawn = std::min(n_grid, p.max_grid_segments);
  std::vector<std::string> caption = p.caption_lines;
  if(n_drawn < n_grid) {
    std::ostringstream c;
    c << "grid: " << n_drawn << " of " << n_grid << " segments drawn (evenly spaced subsample)";
    caption.push_back(c.str());
  }
  const internal::Svg_viewport v = internal::make_svg_viewport(p, caption.size());

  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.setf(std::ios::fixed);
  os.precision(2);

  os << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
     << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << p.width << "\" height=\""
     << p.height << "\" viewBox=\"0 0 " << p.width << ' ' << p.height << "\">\n";
  os << "<title>" << internal::svg_escape(p.title.empty() ? "MDCS curve" : p.title) << "</title>\n";
  os << "<defs><clipPath id=\"mdcs-plot-area\"><rect x=\"" << v.left << "\" y=\"" << v.top << "\" width=\""
     << v.plot_w << "\" height=\"" << v.plot_h << "\"/></clipPath></defs>\n";
  os << "<rect x=\"0\" y=\"0\" width=\"" << p.width << "\" height=\"" << p.height << "\" fill=\"white\"/>\n";

  // Grid.
  os << "<g id=\"grid\" stroke=\"#c8c8c8\" stroke-width=\"0.5\" clip-path=\"url(#mdcs-plot-area)\">\n";
  for(std::size_t j = 0; j < n_drawn; ++j) {
    const std::size_t idx = n_drawn == n_grid
                              ? j
                              : static_cast<std::size_t>((static_cast<long double>(j) * n_grid) / n_drawn);
    const Svg_segment& s = p.grid_segments[idx];
    os << "<line x1=\"" << v.px(s.x0) << "\" y1=\"" << v.py(s.y0) << "\" x2=\"" << v.px(s.x1) << "\" y2=\""
       << v.py(s.y1) << "\"/>\n";
  }
  os << "</g>\n";

  // Frame, and the f = 0 axis when it is inside the box (the axis of rotation in the catenoid problem).
  os << "<rect x=\"" << v.left << "\" y=\"" << v.top << "\" width=\"" << v.plot_w << "\" height=\"" << v.plot_h
     << "\" fill=\"none\" stroke=\"black\" stroke-width=\"1\"/>\n";
  if(p.ymin < 0 && 0 < p.ymax)
    os << "<path d=\"M " << v.left << ' ' << v.py(0) << " H " << v.left + v.plot_w
       << "\" stroke=\"#808080\" stroke-width=\"0.8\" fill=\"none\"/>\n";

  // Curves: extras, analytic, then the solution on top.
  os << "<g id=\"curves\" clip-path=\"url(#mdcs-plot-area)\">\n";
  const std::string solution_color = "#1f3a93", analytic_color = "#000000";
  for(const Svg_curve& c : p.extra_curves)
    if(!c.points.empty())
      internal::write_svg_polyline(os, v, c.points, c.color, 2, c.dashed);
  if(!p.analytic.empty()) // dashed, above the extras so that it stays visible where they coincide
    internal::write_svg_polyline(os, v, p.analytic, analytic_color, 1.5, true);
  if(!p.solution.empty())
    internal::write_svg_polyline(os, v, p.solution, solution_color, 3, false);
  os << "</g>\n";

  // Axis labels: the box extents at the ends of each axis, and the variable names.
  {
    std::ostringstream num;
    num.imbue(std::locale::classic());
    num.precision(6);
    auto label = [&](double value) {
      num.str("");
      num << value;
      return internal::svg_escape(num.str());
    };
    const double bottom = v.top + v.plot_h, right = v.left + v.plot_w;
    os << "<g font-family=\"sans-serif\" font-size=\"12\" fill=\"black\">\n";
    os << "<text x=\"" << v.left << "\" y=\"" << bottom + 16 << "\" text-anchor=\"start\">" << label(p.xmin)
       << "</text>\n";
    os << "<text x=\"" << right << "\" y=\"" << bottom + 16 << "\" text-anchor=\"end\">" << label(p.xmax)
       << "</text>\n";
    os << "<text x=\"" << v.left + 0.5 * v.plot_w << "\" y=\"" << bottom + 16
       << "\" text-anchor=\"middle\" font-style=\"italic\">" << internal::svg_escape(p.x_label) << "</text>\n";
    os << "<text x=\"" << v.left - 6 << "\" y=\"" << bottom << "\" text-anchor=\"end\">" << label(p.ymin)
       << "</text>\n";
    os << "<text x=\"" << v.left - 6 << "\" y=\"" << v.top + 12 << "\" text-anchor=\"end\">" << label(p.ymax)
       << "</text>\n";
    os << "<text x=\"" << v.left - 6 << "\" y=\"" << v.top + 0.5 * v.plot_h
       << "\" text-anchor=\"end\" font-style=\"italic\">" << internal::svg_escape(p.y_label) << "</text>\n";
    os << "</g>\n";
  }

  // Legend, in a corner of the plot area (Svg_curve_plot::legend_position), on a translucent background.
  {
    struct Entry
    {
      std::string label, color;
      double width;
      bool dashed;
    };
    std::vector<Entry> entries;
    if(!p.solution.empty())
      entries.push_back({p.solution_label, solution_color, 3, false});
    if(!p.analytic.empty())
      entries.push_back({p.analytic_label, analytic_color, 1.5, true});
    for(const Svg_curve& c : p.extra_curves)
      if(!c.points.empty())
        entries.push_back({c.label, c.color, 2, c.dashed});
    if(!entries.empty()) {
      // Width from a rough 7 px per character of 12 px sans-serif text.
      std::size_t longest = 0;
      for(const Entry& e : entries)
        longest = std::max(longest, e.label.size());
      const double lw = std::max(120.0, 56 + 7 * static_cast<double>(longest)), lh = 8 + 18 * static_cast<double>(entries.size());
      const bool right = p.legend_position == Svg_curve_plot::TOP_RIGHT || p.legend_position == Svg_curve_plot::BOTTOM_RIGHT;
      const bool top = p.legend_position == Svg_curve_plot::TOP_RIGHT || p.legend_position == Svg_curve_plot::TOP_LEFT;
      const double lx = right ? v.left + v.plot_w - lw - 8 : v.left + 8;
      const double ly = top ? v.top + 8 : v.top + v.plot_h - lh - 8;
      os << "<g id=\"legend\" font-family=\"sans-serif\" font-size=\"12\">\n";
      os << "<rect x=\"" << lx << "\" y=\"" << ly << "\" width=\"" << lw << "\" height=\"" << lh
         << "\" fill=\"white\" fill-opacity=\"0.85\" stroke=\"#808080\" stroke-width=\"0.5\"/>\n";
      for(std::size_t i = 0; i < entries.size(); ++i) {
        const double yy = ly + 16 + 18 * static_cast<double>(i);
        os << "<path d=\"M " << lx + 8 << ' ' << yy - 4 << " h 30\" fill=\"none\" stroke=\""
           << internal::svg_escape(entries[i].color) << "\" stroke-width=\"" << entries[i].width << "\"";
        if(entries[i].dashed)
          os << " stroke-dasharray=\"8,5\"";
        os << "/>\n<text x=\"" << lx + 46 << "\" y=\"" << yy << "\">" << internal::svg_escape(entries[i].label)
           << "</text>\n";
      }
      os << "</g>\n";
    }
  }

  // Title and caption.
  os << "<g font-family=\"sans-serif\" fill=\"black\">\n";
  if(!p.title.empty())
    os << "<text x=\"" << 0.5 * p.width << "\" y=\"" << p.margin * 0.5 + 6
       << "\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">" << internal::svg_escape(p.title)
       << "</text>\n";
  for(std::size_t i = 0; i < caption.size(); ++i)
    os << "<text x=\"" << p.margin << "\" y=\""
       << p.height - p.margin * 0.5 - internal::svg_line_height * static_cast<double>(caption.size() - 1 - i)
       << "\" font-size=\"12\">" << internal::svg_escape(caption[i]) << "</text>\n";
  os << "</g>\n</svg>\n";

  out << os.str();
}

/*!
  \ingroup PkgVariationalMinimizationIO
  Writes `plot` to the file `filename` (see the stream overload).
  \throws std::runtime_error if the file cannot be opened or written.
*/
inline void write_curve_svg(const std::string& filename, const Svg_curve_plot& plot)
{
  std::ofstream file(filename);
  if(!file)
    throw std::runtime_error("MDCS: write_curve_svg: cannot open '" + filename + "' for writing");
  write_curve_svg(file, plot);
  file.flush();
  if(!file)
    throw std::runtime_error("MDCS: write_curve_svg: error while writing '" + filename + "'");
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_IO_WRITE_CURVE_SVG_H
