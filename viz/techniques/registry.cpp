#include "techniques/registry.h"

#include "core/error.h"
#include "techniques/minmax/minmax.h"
#include "techniques/polyvol/polyvol.h"
#include "techniques/raymarch/raymarch.h"
#include "techniques/reference/reference.h"
#include "techniques/slices/slices.h"
#include "techniques/vsv/ivsv.h"
#include "techniques/vsv/vsv.h"

namespace viz {

std::vector<std::string> techniqueIds() { return {"reference", "raymarch", "slices", "polyvol", "minmax", "vsv", "ivsv"}; }

std::unique_ptr<Technique> makeTechnique(std::string_view id) {
    if (id == "reference") return makeReferenceTechnique();
    if (id == "raymarch") return makeRaymarchTechnique();
    if (id == "slices") return makeSlicesTechnique();
    if (id == "polyvol") return makePolyvolTechnique();
    if (id == "minmax") return makeMinmaxTechnique();
    if (id == "vsv") return makeVsvTechnique();
    if (id == "ivsv") return makeIvsvTechnique();
    std::string known;
    for (const std::string& t : techniqueIds()) known += (known.empty() ? "" : ", ") + t;
    throw InputError("unknown technique '" + std::string(id) + "' (known: " + known + ")");
}

}  // namespace viz
