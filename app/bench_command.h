// `airlight bench`: how each technique's cost per stage grows with one kind of work at a time (image
// size, shadow-map size, VPL count, scene triangles), everything else fixed; bench.csv, bench.html and
// log-log plots with a fitted exponent per technique and stage.
#pragma once

#include <string>

#include "cli_args.h"

namespace airlight {

int runBenchCommand(Args& args, const std::string& commandLine);

}  // namespace airlight
