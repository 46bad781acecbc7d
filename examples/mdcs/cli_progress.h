// Progress of the mdcs commands on stderr. On a terminal: a bar redrawn in place, its clock ticking every second.
// Elsewhere (logs, CI): a heartbeat line every --heartbeat seconds (default 10) while a stage runs, also through
// stages that report no fraction (a factorisation, an LP solve), and one line per finished stage. --quiet prints
// none of it. Ctrl-C (SIGINT) or SIGTERM ask the running stage to stop at its next progress report (exit code 1,
// no partial output files); a second one ends the process at once.
#ifndef MDCS_CLI_PROGRESS_H
#define MDCS_CLI_PROGRESS_H

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <unistd.h>

namespace mdcs_cli {

inline std::atomic<int>& interrupt_count()
{
  static std::atomic<int> count{0};
  return count;
}

extern "C" inline void mdcs_cli_on_interrupt(int signal_number)
{
  if(interrupt_count().fetch_add(1) >= 1) { // the second one: stop now
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
  }
}

// Installs the handlers of SIGINT / SIGTERM, and ignores SIGXFSZ so that a write beyond the file size limit
// fails (and is reported like a full disk) instead of killing the process.
inline void install_signal_handlers()
{
  std::signal(SIGINT, mdcs_cli_on_interrupt);
  std::signal(SIGTERM, mdcs_cli_on_interrupt);
  std::signal(SIGXFSZ, SIG_IGN);
}

inline bool interrupted() { return interrupt_count().load() > 0; }

// The progress callback of the commands: `bool(const char* stage, double fraction)`; returns false after an
// interrupt. A cheap handle: copies share one display (and one heartbeat thread).
class Progress_bar
{
  typedef std::chrono::steady_clock Clock;

  struct State
  {
    bool quiet = false, tty = false;
    double interval = 10;
    std::mutex mutex;
    std::condition_variable wake;
    bool stop = false;
    std::thread heartbeat;
    std::string stage, finished; // the running stage; the last finished one
    double fraction = -1; // -1: the stage reports no fraction
    int percent = -1;
    Clock::time_point run_start = Clock::now(), stage_start = run_start, last_line = run_start;
    bool line_open = false; // a terminal bar is drawn on the current line

    ~State()
    {
      {
        std::lock_guard<std::mutex> lock(mutex);
        stop = true;
      }
      wake.notify_all();
      if(heartbeat.joinable()) heartbeat.join();
      if(line_open) std::fprintf(stderr, "\n");
    }

    static double since(Clock::time_point t, Clock::time_point now) { return std::chrono::duration<double>(now - t).count(); }

    void draw_bar(Clock::time_point now) // terminal only; mutex held
    {
      const int width = 30, p = percent < 0 ? 0 : percent, filled = p * width / 100;
      if(fraction < 0)
        std::fprintf(stderr, "\r  %-22s running  %.0fs          ", stage.c_str(), since(stage_start, now));
      else
        std::fprintf(stderr, "\r  %-22s [%.*s%*s] %3d%%  %.1fs", stage.c_str(), filled, "##############################",
                     width - filled, "", p, since(stage_start, now));
      std::fflush(stderr);
      line_open = true;
    }

    void heartbeat_line(Clock::time_point now) // logs; mutex held
    {
      if(fraction < 0)
        std::fprintf(stderr, "  %s: running for %.0f s (total %.0f s)\n", stage.c_str(), since(stage_start, now), since(run_start, now));
      else
        std::fprintf(stderr, "  %s: %d%% after %.0f s (total %.0f s)\n", stage.c_str(), percent < 0 ? 0 : percent,
                     since(stage_start, now), since(run_start, now));
      std::fflush(stderr);
      last_line = now;
    }

    void run_heartbeat()
    {
      std::unique_lock<std::mutex> lock(mutex);
      const auto tick = std::chrono::duration<double>(tty ? 1.0 : (interval < 1 ? interval : 1.0));
      while(!stop) {
        wake.wait_for(lock, std::chrono::duration_cast<Clock::duration>(tick));
        if(stop || stage.empty()) continue;
        const auto now = Clock::now();
        if(tty) draw_bar(now);
        else if(since(last_line, now) >= interval) heartbeat_line(now);
      }
    }
  };

public:
  explicit Progress_bar(bool quiet = false, double heartbeat_seconds = 10) : state_(std::make_shared<State>())
  {
    state_->quiet = quiet;
    state_->tty = isatty(fileno(stderr)) != 0;
    state_->interval = heartbeat_seconds > 0 ? heartbeat_seconds : 10;
    if(!quiet) {
      State* s = state_.get();
      s->heartbeat = std::thread([s] { s->run_heartbeat(); });
    }
  }

  bool operator()(const char* stage, double fraction) const
  {
    if(!state_->quiet) update(stage, fraction);
    return !interrupted();
  }

  // A stage that reports no fraction (the heartbeat still shows it is alive).
  void begin(const char* stage) const
  {
    if(!state_->quiet) update(stage, -1);
  }

  // The current stage is done (a line in logs, the bar closed on a terminal).
  void end() const
  {
    if(state_->quiet) return;
    std::lock_guard<std::mutex> lock(state_->mutex);
    finish_stage(Clock::now());
  }

private:
  void finish_stage(Clock::time_point now) const // mutex held
  {
    State& s = *state_;
    if(s.stage.empty()) return;
    if(s.tty) {
      s.percent = 100;
      if(s.fraction >= 0) s.fraction = 1;
      s.draw_bar(now);
      std::fprintf(stderr, "\n");
      s.line_open = false;
    } else {
      std::fprintf(stderr, "  %s done in %.2f s\n", s.stage.c_str(), State::since(s.stage_start, now));
      s.last_line = now;
    }
    std::fflush(stderr);
    s.finished = s.stage;
    s.stage.clear();
  }

  void update(const char* stage, double fraction) const
  {
    State& s = *state_;
    std::lock_guard<std::mutex> lock(s.mutex);
    const auto now = Clock::now();
    if(fraction >= 1 && s.stage.empty() && s.finished == stage) return; // reported done twice
    if(s.stage != stage) {
      if(s.tty && s.line_open) { // a stage left unfinished: keep its line
        std::fprintf(stderr, "\n");
        s.line_open = false;
      }
      s.stage = stage;
      s.stage_start = now;
      s.percent = -1;
    }
    s.fraction = fraction;
    const int percent = fraction < 0 ? -1 : int(fraction * 100.0 + 0.5);
    if(percent == s.percent && fraction < 1) return;
    s.percent = percent;
    if(fraction >= 1) {
      finish_stage(now);
      return;
    }
    if(s.tty) s.draw_bar(now);
  }

  std::shared_ptr<State> state_;
};

} // namespace mdcs_cli

#endif // MDCS_CLI_PROGRESS_H
