// The sub-commands of mdcs, each compiled in its own translation unit (cmd_<name>.cpp): its option table and the
// function that runs it. mdcs.cpp dispatches to them.
#ifndef MDCS_CLI_COMMANDS_H
#define MDCS_CLI_COMMANDS_H

#include "cli_common.h"

namespace mdcs_cli {

struct Command_entry
{
  const char* name;
  const char* summary; // one line for `mdcs --help`
  Command_spec (*spec)();
  int (*run)(Invocation&);
};

Command_spec curve_spec();
int run_curve_command(Invocation&);
Command_spec demo_spec();
int run_demo_command(Invocation&);
Command_spec geodesics_spec();
int run_geodesics_command(Invocation&);
Command_spec mincut_spec();
int run_mincut_command(Invocation&);
Command_spec mwt_spec();
int run_mwt_command(Invocation&);
Command_spec silhouette_spec();
int run_silhouette_command(Invocation&);
Command_spec surface_spec();
int run_surface_command(Invocation&);

} // namespace mdcs_cli

#endif // MDCS_CLI_COMMANDS_H
