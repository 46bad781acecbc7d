// `mdcs mwt`: Minimum weight triangulation of a point set (issue 5).
// SKELETON: the sub-command is wired into mdcs.cpp and cmd_demo.h; its implementation is being written.
#ifndef MDCS_CLI_CMD_MWT_H
#define MDCS_CLI_CMD_MWT_H

#include "cli_common.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace mdcs_cli {

// Names of the options of `mdcs mwt` that take no value.
inline std::vector<std::string> mwt_flags() { return {"quiet", "help"}; }

inline const char* mwt_usage() { return "usage: mdcs mwt ...   (not available yet)\n"; }

inline int command_mwt(const Options& o)
{
  (void)o;
  throw std::runtime_error("mdcs mwt is not available yet");
}

// Part of `mdcs demo`: writes its pictures and files into folder, appends a section to the summary md;
// returns false when one of its consistency checks failed.
inline bool demo_mwt(const std::filesystem::path& folder, bool quick, bool quiet, Progress_bar& progress, std::ostream& md)
{
  (void)folder; (void)quick; (void)quiet; (void)progress; (void)md;
  return true;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_MWT_H
