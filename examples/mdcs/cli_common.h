// Shared pieces of the mdcs command-line tool: errors with exit codes, the options every sub-command has
// (--output, --no-picture, --threads, --quiet, --heartbeat, --help, --version), the thread limit, and the
// machine-readable summary (summary.json) every run writes.
#ifndef MDCS_CLI_COMMON_H
#define MDCS_CLI_COMMON_H

#include "cli_json.h"
#include "cli_options.h"
#include "cli_output.h"
#include "cli_progress.h"

#include <CGAL/MDCS/concurrency.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef MDCS_VERSION
#define MDCS_VERSION "unknown"
#endif

namespace mdcs_cli {

inline const char* mdcs_version() { return MDCS_VERSION; }

// A malformed or unusable input file or input data: exit code 3.
struct Input_error : std::runtime_error { using std::runtime_error::runtime_error; };

// A result that failed its check before it was reported (non-finite, absurd): exit code 1.
struct Result_error : std::runtime_error { using std::runtime_error::runtime_error; };

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// ------------------------------------------------------------------------------------------------------------
// Options shared by the sub-commands, appended to each table.

struct Common_options
{
  std::string output_default; // "": the command has no output folder unless --output is given
  bool output = true;         // the command has --output
  bool picture = true;        // the command draws pictures (--no-picture)
};

inline void add_common_options(Command_spec& spec, const Common_options& c)
{
  if(c.output)
    spec.options.push_back(text_option("output", "DIR", c.output_default,
                                       c.output_default.empty() ? "also write the output files, summary.json included, into DIR"
                                                                : "output folder (created if needed)"));
  if(c.picture)
    spec.options.push_back(flag_option("no-picture", "write no SVG / PNG picture (the data files only; large meshes draw slowly)"));
  spec.options.push_back(integer_option("threads", "N", "0", 0, 1024,
                                        "threads for the parallel stages (0: every hardware thread; 1: sequential)"));
  spec.options.push_back(flag_option("quiet", "no progress lines on stderr (results, warnings and errors are still printed)"));
  spec.options.push_back(real_option("heartbeat", "S", "10", 0.1, 86400,
                                     "seconds between progress lines when stderr is not a terminal (logs)"));
  spec.options.push_back(flag_option("help", "this help"));
  spec.options.push_back(flag_option("version", "the version of mdcs"));
}

// ------------------------------------------------------------------------------------------------------------
// The thread count of a run (--threads): the limit holds for every TBB loop of the process, the library's
// (CGAL/MDCS/concurrency.h) and CGAL's own; the count is also passed to the entry points that take one.

class Thread_limit
{
public:
  explicit Thread_limit(std::size_t requested)
    : requested_(requested), used_(CGAL::MDCS::effective_threads(requested, true))
  {
#ifdef CGAL_LINKED_WITH_TBB
    control_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, used_);
#endif
  }
  std::size_t requested() const { return requested_; }
  std::size_t used() const { return used_; }
  static constexpr bool parallel() { return CGAL::MDCS::has_parallel_support(); }

private:
  std::size_t requested_, used_;
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> control_;
#endif
};

inline std::string threads_text(const Thread_limit& t)
{
  return std::to_string(t.used()) + (t.requested() == 0 ? " (--threads 0: every hardware thread)" : "") +
         (Thread_limit::parallel() ? "" : " (built without TBB: sequential)");
}

// ------------------------------------------------------------------------------------------------------------
// One run of a sub-command: its options, thread limit, progress display, and what goes into summary.json.

struct Invocation
{
  Invocation(const Command_spec& spec, int argc, char** argv, int first)
    : command(spec.name), options(parse_command_line(spec, argc, argv, first)),
      threads(std::size_t(options.integer("threads"))),
      progress(options.flag("quiet"), options.real("heartbeat")), start(std::chrono::steady_clock::now())
  {
    for(int i = first; i < argc; ++i) arguments.push_back(argv[i]);
  }

  bool quiet() const { return options.flag("quiet"); }
  bool picture() const { return !options.flag("no-picture"); }

  std::string command;
  std::vector<std::string> arguments;
  Parsed_options options;
  Thread_limit threads;
  Progress_bar progress;
  std::chrono::steady_clock::time_point start;
};

// summary.json: what ran (command, version, arguments, every option's effective value, threads), on what
// (inputs), how long (timings, seconds), what came out (results), notes and the files written.
struct Run_summary_json
{
  Json_object inputs, timings, results;
  std::vector<std::string> notes, files;

  std::string text(const Invocation& run, int exit_code) const
  {
    Json_object o, opts, threads;
    o.add("command", run.command).add("version", std::string(mdcs_version())).raw("arguments", json_strings(run.arguments));
    // Typed: flags as booleans, integers and reals as numbers, lists as arrays of numbers, the rest as strings.
    for(const auto& v : run.options.effective()) {
      if(v.kind == Option_kind::flag || v.kind == Option_kind::integer || v.kind == Option_kind::real) opts.raw(v.name, v.text);
      else if(v.kind == Option_kind::list) opts.raw(v.name, json_numbers(run.options.list(v.name)));
      else opts.add(v.name, v.text);
    }
    o.add("options", opts);
    threads.add("requested", (unsigned long long)run.threads.requested()).add("used", (unsigned long long)run.threads.used())
      .add("parallel_support", Thread_limit::parallel());
    o.add("threads", threads);
    o.add("inputs", inputs);
    Json_object t = timings;
    t.add("total", seconds_since(run.start));
    o.add("timings_seconds", t);
    o.add("results", results);
    o.raw("notes", json_strings(notes));
    o.raw("files", json_strings(files));
    o.add("exit_code", exit_code);
    return o.text() + "\n";
  }

  // Writes `path` (listed among the files first).
  void write(const std::string& path, const Invocation& run, int exit_code)
  {
    files.push_back(path);
    write_text_file(path, text(run, exit_code));
  }
};

} // namespace mdcs_cli

#endif // MDCS_CLI_COMMON_H
