// `airlight report`: every technique's quality sweep on each scene, timed and compared with the
// reference, written as results.csv, results.json, error-against-time plots and index.html.
#pragma once

#include <string>
#include <vector>

#include "cli_args.h"

namespace airlight {

int runReportCommand(Args& args, const std::string& commandLine);

}  // namespace airlight
