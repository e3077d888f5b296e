#include "ui/offscreen.h"

#include <cmath>

#include "gl/framebuffer.h"
#include "gl/readback.h"
#include "gl/texture.h"

namespace viz::ui {

Image renderOffscreen(const DrawList& list, glm::ivec2 size, glm::vec4 background) {
    const gl::Texture target = gl::Texture::create(
        {.target = GL_TEXTURE_2D, .format = GL_RGBA8, .size = {size.x, size.y, 1}, .levels = 1, .label = "ui.offscreen"});
    gl::Framebuffer framebuffer = gl::Framebuffer::create("ui.offscreen");
    framebuffer.attachColour(0, target);
    framebuffer.checkComplete();
    framebuffer.bind();
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, &background.r);
    TextRenderer renderer(list.font());
    renderer.draw(list, size);
    gl::Framebuffer::bindDefault();

    return linearFromDisplay(gl::readTexture(target));
}

Image linearFromDisplay(const Image& display) {
    Image linear(display.width, display.height, 3);
    for (int y = 0; y < display.height; ++y)
        for (int x = 0; x < display.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float s = display.at(x, y, c);
                linear.at(x, y, c) = s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
            }
    return linear;
}

}  // namespace viz::ui
