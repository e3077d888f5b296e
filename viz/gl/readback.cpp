#include "gl/readback.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/error.h"

namespace viz::gl {

namespace {

GLint levelParameter(GLuint texture, int level, GLenum pname) {
    GLint v = 0;
    glGetTextureLevelParameteriv(texture, level, pname, &v);
    return v;
}

}  // namespace

int textureLayerCount(GLuint texture, int level) {
    VIZ_CHECK(texture != 0 && glIsTexture(texture), "textureLayerCount: not a texture name");
    GLint target = 0;
    glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
    if (target == GL_TEXTURE_CUBE_MAP) return 6;
    return std::max(levelParameter(texture, level, GL_TEXTURE_DEPTH), 1);
}

Image readTexture(GLuint texture, int level, int layer, int wantChannels) {
    VIZ_CHECK(texture != 0 && glIsTexture(texture), "readTexture: not a texture name");
    const int width = levelParameter(texture, level, GL_TEXTURE_WIDTH);
    const int height = levelParameter(texture, level, GL_TEXTURE_HEIGHT);
    const int z = layer < 0 ? 0 : layer;
    VIZ_CHECK(z < textureLayerCount(texture, level), "readTexture: layer out of range");

    // The format decides channels and how to read: per-channel sizes and component types.
    const bool isDepth = levelParameter(texture, level, GL_TEXTURE_DEPTH_SIZE) > 0;
    int channels = 1;
    GLenum componentType = GL_FLOAT;
    if (isDepth) {
        componentType = static_cast<GLenum>(levelParameter(texture, level, GL_TEXTURE_DEPTH_TYPE));
    } else {
        const bool g = levelParameter(texture, level, GL_TEXTURE_GREEN_SIZE) > 0;
        const bool b = levelParameter(texture, level, GL_TEXTURE_BLUE_SIZE) > 0;
        const bool a = levelParameter(texture, level, GL_TEXTURE_ALPHA_SIZE) > 0;
        channels = a ? 4 : b ? 3 : g ? 2 : 1;
        componentType = static_cast<GLenum>(levelParameter(texture, level, GL_TEXTURE_RED_TYPE));
    }
    const bool isInteger =
        !isDepth && (componentType == GL_INT || componentType == GL_UNSIGNED_INT);
    VIZ_CHECK(wantChannels >= 0 && wantChannels <= 4 && (wantChannels == 0 || !isDepth),
              "readTexture: a channel count of 1 to 4, and none for a depth format");
    if (wantChannels > 0) channels = wantChannels;  // GL drops the channels past it or fills them (0, alpha 1)
    static const GLenum kFloatFormats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    static const GLenum kIntFormats[] = {GL_RED_INTEGER, GL_RG_INTEGER, GL_RGB_INTEGER,
                                         GL_RGBA_INTEGER};
    const GLenum pixelFormat = isDepth     ? GL_DEPTH_COMPONENT
                               : isInteger ? kIntFormats[channels - 1]
                                           : kFloatFormats[channels - 1];

    // Read straight into the image's storage and flip its rows there: a second buffer of the same
    // size would be fresh memory every frame (a 1920x1080 RGBA float read is 33 MB of page faults).
    Image image(width, height, channels);
    const size_t count = image.pixels.size();
    // Rows are tightly packed in our buffers; the default pack alignment of 4 would pad odd widths.
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    const GLsizei bytes = static_cast<GLsizei>(count * sizeof(float));
    if (isInteger) {
        // Signed and unsigned 32-bit values are read as their own type, then converted to float.
        const GLenum type = componentType == GL_INT ? GL_INT : GL_UNSIGNED_INT;
        std::vector<uint32_t> ints(count);
        glGetTextureSubImage(texture, level, 0, 0, z, width, height, 1, pixelFormat, type, bytes,
                             ints.data());
        for (size_t i = 0; i < count; ++i) {
            image.pixels[i] = type == GL_INT ? static_cast<float>(static_cast<int32_t>(ints[i]))
                                             : static_cast<float>(ints[i]);
        }
    } else {
        glGetTextureSubImage(texture, level, 0, 0, z, width, height, 1, pixelFormat, GL_FLOAT,
                             bytes, image.pixels.data());
    }

    // GL row 0 is the bottom; viz::Image row 0 is the top.
    const size_t rowFloats = static_cast<size_t>(width) * static_cast<size_t>(channels);
    for (int y = 0; y < height / 2; ++y) {
        auto top = image.pixels.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(y) * rowFloats);
        auto bottom =
            image.pixels.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(height - 1 - y) * rowFloats);
        std::swap_ranges(top, top + static_cast<std::ptrdiff_t>(rowFloats), bottom);
    }
    return image;
}

Image readTexture(const Texture& texture, int level, int layer, int channels) {
    return readTexture(texture.id(), level, layer, channels);
}

}  // namespace viz::gl
