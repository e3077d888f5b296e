// `airlight compare TEST REFERENCE [--heatmap OUT.png]`: the report's error figures for two images
// (EXR or PNG, same size), e.g. a render against the reference or one setting against another.
#pragma once

#include "cli_args.h"

namespace airlight {

int runCompare(Args& args);

}  // namespace airlight
