// `mdcs mwt`: its option table and its run (the points, the outputs and the report are in cmd_mwt.h).
#include "cmd_mwt.h"
#include "commands.h"

#include <iostream>

namespace mdcs_cli {

Command_spec mwt_spec()
{
  Command_spec s;
  s.name = "mwt";
  s.synopsis = "POINTS | --random N | --wheel K  [options]";
  s.description =
    "Minimum weight triangulation by the triangle-based LP (diamond-test pruning, certificate, branch and bound when\n"
    "the LP optimum is fractional), or by the LMT-skeleton pipeline (--lmt).\n";
  s.positionals = {{"POINTS", "text file, one point per line: 'x y', 'x,y' or 'x;y' (finite numbers), '#' comments, blank\n"
                              "lines, an optional first line of words ('x,y'); anything else exits 3 with the line"}};
  s.min_positionals = 0;
  s.max_positionals = 1;
  s.options = {
    integer_option("random", "N", "", 3, 1e8, "N random points (see --distribution, --seed; 10^6 points take about 1.1 GB\n"
                   "with --lmt, 10^7 about 11 GB)"),
    integer_option("wheel", "K", "", 3, 100000, "a centre and K points on the unit circle (odd K: fractional LP)"),
    text_option("distribution", "D", "uniform", "uniform, clustered or normal (with --random)", {"uniform", "clustered", "normal"}),
    integer_option("seed", "S", "1", 0, 4294967295.0, "random seed (with --random)"),
    text_option("solver", "S", "clp", "clp (dual simplex), glpk, exact (GLPK + rational verification), qp (CGAL's exact\n"
                "QP_solver: the LP optimum in rational arithmetic; small inputs only, see --qp-max-columns)",
                {"clp", "glpk", "exact", "qp"}),
    integer_option("qp-max-columns", "N", std::to_string(mwt_detail::MWT::Mwt_options().qp_max_columns), 0, 1e9,
                   "with --solver qp: refuse an LP of more than N columns (empty\n"
                   "triangles) before solving it, exit code 1 (0: no limit). QP_solver cannot be interrupted once\n"
                   "started and its time grows about like the cube of the columns: 550 took up to 31 s, the\n"
                   "default up to about 45 s (extrapolated; the LP size is in the report)"),
    text_option("metric", "M", "L2", "L2, L1 or Linf (L1/Linf: no pruning, small inputs only)", {"L2", "L1", "Linf"}),
    flag_option("no-pruning", "use every segment as a candidate edge (O(n^3) triangles)"),
    flag_option("lp-only", "do not resolve a fractional LP optimum by branch and bound"),
    real_option("time-limit", "S", "", 0, 1e7, "seconds (wall clock) for the LP solve and, separately, for the branch and bound\n"
                "of a fractional optimum (0: none; not given: no limit on the LP, 300 s on branch and\n"
                "bound); at the LP's limit: status time_limit_reached, no triangulation, exit code 1. With\n"
                "--solver qp only branch and bound is limited: QP_solver's LP solve cannot be stopped\n"
                "(--qp-max-columns bounds it instead)"),
    flag_option("lmt", "LMT-skeleton + dynamic program on its faces, the LP only for the rest (L2 only)"),
  };
  add_common_options(s, Common_options{"mwt_output", true, true});
  s.notes =
    "Files in the output folder: mwt.off (the triangulation), mwt_edges.csv (i,j,length,xi,yi,xj,yj; 17 significant\n"
    "digits), mwt.svg/.png (not with --no-picture), report.txt, summary.json.\n"
    "Exit code 1 also when no triangulation was found: the LP solver failed (solver_failed), stopped at --time-limit\n"
    "(time_limit_reached), or branch and bound ran out of time on a fractional optimum (fractional_bound_only; with\n"
    "--lp-only that status is the answer asked for, exit code 0), or --solver qp refused an LP larger than\n"
    "--qp-max-columns (the message gives its size; no output files). The report says why.\n";
  return s;
}

int run_mwt_command(Invocation& run)
{
  using namespace mwt_detail;
  const Parsed_options& o = run.options;
  const int sources = int(o.given("random")) + int(o.given("wheel")) + int(!o.positional().empty());
  if(sources != 1) throw Usage_error("give exactly one of POINTS, --random N, --wheel K");
  if(!o.given("random") && (o.given("distribution") || o.given("seed")))
    throw Usage_error("--distribution and --seed apply to --random only");
  MWT::Mwt_options opt;
  const std::string solver = o.text("solver"), metric = o.text("metric");
  opt.solver = solver == "glpk" ? MWT::Lp_solver_choice::glpk : solver == "exact" ? MWT::Lp_solver_choice::exact
              : solver == "qp" ? MWT::Lp_solver_choice::qp_solver : MWT::Lp_solver_choice::clp;
  if(o.given("qp-max-columns") && solver != "qp") throw Usage_error("--qp-max-columns applies to --solver qp only");
  opt.qp_max_columns = std::size_t(o.integer("qp-max-columns"));
  if(!MWT::has_lp_solver(opt.solver)) throw std::runtime_error("the solver '" + solver + "' is not built in");
  opt.metric = metric == "L1" ? MWT::Edge_metric::L1 : metric == "Linf" ? MWT::Edge_metric::Linf : MWT::Edge_metric::L2;
  if(o.flag("lmt") && metric != "L2") throw Usage_error("--lmt needs --metric L2");
  if(o.flag("no-pruning")) opt.pruning = MWT::Pruning::none;
  opt.resolve_fractional = !o.flag("lp-only");
  opt.use_lmt_skeleton = o.flag("lmt");
  if(o.given("time-limit")) {
    opt.lp_time_limit = o.real("time-limit");
    opt.branch_and_bound_time_limit = o.real("time-limit");
  }
  const Progress_bar& bar = run.progress;
  opt.progress = [bar](const char* stage, double f) { return bar(stage, f); };

  const auto t_read = std::chrono::steady_clock::now();
  const std::vector<Point> p = o.given("random") ? random_points(long(o.integer("random")), o.text("distribution"), unsigned(o.integer("seed")))
                               : o.given("wheel") ? wheel(long(o.integer("wheel")))
                                                  : read_points(o.positional().front());
  const double seconds_read = seconds_since(t_read);
  const auto folder = prepare_output_folder(o.text("output"));
  const MWT::Mwt_result r = [&] {
    try {
      return MWT::minimum_weight_triangulation_2(p, opt);
    } catch(const MWT::Linear_program_too_large& e) {   // exit code 1, with the option that raises the limit
      throw std::runtime_error(std::string(e.what()) + " (--qp-max-columns " + std::to_string(e.limit()) + ")");
    }
  }();
  check_mwt_result(r);
  const std::string text = report(r) + "threads           " + threads_text(run.threads) + "\n";
  std::cout << text;
  Run_summary_json json;
  json.files.push_back((folder / "report.txt").string());
  write_text_file(json.files.back(), text);
  if(r.has_triangulation()) {
    run.progress.begin("writing the outputs");
    for(const std::string& f : write_outputs(folder, "mwt", p, r, run.picture())) json.files.push_back(f);
    run.progress.end();
    std::cout << "wrote " << (folder / "mwt.off").string() << ", mwt_edges.csv" << (run.picture() ? ", mwt.svg" : "") << "\n";
  }
  // No triangulation although one was asked for: a runtime failure, never a success.
  const bool failed = r.status == MWT::Mwt_status::solver_failed || r.status == MWT::Mwt_status::time_limit_reached ||
                      (r.status == MWT::Mwt_status::fractional_bound_only && opt.resolve_fractional);
  const int code = failed ? EXIT_FAILURE_RUNTIME : EXIT_OK;
  const auto& st = r.statistics;
  json.inputs.add("points", o.given("random") ? "random " + o.text("distribution") + " " + std::to_string(o.integer("random"))
                            : o.given("wheel") ? "wheel " + std::to_string(o.integer("wheel")) : o.positional().front())
    .add("count", (unsigned long long)st.points).add("hull_points", (unsigned long long)st.hull_points);
  json.timings.add("read", seconds_read).add("setup", st.time_setup).add("candidates", st.time_candidates)
    .add("triangles", st.time_triangles).add("lp_build", st.time_lp_build).add("lp_solve", st.time_lp_solve)
    .add("certificate", st.time_certificate).add("branch_and_bound", st.time_branch_and_bound).add("lmt", st.time_lmt)
    .add("face_dp", st.time_face_dp).add("mwt_total", st.time_total);
  json.results.add("status", std::string(MWT::to_string(r.status))).add("message", r.message).add("weight", r.weight)
    .add("lower_bound", r.lower_bound).add("lp_objective", r.lp_objective).add("lp_integral", r.lp_integral)
    .add("lp_exact", r.lp_exact).add("certificate_exact", r.certificate_exact)
    .add("certificate_support", (unsigned long long)r.certificate_support).add("solver", r.solver)
    .add("triangles", (unsigned long long)r.triangles.size()).add("candidate_edges", (unsigned long long)st.candidate_edges)
    .add("empty_triangles", (unsigned long long)st.empty_triangles).add("lp_columns", (unsigned long long)st.lp_columns)
    .add("lp_rows", (unsigned long long)st.lp_rows);
  if(r.has_triangulation()) json.results.add("edges_csv", (folder / "mwt_edges.csv").string());
  json.notes.push_back("lower_bound null: no bound was computed; lp_objective null: no LP was solved (the LMT pipeline solved every face)");
  json.write((folder / "summary.json").string(), run, code);
  return code;
}

} // namespace mdcs_cli
