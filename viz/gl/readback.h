// Reading textures back into viz::Image (float, row 0 at the top: GL's row 0 is the bottom, so rows
// are flipped). The channel count follows the format: R -> 1, RG -> 2, RGB -> 3, RGBA -> 4, depth
// -> 1. Integer formats (R32UI, ...) are converted to float values.
#pragma once

#include <epoxy/gl.h>

#include "core/image.h"
#include "gl/texture.h"

namespace viz::gl {

// layer: the array layer, cube face (0..5 = +X,-X,+Y,-Y,+Z,-Z) or 3D slice; -1 means layer 0.
// channels: 0 reads the format's; 1 to 4 reads that many (GL drops the rest, or fills green and blue
// with 0 and alpha with 1), in one pass and one buffer (not for depth formats).
Image readTexture(GLuint texture, int level = 0, int layer = -1, int channels = 0);
Image readTexture(const Texture& texture, int level = 0, int layer = -1, int channels = 0);

// The layers readTexture can read at `level`: 6 for a cube map, the array layers or 3D slices, else 1.
int textureLayerCount(GLuint texture, int level = 0);

}  // namespace viz::gl
