// The minimal-surface section of `mdcs demo` (cmd_demo.h).
#include "demo_sections.h"
#include "cmd_surface.h"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace mdcs_cli {

// Part of `mdcs demo`: writes its pictures and files into folder, appends a section to the summary md;
// returns false when one of its consistency checks failed.
bool demo_surface(const std::filesystem::path& folder, bool quick, const Progress_bar& progress, std::ostream& md)
{
  bool ok = true;
  md << "\n## Minimal surfaces (bivariate problems)\n\nEach surface is the min-cut of the directed dual graph of a random "
        "plane arrangement (BSP complex with exact predicates); the cut value must equal the surface energy and the "
        "surface must be single-valued over the domain.\n\n"
        "| problem | planes | cells | discrete energy | cut gap | relaxed | exact | time (s) | picture |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  struct Demo { const char* problem; long planes; long selection; bool relax; const char* domain; };
  const std::vector<Demo> runs = quick ? std::vector<Demo>{{"saddle", 60, 1, false, ""}, {"scherk", 60, 1, true, ""},
                                                           {"saddle", 60, 1, false, "L"}}
                                       : std::vector<Demo>{{"saddle", 120, 1, true, ""}, {"membrane", 120, 1, false, ""},
                                                           {"scherk", 140, 1, true, ""}, {"blobs", 90, 3, true, ""},
                                                           {"saddle", 120, 1, true, "L"}};
  std::ostringstream hist;
  for(const Demo& d : runs) {
    Surface_settings s;
    s.problem = d.problem;
    s.planes = d.planes;
    s.plane_selection = d.selection;
    s.relax = d.relax;
    s.domain = d.domain;
    if(std::string(d.problem) == "blobs") s.descents = 8; // the histogram of Table 2.3, at a small size
    s.output = folder.string();
    s.name = std::string("surface_") + d.problem + (s.domain.empty() ? "" : "_" + s.domain);
    const Surface_run r = run_surface(s, progress);
    std::cout << "== surface " << d.problem << "\n" << r.summary << "\n";
    if(!r.surface.is_feasible) {
      ok = false;
      md << "| " << d.problem << " | " << d.planes << " | " << r.cells << " | INFEASIBLE | | | | | |\n";
      continue;
    }
    const double gap = std::abs(r.surface.energy - r.surface.solver_value) / r.surface.energy;
    const double single = std::abs(r.surface.projected_area - r.problem.domain_area()) / r.problem.domain_area();
    if(gap > 1e-9 || single > 1e-9) ok = false;
    std::ostringstream row;
    row << std::setprecision(8) << "| " << d.problem << (s.domain.empty() ? "" : " (" + s.domain + "-shaped domain)") << (d.selection > 1 ? " (plane selection x" + std::to_string(d.selection) + ")" : "")
        << " | " << d.planes << " | " << r.cells << " | " << r.surface.energy << " | " << std::setprecision(2) << gap
        << " | " << std::setprecision(8);
    if(r.has_relaxed) row << r.relaxed.energy;
    else row << "-";
    row << " | ";
    if(std::isfinite(r.exact)) row << r.exact;
    else row << "-";
    row << " | " << std::setprecision(3) << r.seconds_total << " | [" << s.name << ".svg](" << s.name << ".svg) |\n";
    md << row.str();
    if(!r.histogram_svg.empty()) {
      std::size_t lower = 0;
      for(double e : r.descent_energies) lower += descent_is_lower(e, r.global_descent_energy) ? 1 : 0;
      hist << "\nBlob problem (thesis Table 2.3 as a plot): " << r.descent_energies.size()
           << " local descents from random smooth starts against the global result, all relaxed on 20^2, 40^2 grids: "
           << lower << " of them end lower than the global result. [" << s.name << "_histogram.svg](" << s.name
           << "_histogram.svg)\n";
    }
  }
  md << hist.str();
  return ok;
}

} // namespace mdcs_cli

