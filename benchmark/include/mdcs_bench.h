// Small helpers shared by the benchmark programs: wall-clock timing, medians, peak memory, CSV output.
#ifndef MDCS_BENCH_H
#define MDCS_BENCH_H

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>
#include <sys/resource.h>
#include <time.h>

namespace mdcs_bench {

inline double now_seconds()
{
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

// CPU time of this process (user + system), in seconds: on a shared machine it measures the one-core cost
// of a single-threaded phase without the time spent waiting for a core.
inline double cpu_seconds()
{
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

inline double median(std::vector<double> v)
{
  if(v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Peak resident set size of this process so far, in MiB (Linux: VmHWM).
inline double peak_rss_mib()
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, 6, "VmHWM:") == 0)
      return std::stod(line.substr(6)) / 1024.0;
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// Current resident set size in MiB (Linux: VmRSS).
inline double current_rss_mib()
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, 6, "VmRSS:") == 0)
      return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

// Resets the peak-RSS counter (Linux >= 4.0), so that the next peak_rss_mib() measures one phase.
// Returns false where the kernel does not allow it; then peaks are process-wide.
inline bool reset_peak_rss()
{
  std::ofstream out("/proc/self/clear_refs");
  if(!out) return false;
  out << "5";
  return bool(out);
}

// A table printed to stdout and written as CSV.
class Table
{
public:
  explicit Table(std::vector<std::string> columns) : columns_(std::move(columns)) {}
  void add_row(std::vector<std::string> row) { rows_.push_back(std::move(row)); }

  void print() const
  {
    std::vector<std::size_t> width(columns_.size());
    for(std::size_t c = 0; c < columns_.size(); ++c) {
      width[c] = columns_[c].size();
      for(const auto& r : rows_)
        if(c < r.size()) width[c] = std::max(width[c], r[c].size());
    }
    auto line = [&](const std::vector<std::string>& r) {
      for(std::size_t c = 0; c < columns_.size(); ++c)
        std::printf("%s%*s", c ? "  " : "", int(width[c]), c < r.size() ? r[c].c_str() : "");
      std::printf("\n");
    };
    line(columns_);
    for(const auto& r : rows_) line(r);
    std::fflush(stdout);
  }

  bool write_csv(const std::string& path) const
  {
    std::ofstream out(path);
    if(!out) return false;
    auto line = [&](const std::vector<std::string>& r) {
      for(std::size_t c = 0; c < r.size(); ++c) out << (c ? "," : "") << r[c];
      out << "\n";
    };
    line(columns_);
    for(const auto& r : rows_) line(r);
    return bool(out);
  }

private:
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
};

inline std::string fmt(double v, const char* format = "%.4g")
{
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

} // namespace mdcs_bench

#endif // MDCS_BENCH_H
