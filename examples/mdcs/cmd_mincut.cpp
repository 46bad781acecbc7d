// `mdcs mincut`: its option table and its run (the DIMACS reading and the solve are in cmd_mincut.h).
#include "cmd_mincut.h"
#include "commands.h"

#include <cmath>
#include <iostream>

namespace mdcs_cli {

Command_spec mincut_spec()
{
  Command_spec s;
  s.name = "mincut";
  s.synopsis = "FILE [options]";
  s.description =
    "Reads a max-flow problem in DIMACS format ('p max N M', 'n ID s', 'n ID t', 'a U V CAP', 'c' comments),\n"
    "computes the maximum flow / minimum cut with the Min_cut component and prints the value and the size of the\n"
    "source side. The file is checked line by line (one 'p' line first, one source, one sink, node ids in 1..N,\n"
    "finite capacities >= 0, exactly M arcs): any problem exits 3 with the line and the reason.\n";
  s.positionals = {{"FILE", "a DIMACS max-flow file"}};
  s.min_positionals = s.max_positionals = 1;
  s.options = {
    text_option("engine", "E", "pf", "max-flow engine: pf (pseudoflow), pr (push-relabel) or bk (Boykov-Kolmogorov;\n"
                                     "Boost.Graph, 32-bit CSR)", {"pf", "pr", "bk"}),
    text_option("sides", "OUT", "", "write 'ID S' (source side) or 'ID T' for every node that a line of the file\n"
                "mentions; nodes no line mentions are isolated and on the sink side: a first line\n"
                "'c ...' counts them"),
  };
  add_common_options(s, Common_options{"", true, false});
  s.notes = "With --output DIR: DIR/summary.json (the value, the counts, the engine, the times) and DIR/sides.txt\n"
            "(as --sides).\n";
  return s;
}

namespace {

void write_sides(const std::string& path, const Mincut_report& r)
{
  Output_file out(path);
  // Nodes that no line of the file mentions are isolated, on the sink side, and not listed (see Mincut_report).
  if(r.sides.size() < r.nodes)
    out << "c " << r.nodes - r.sides.size() << " of the " << r.nodes << " nodes appear in no line of the input: they are "
        << "isolated, on the sink side (T), and not listed\n";
  for(const auto& side : r.sides) out << side.first << (side.second ? " S\n" : " T\n");
  out.commit();
}

} // namespace

int run_mincut_command(Invocation& run)
{
  const Parsed_options& o = run.options;
  const std::string engine = o.text("engine"), sides = o.text("sides"), file = o.positional().front();
  run.progress.begin("max-flow");
  const Mincut_report r = solve_dimacs_file(file, engine);
  run.progress.end();
  if(!std::isfinite(r.value) || r.value < 0)
    throw Result_error("the max-flow engine returned the value " + std::to_string(r.value) + " (not a finite number >= 0)");
  const char* engine_name = engine == "bk" ? "Boykov-Kolmogorov" : engine == "pr" ? "push-relabel" : "pseudoflow";
  std::cout.precision(12);
  std::cout << "max flow = min cut = " << r.value << "\n"
            << "nodes " << r.nodes << ", arcs " << r.arcs << ", source side " << r.source_side << " nodes\n"
            << "engine " << engine_name << ", " << r.seconds << " s\n";
  if(!sides.empty()) write_sides(sides, r);
  if(o.given("output")) {
    const std::filesystem::path folder = prepare_output_folder(o.text("output"));
    Run_summary_json json;
    const std::string sides_file = (folder / "sides.txt").string();
    write_sides(sides_file, r);
    json.files.push_back(sides_file);
    if(!sides.empty()) json.files.push_back(sides);
    json.inputs.add("file", file).add("nodes", (unsigned long long)r.nodes).add("arcs", (unsigned long long)r.arcs);
    json.timings.add("max_flow", r.seconds);
    json.results.add("max_flow", r.value).add("source_side_nodes", (unsigned long long)r.source_side).add("engine", engine_name);
    json.write((folder / "summary.json").string(), run, EXIT_OK);
    std::cout << "files: " << (folder / "summary.json").string() << ", " << sides_file << "\n";
  }
  return EXIT_OK;
}

} // namespace mdcs_cli
