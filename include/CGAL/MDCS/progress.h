// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Progress reporting and cancellation shared by every MDCS algorithm.

#ifndef CGAL_MDCS_PROGRESS_H
#define CGAL_MDCS_PROGRESS_H

#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {
namespace MDCS {

/*!
  \brief The default progress callback: reports nothing, never cancels.

  Long MDCS computations accept a *progress callback*: any callable with the signature
  `bool(const char* stage, double fraction)`. It is called with the name of the current stage
  (for example `"arrangement"`, `"weights"`, `"max-flow"`) and the completed fraction of that stage in
  [0, 1]. Returning `false` cancels the computation, which then throws `Operation_cancelled`.
  Callbacks are invoked a bounded number of times per stage (about a hundred), so they may print.
*/
struct No_progress
{
  bool operator()(const char* /*stage*/, double /*fraction*/) const { return true; }
};

/// Thrown when a progress callback asks to stop.
class Operation_cancelled : public std::runtime_error
{
public:
  explicit Operation_cancelled(const std::string& stage)
    : std::runtime_error("MDCS: operation cancelled by the progress callback during stage '" + stage + "'")
  {}
};

namespace internal {

// True for the default callback: an algorithm may then skip the work of computing a fraction nobody reads.
template <class Progress>
struct Reports_nothing : std::is_same<typename std::decay<Progress>::type, No_progress>
{};

// Calls the callback about every `total / 100` steps; throws Operation_cancelled when it returns false.
template <class Progress>
class Progress_reporter
{
public:
  Progress_reporter(Progress& progress, const char* stage, std::size_t total)
    : progress_(progress), stage_(stage), total_(total == 0 ? 1 : total),
      step_(total_ / 100 == 0 ? 1 : total_ / 100), next_(0)
  {
    report(0);
  }

  void operator()(std::size_t done)
  {
    if(done >= next_) {
      report(done);
      next_ = done + step_;
    }
  }

  void finish() { report(total_); }

private:
  void report(std::size_t done)
  {
    const double fraction = done >= total_ ? 1.0 : double(done) / double(total_);
    if(!progress_(stage_, fraction))
      throw Operation_cancelled(stage_);
  }

  Progress& progress_;
  const char* stage_;
  std::size_t total_, step_, next_;
};

} // namespace internal
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_PROGRESS_H
