// An emission, cookie or base-colour texture for the reference, decoded to linear RGB in double.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::reference {

// RGB texture decoded from sRGB to linear once, sampled bilinearly with texel centres at
// ((i + 0.5) / width, (j + 0.5) / height), row 0 = v near 0 = the top row of the file.
class LinearTexture {
public:
    LinearTexture() = default;
    explicit LinearTexture(const scene::Texture& texture);
    bool empty() const { return mWidth == 0; }
    int width() const { return mWidth; }
    int height() const { return mHeight; }
    // Bilinear, clamp to edge (the convention of scene/texture_sampling.h, in double precision).
    glm::dvec3 sample(glm::dvec2 uv) const;

private:
    glm::dvec3 texel(int i, int j) const { return mTexels[std::size_t(j) * std::size_t(mWidth) + std::size_t(i)]; }
    int mWidth = 0, mHeight = 0;
    std::vector<glm::dvec3> mTexels;
};

}  // namespace viz::reference
