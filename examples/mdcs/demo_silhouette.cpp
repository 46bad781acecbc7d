// The silhouette section of `mdcs demo` (cmd_demo.h).
#include "demo_sections.h"
#include "cmd_silhouette.h"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <string>

namespace mdcs_cli {

// Part of `mdcs demo`: writes its pictures and files into folder, appends a section to the summary md;
// returns false when one of its consistency checks failed.
bool demo_silhouette(const std::filesystem::path& folder, bool quick, const Progress_bar& progress, std::ostream& md)
{
  using namespace sil_detail;
  const std::string dir = MDCS_CGAL_MESH_DIR;
  Mesh fine;
  Run_parameters p;
  bool generated = false;
  const std::string name = quick ? "elephant.off" : "bunny00.off";
  bool read = false;
  if(!dir.empty()) {
    try {
      std::vector<std::string> notes;
      load_geodesics_mesh(dir + "/" + name, fine, notes);
      read = num_faces(fine) > 0;
    } catch(const Input_error&) {
      read = false;
    }
  }
  if(read) {
    p.name = name;
    if(!quick) {
      // The thesis's setting: a 20,000-face bunny and a 1,000-face coarse mesh.
      SS::Coarse_mesh_options o;
      o.target_faces = 20000;
      o.smoothing_iterations = 0;
      fine = SS::build_coarse_mesh(fine, o).mesh;
      p.name = "bunny00.off simplified to 20k faces";
    }
  } else {
    fine = generated_mesh(quick ? 4 : 5);
    p.name = "generated bumpy sphere";
    generated = true;
  }
  p.coarse_faces = quick ? 500 : 1000;
  p.frames = quick ? 0 : 12;
  p.up = 1;
  const auto sub = folder / "silhouette";
  prepare_output_folder(sub.string());
  const Run_summary s = run_silhouette(fine, p, sub, progress);
  std::cout << "== silhouette simplification\n" << s.report;
  md << "\n## Simplified silhouettes\n\n"
     << p.name << (generated ? " (CGAL's meshes are not installed, so a generated surface is used)" : "") << ": "
     << s.fine_faces << " faces, coarse mesh " << s.coarse_faces << " faces (preprocessing " << std::setprecision(3)
     << s.preprocess_s << " s). One view ([silhouette/silhouette.svg](silhouette/silhouette.svg)):\n\n"
     << "| silhouette | edges | loops | time (ms) |\n|---|---:|---:|---:|\n"
     << "| fine | " << s.fine_edges << " | " << s.fine_loops << " | " << s.extract_ms << " (both meshes) |\n"
     << "| coarse | " << s.coarse_edges << " | " << s.coarse_loops << " | |\n"
     << "| loop picking (A) | " << s.picked_edges << " | " << s.picked_loops << " | " << s.picking_ms << " |\n"
     << "| loop mapping (B, min cut) | " << s.mapped_edges << " | " << s.mapped_loops << " | " << s.mapping_ms << " |\n";
  if(p.frames > 1)
    md << "\nRotation: " << p.frames << " frames (`silhouette/frame_*.svg`). Temporal incoherence (change of the simplified "
       << "silhouette / change of the true one, 0.5 degree steps): picking " << s.incoherence[0] << " (with the previous-frame "
       << "bias " << s.incoherence[1] << "), mapping " << s.incoherence[2] << " (with the bias " << s.incoherence[3] << ").\n";
  md << "\nChecks: every loop closed and made of mesh edges, picked edges on the fine silhouette: "
     << (s.consistent ? "passed" : "FAILED (" + s.problems + ")") << ".\n";
  return s.consistent;
}

} // namespace mdcs_cli

