// The airlight subcommands. Each returns the process exit code; user errors throw viz::InputError.
#pragma once

#include "cli_args.h"

namespace airlight {

int runDefault();
int runRender(Args& args);
int runList(Args& args);
int runPlan(Args& args);
int runExportScene(Args& args);
int runGuiCommand(Args& args);

}  // namespace airlight
