// The voxel grid's shared passes (grid_passes.h).
#include "techniques/vsv/grid_passes.h"

#include <utility>

namespace viz::vsv {

void packGrid(const gl::Program& pack, const gl::Texture& words, const gl::Texture& grid, glm::ivec2 origin,
              glm::ivec3 size) {
    pack.use();
    pack.set("uSize", size);
    pack.set("uOrigin", origin);
    words.bindImage(0, GL_READ_ONLY);
    grid.bindImage(1, GL_WRITE_ONLY);
    const glm::ivec3 groups = gl::groupCount(size, pack.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

const gl::Texture* scanGrid(const gl::Program& scan, const gl::Texture* a, const gl::Texture* b, glm::ivec2 origin,
                            glm::ivec3 size, int segment, int passes) {
    scan.use();
    scan.set("uSegment", segment);
    scan.set("uOrigin", origin);
    scan.set("uSize", size);
    const glm::ivec3 groups = gl::groupCount(size, scan.workGroupSize());
    for (int p = 0; p < passes; ++p) {
        scan.set("uOffset", 1 << p);
        a->bindImage(0, GL_READ_ONLY);
        b->bindImage(1, GL_WRITE_ONLY);
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
        std::swap(a, b);
    }
    return a;
}

}  // namespace viz::vsv
