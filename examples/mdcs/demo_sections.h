// The sections of `mdcs demo` that have their own translation unit (demo_<name>.cpp), so that the demo compiles in
// parallel pieces of moderate memory. Each writes its files into `folder`, appends a section to the markdown
// summary `md`, and returns false when one of its consistency checks failed.
#ifndef MDCS_CLI_DEMO_SECTIONS_H
#define MDCS_CLI_DEMO_SECTIONS_H

#include "cli_progress.h"

#include <filesystem>
#include <ostream>

namespace mdcs_cli {

bool demo_geodesics(const std::filesystem::path& folder, bool quick, const Progress_bar& progress, std::ostream& md);
bool demo_surface(const std::filesystem::path& folder, bool quick, const Progress_bar& progress, std::ostream& md);
bool demo_mwt(const std::filesystem::path& folder, bool quick, const Progress_bar& progress, std::ostream& md);
bool demo_silhouette(const std::filesystem::path& folder, bool quick, const Progress_bar& progress, std::ostream& md);

} // namespace mdcs_cli

#endif // MDCS_CLI_DEMO_SECTIONS_H
