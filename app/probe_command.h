// `airlight probe`: what this machine's GL renderer does per millisecond with each kind of work the
// techniques are made of (gl/throughput_probe.h), so that a technique's times on one GPU can be read
// against another's.
#pragma once

#include "cli_args.h"

namespace airlight {

int runProbeCommand(Args& args);

}  // namespace airlight
