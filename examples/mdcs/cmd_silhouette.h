// `mdcs silhouette`: Silhouette simplification of a triangle mesh (issue 7).
// SKELETON: the sub-command is wired into mdcs.cpp and cmd_demo.h; its implementation is being written.
#ifndef MDCS_CLI_CMD_SILHOUETTE_H
#define MDCS_CLI_CMD_SILHOUETTE_H

#include "cli_common.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace mdcs_cli {

// Names of the options of `mdcs silhouette` that take no value.
inline std::vector<std::string> silhouette_flags() { return {"quiet", "help"}; }

inline const char* silhouette_usage() { return "usage: mdcs silhouette ...   (not available yet)\n"; }

inline int command_silhouette(const Options& o)
{
  (void)o;
  throw std::runtime_error("mdcs silhouette is not available yet");
}

// Part of `mdcs demo`: writes its pictures and files into folder, appends a section to the summary md;
// returns false when one of its consistency checks failed.
inline bool demo_silhouette(const std::filesystem::path& folder, bool quick, bool quiet, Progress_bar& progress, std::ostream& md)
{
  (void)folder; (void)quick; (void)quiet; (void)progress; (void)md;
  return true;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_SILHOUETTE_H
