// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Variational_minimization/IO/write_curve_svg.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace VM = CGAL::Variational_minimization;

namespace {

std::size_t count_occurrences(const std::string& text, const std::string& pattern)
{
  std::size_t n = 0;
  for(std::size_t pos = text.find(pattern); pos != std::string::npos; pos = text.find(pattern, pos + 1))
    ++n;
  return n;
}

// Minimal well-formedness check: every start tag is closed in order, self-closing tags and the XML
// declaration are skipped, attribute values are quoted, and no raw '<' or '&' hides in text.
bool tags_are_balanced(const std::string& svg, std::string& problem)
{
  std::vector<std::string> stack;
  std::size_t pos = 0;
  while(true) {
    const std::size_t lt = svg.find('<', pos);
    const std::string text = svg.substr(pos, lt == std::string::npos ? std::string::npos : lt - pos);
    for(std::size_t amp = text.find('&'); amp != std::string::npos; amp = text.find('&', amp + 1)) {
      const std::size_t semi = text.find(';', amp);
      if(semi == std::string::npos || semi - amp > 6) {
        problem = "unescaped & in text";
        return false;
      }
    }
    if(lt == std::string::npos)
      break;
    std::size_t gt = lt + 1;
    bool in_quotes = false;
    for(; gt < svg.size(); ++gt) {
      if(svg[gt] == '"')
        in_quotes = !in_quotes;
      else if(!in_quotes && svg[gt] == '<') {
        problem = "'<' inside a tag";
        return false;
      } else if(!in_quotes && svg[gt] == '>')
        break;
    }
    if(gt == svg.size()) {
      problem = "unterminated tag";
      return false;
    }
    const std::string tag = svg.substr(lt + 1, gt - lt - 1);
    pos = gt + 1;
    if(tag.empty()) {
      problem = "empty tag";
      return false;
    }
    if(tag[0] == '?' || tag[0] == '!')
      continue;
    if(tag[0] == '/') {
      if(stack.empty() || stack.back() != tag.substr(1)) {
        problem = "mismatched </" + tag.substr(1) + ">";
        return false;
      }
      stack.pop_back();
      continue;
    }
    if(tag.back() == '/')
      continue;
    stack.push_back(tag.substr(0, tag.find_first_of(" \n\t")));
  }
  if(!stack.empty()) {
    problem = "unclosed <" + stack.back() + ">";
    return false;
  }
  return true;
}

// The "points" attribute of the n-th <polyline>, as numbers.
std::vector<double> polyline_points(const std::string& svg, std::size_t n)
{
  std::size_t pos = 0;
  for(std::size_t i = 0; i <= n; ++i)
    pos = svg.find("<polyline", pos + (i ? 1 : 0));
  const std::size_t start = svg.find("points=\"", pos) + 8;
  std::string list = svg.substr(start, svg.find('"', start) - start);
  for(char& c : list)
    if(c == ',')
      c = ' ';
  std::istringstream is(list);
  return std::vector<double>(std::istream_iterator<double>(is), std::istream_iterator<double>());
}

VM::Svg_curve_plot sample_plot(std::size_t n_grid)
{
  VM::Svg_curve_plot plot;
  plot.xmin = -1;
  plot.xmax = 1;
  plot.ymin = 0;
  plot.ymax = 2;
  plot.title = "Surface of rotation, R = 2";
  plot.caption_lines = {"energy 23.97 (analytic 23.967188)", "lines: 40"};
  for(std::size_t i = 0; i < n_grid; ++i) {
    const double t = double(i) / double(n_grid);
    plot.grid_segments.push_back({-1, 2 * t, 1, 2 - 2 * t});
  }
  plot.solution = {{-1, 2}, {0, 1.7}, {1, 2}};
  for(int i = 0; i <= 20; ++i) {
    const double x = -1 + i / 10.0;
    plot.analytic.push_back({x, 1.69667587619 * std::cosh(x / 1.69667587619)});
  }
  plot.extra_curves.push_back({{{-1, 2}, {-0.5, 1.8}, {0.5, 1.8}, {1, 2}}, "local descent", "#e7298a", false});
  return plot;
}

} // namespace

TEST_CASE("write_curve_svg: structure and counts", "[Variational_minimization][svg]")
{
  const VM::Svg_curve_plot plot = sample_plot(100);
  std::ostringstream os;
  VM::write_curve_svg(os, plot);
  const std::string svg = os.str();
  std::string problem;
  const bool balanced = tags_are_balanced(svg, problem);
  INFO(problem);
  CHECK(balanced);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"") != std::string::npos);
  CHECK(count_occurrences(svg, "<line ") == 100);
  CHECK(count_occurrences(svg, "<polyline ") == 3); // analytic, extra, solution
  CHECK(count_occurrences(svg, "stroke-dasharray") == 2); // analytic curve and its legend sample
  CHECK(svg.find("local descent") != std::string::npos);
  CHECK(svg.find("analytic solution") != std::string::npos);
  CHECK(svg.find("discrete minimum") != std::string::npos);
  CHECK(svg.find("energy 23.97 (analytic 23.967188)") != std::string::npos);
  CHECK(svg.find("subsample") == std::string::npos);
  // Axis labels carry the box extents.
  CHECK(svg.find(">-1</text>") != std::string::npos);
  CHECK(svg.find(">2</text>") != std::string::npos);
}

TEST_CASE("write_curve_svg: large grids are subsampled and the caption says so", "[Variational_minimization][svg]")
{
  VM::Svg_curve_plot plot = sample_plot(1000);
  plot.max_grid_segments = 30;
  std::ostringstream first, second;
  VM::write_curve_svg(first, plot);
  VM::write_curve_svg(second, plot);
  CHECK(first.str() == second.str()); // deterministic
  CHECK(count_occurrences(first.str(), "<line ") == 30);
  CHECK(first.str().find("grid: 30 of 1000 segments drawn") != std::string::npos);
  std::string problem;
  CHECK(tags_are_balanced(first.str(), problem));

  plot.max_grid_segments = 0;
  std::ostringstream none;
  VM::write_curve_svg(none, plot);
  CHECK(count_occurrences(none.str(), "<line ") == 0);
  CHECK(none.str().find("grid: 0 of 1000 segments drawn") != std::string::npos);
}

TEST_CASE("write_curve_svg: the y axis points up", "[Variational_minimization][svg]")
{
  VM::Svg_curve_plot plot;
  plot.xmin = 0;
  plot.xmax = 4;
  plot.ymin = -1;
  plot.ymax = 1;
  plot.width = 500;
  plot.height = 300;
  plot.margin = 50;
  plot.preserve_aspect_ratio = false;
  plot.solution = {{0, -1}, {4, 1}, {2, 0}};
  std::ostringstream os;
  VM::write_curve_svg(os, plot);
  // No title, no caption: the plot area is [50, 450] x [50, 250].
  const std::vector<double> p = polyline_points(os.str(), 0);
  REQUIRE(p.size() == 6);
  CHECK(p[0] == Approx(50));  // (xmin, ymin) -> bottom left
  CHECK(p[1] == Approx(250));
  CHECK(p[2] == Approx(450)); // (xmax, ymax) -> top right
  CHECK(p[3] == Approx(50));
  CHECK(p[4] == Approx(250)); // centre
  CHECK(p[5] == Approx(150));

  // With equal scales the 4 x 2 box fits the width, centred vertically: scale 100 px per unit.
  plot.preserve_aspect_ratio = true;
  std::ostringstream equal;
  VM::write_curve_svg(equal, plot);
  const std::vector<double> q = polyline_points(equal.str(), 0);
  REQUIRE(q.size() == 6);
  CHECK(q[2] - q[0] == Approx(400));
  CHECK(q[1] - q[3] == Approx(200));
  CHECK(q[5] == Approx(150));
}

TEST_CASE("write_curve_svg: text is escaped and numbers ignore the stream locale", "[Variational_minimization][svg]")
{
  VM::Svg_curve_plot plot = sample_plot(5);
  plot.title = "a < b & \"c\"";
  plot.extra_curves[0].label = "<script>";
  std::ostringstream os;
  VM::write_curve_svg(os, plot);
  const std::string svg = os.str();
  CHECK(svg.find("a &lt; b &amp; &quot;c&quot;") != std::string::npos);
  CHECK(svg.find("&lt;script&gt;") != std::string::npos);
  CHECK(svg.find("<script>") == std::string::npos);
  std::string problem;
  CHECK(tags_are_balanced(svg, problem));

  // A stream with a decimal comma and digit grouping gets the same bytes.
  struct Comma_numpunct : std::numpunct<char>
  {
    char do_decimal_point() const override { return ','; }
    char do_thousands_sep() const override { return '.'; }
    std::string do_grouping() const override { return "\3"; }
  };
  std::ostringstream localized;
  localized.imbue(std::locale(std::locale::classic(), new Comma_numpunct));
  VM::write_curve_svg(localized, plot);
  CHECK(localized.str() == svg);
}

TEST_CASE("write_curve_svg: files and errors", "[Variational_minimization][svg]")
{
  const VM::Svg_curve_plot plot = sample_plot(10);
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "mdcs_test_write_curve_svg.svg";
  VM::write_curve_svg(path.string(), plot);
  std::ifstream in(path);
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ostringstream os;
  VM::write_curve_svg(os, plot);
  CHECK(content == os.str());
  in.close();
  std::filesystem::remove(path);

  CHECK_THROWS_AS(VM::write_curve_svg("/nonexistent-mdcs-directory/out.svg", plot), std::runtime_error);

  VM::Svg_curve_plot bad = plot;
  bad.xmax = bad.xmin;
  CHECK_THROWS_AS(VM::write_curve_svg(os, bad), std::invalid_argument);
  bad = plot;
  bad.solution.push_back({0, std::numeric_limits<double>::quiet_NaN()});
  CHECK_THROWS_AS(VM::write_curve_svg(os, bad), std::invalid_argument);
  bad = plot;
  bad.width = 50;
  CHECK_THROWS_AS(VM::write_curve_svg(os, bad), std::invalid_argument);
}
