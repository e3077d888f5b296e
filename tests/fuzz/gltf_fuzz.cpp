// libFuzzer target for the glTF loader. Each input is one file with no folder around it: a GLB when it
// starts with the magic "glTF", else glTF JSON. The loader may refuse it only with viz::InputError; any
// other exception escapes and ends the run, so libFuzzer records it like a crash. A returned scene must
// be finite and pass validateScene, and a refusal must be one short line (load_contract.h); when not,
// the target says why on stderr and aborts.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "load_contract.h"
#include "scene/gltf_loader.h"
#include "scene/validate.h"

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "gltf_fuzz: %s: %s\n", what, detail.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace scene = viz::scene;
    const std::vector<unsigned char> bytes(data, data + size);
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::string fileName = binary ? "fuzz.glb" : "fuzz.gltf";

    scene::Scene loaded;
    try {
        // An empty baseDir: only data: URIs and the GLB's own chunk can be read.
        loaded = scene::loadGltfFromMemory(bytes, fileName, /*baseDir=*/"", binary);
    } catch (const viz::InputError& e) {
        const std::string problem = scene::contract::errorMessageProblem(e.what());
        if (!problem.empty()) broken(problem.c_str(), e.what());
        return 0;
    }

    const std::string problem = scene::contract::sceneProblem(loaded);
    if (!problem.empty()) broken("the loaded scene has a non-finite or out-of-range value", problem);
    try {
        scene::validateScene(loaded);
    } catch (const viz::InputError& e) {
        broken("the loaded scene fails validateScene", e.what());
    }
    return 0;
}
