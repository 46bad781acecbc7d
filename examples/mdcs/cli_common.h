// Shared pieces of the mdcs command-line tool: options, errors with exit codes, the progress bar, output files.
#ifndef MDCS_CLI_COMMON_H
#define MDCS_CLI_COMMON_H

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>
#include <unistd.h>

namespace mdcs_cli {

// Exit codes, documented in `mdcs --help`.
enum Exit_code { EXIT_OK = 0, EXIT_FAILURE_RUNTIME = 1, EXIT_USAGE = 2, EXIT_BAD_INPUT = 3, EXIT_INFEASIBLE = 4 };

// A wrong command line: printed with the command's usage, exit code 2.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

// Options of the form --name value, --name=value and --flag; everything else is positional.
class Options
{
public:
  Options(int argc, char** argv, int first, const std::vector<std::string>& flags)
  {
    for(int i = first; i < argc; ++i) {
      std::string a = argv[i];
      if(a.size() > 2 && a[0] == '-' && a[1] == '-') {
        std::string name = a.substr(2), value;
        const auto eq = name.find('=');
        if(eq != std::string::npos) {
          value = name.substr(eq + 1);
          name = name.substr(0, eq);
        } else if(std::find(flags.begin(), flags.end(), name) != flags.end()) {
          value = "1";
        } else {
          if(i + 1 >= argc) throw Usage_error("option --" + name + " needs a value");
          value = argv[++i];
        }
        values_[name] = value;
      } else if(a == "-h") {
        values_["help"] = "1";
      } else {
        positional_.push_back(a);
      }
    }
  }

  bool has(const std::string& name) const { return values_.count(name) != 0; }

  std::string text(const std::string& name, const std::string& fallback) const
  {
    used_.push_back(name);
    auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
  }

  double number(const std::string& name, double fallback) const
  {
    const std::string s = text(name, "");
    if(s.empty()) return fallback;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if(end == s.c_str() || *end != '\0') throw Usage_error("option --" + name + ": '" + s + "' is not a number");
    return v;
  }

  long integer(const std::string& name, long fallback, long min_value) const
  {
    const std::string s = text(name, "");
    if(s.empty()) return fallback;
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if(end == s.c_str() || *end != '\0') throw Usage_error("option --" + name + ": '" + s + "' is not an integer");
    if(v < min_value) throw Usage_error("option --" + name + " must be >= " + std::to_string(min_value));
    return v;
  }

  const std::vector<std::string>& positional() const { return positional_; }

  // Rejects options that no one asked for (typos), after the command has read its options.
  void reject_unknown() const
  {
    for(const auto& kv : values_)
      if(kv.first != "help" && std::find(used_.begin(), used_.end(), kv.first) == used_.end())
        throw Usage_error("unknown option --" + kv.first);
  }

private:
  std::map<std::string, std::string> values_;
  std::vector<std::string> positional_;
  mutable std::vector<std::string> used_;
};

// A progress bar on stderr: redrawn in place on a terminal, one line per finished stage otherwise (logs, CI).
class Progress_bar
{
public:
  explicit Progress_bar(bool quiet = false) : quiet_(quiet), tty_(isatty(fileno(stderr)) != 0) {}

  bool operator()(const char* stage, double fraction)
  {
    if(quiet_) return true;
    const auto now = std::chrono::steady_clock::now();
    if(stage_ != stage) {
      stage_ = stage;
      start_ = now;
      last_ = -1;
    }
    const int percent = int(fraction * 100.0 + 0.5);
    if(percent == last_) return true;
    last_ = percent;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    if(tty_) {
      const int width = 30, filled = percent * width / 100;
      std::fprintf(stderr, "\r  %-14s [%.*s%*s] %3d%%  %.1fs", stage, filled, "##############################",
                   width - filled, "", percent, seconds);
      if(percent >= 100) std::fprintf(stderr, "\n");
    } else if(percent >= 100) {
      std::fprintf(stderr, "  %-14s done in %.2fs\n", stage, seconds);
    }
    std::fflush(stderr);
    return true;
  }

private:
  bool quiet_, tty_;
  std::string stage_;
  int last_ = -1;
  std::chrono::steady_clock::time_point start_;
};

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

inline std::filesystem::path prepare_output_folder(const std::string& folder)
{
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if(ec || !std::filesystem::is_directory(folder))
    throw std::runtime_error("cannot create the output folder '" + folder + "': " + ec.message());
  return std::filesystem::path(folder);
}

// Writes a PNG copy of an SVG picture when rsvg-convert is installed; returns whether it did.
inline bool svg_to_png(const std::filesystem::path& svg)
{
  if(std::system("command -v rsvg-convert >/dev/null 2>&1") != 0) return false;
  std::filesystem::path png = svg;
  png.replace_extension(".png");
  const std::string cmd = "rsvg-convert -w 1000 -b white -o '" + png.string() + "' '" + svg.string() + "' 2>/dev/null";
  return std::system(cmd.c_str()) == 0;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_COMMON_H
