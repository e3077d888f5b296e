// The worked example technique of docs/architecture.md#adding-a-technique: the shape every technique has
// (a settings struct declared with its parameters, stages declared as data and run by the stage runner,
// a plan that says what it leaves out) on the smallest subject there is, the unshadowed airlight of
// suns along rays that meet no surface. Registered only by the tests (tests/cpu/plan/example_test.cpp).
#pragma once

#include <memory>

#include "debug/technique.h"

namespace viz {

std::unique_ptr<Technique> makeExampleTechnique();

}  // namespace viz
