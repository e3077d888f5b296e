// The picked pixel's ray replayed against the sampling planes: which planes it crosses, what each adds
// (the ray-planes table and chart).
#include "techniques/slices/slices_technique.h"

namespace viz::slices_detail {

void SlicesTechnique::replayPick(const FrameInput& input, const CameraBasis& basis, const Terms& t) {
    mRayPlanes.reset();
    if (mPickSets.empty()) return;
    // The plane pass's SSBO writes, visible to the replay's reads.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    const int count = mPickSets.back().base + mPickSets.back().drawn;
    if (count <= 0) return;
    const int columns = std::min(count, kReplayColumns);
    const int rows = (count + columns - 1) / columns;
    const GLenum format = GLenum(mAccum.format());
    if (!mReplay || mReplay.size().x != columns || mReplay.size().y != rows || GLenum(mReplay.format()) != format)
        mReplay = gl::Texture::create(
            {.target = GL_TEXTURE_2D, .format = format, .size = {columns, rows, 1}, .label = "slices.pick_replay"});
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(mReplay.id(), 0, GL_RGBA, GL_FLOAT, zero);
    if (!mReplayProgram)
        mReplayProgram = gl::Program::compile(
            {.stages = {"slices/pick_replay.vert", "slices/pick_replay.frag"}, .label = "slices.pick_replay"});
    const gl::Program& program = mReplayProgram;
    const scene::Camera& cam = input.scene->camera;
    program.use();
    program.set("uRows", rows);
    program.set("uColumns", columns);
    program.set("uSeedRow", -1);
    program.set("uPickPixel", glm::ivec2(mPickPixel.x, input.height - 1 - mPickPixel.y));
    setPixelRay(program, basis, input);
    program.set("uUserClip", t.userClip ? 1 : 0);
    const double eyeY = cam.position.y;
    program.set("uUserPlane0", glm::vec4(0, 1, 0, float(eyeY - mSettings.clipYMin)));
    program.set("uUserPlane1", glm::vec4(0, -1, 0, float(mSettings.clipYMax - eyeY)));
    mView.surface().distance().bindUnit(0);
    mReplay.bindUnit(1);
    mFramebuffer.attachColour(0, mReplay);
    mFramebuffer.checkComplete();
    mFramebuffer.bind();
    glViewport(0, 0, columns, rows);
    mVao.bind();
    for (int row = 0; row < rows; ++row) {
        const int k0 = row * columns, k1 = std::min(count, k0 + columns);
        if (row > 0) {
            // The row starts from the accumulation at the end of the row before.
            glTextureBarrier();
            program.set("uSeedRow", row);
            glDrawArrays(GL_TRIANGLES, 0, 6);
            program.set("uSeedRow", -1);
        }
        for (const PickSet& ps : mPickSets) {
            const int j0 = std::max(k0, ps.base) - ps.base, j1 = std::min(k1, ps.base + ps.drawn) - ps.base;
            if (j0 >= j1) continue;
            program.set("uPickBase", ps.base);
            program.set("uDepthFar", ps.depthFar);
            program.set("uSpacing", ps.spacing);
            program.set("uDrawNear", ps.drawNear);
            program.set("uNearestPlane", ps.nearestPlane);
            program.set("uNearestWeight", ps.nearestWeight);
            program.set("uClipLight", ps.clipLight ? 1 : 0);
            program.set("uLightMatrix", ps.volume);
            program.set("uBoxMinXY", ps.boxMin);
            program.set("uBoxMaxXY", ps.boxMax);
            glDrawArrays(GL_TRIANGLES, 6 * j0, 6 * (j1 - j0));
        }
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    std::vector<PickRecord> records(static_cast<std::size_t>(count));
    mPickRecords.download(0, records.size() * sizeof(PickRecord), records.data());
    const Image replay = gl::readTexture(mReplay);  // row 0 at the top: GL row height - 1
    mRayPlanes = rayPlaneTable(records, replay, t);
}

std::shared_ptr<Image> SlicesTechnique::rayPlaneTable(const std::vector<PickRecord>& records, const Image& replay,
                                     const Terms& t) const {
    using namespace slices;
    auto table = std::make_shared<Image>(int(kRayPlaneColumns), int(std::max<std::size_t>(records.size(), 1)), 4);
    const float radianceScale =
        float(1.0 / mLastStoreScale) * (t.mask ? (mMaskColour.r + mMaskColour.g + mMaskColour.b) : 1.0f);
    glm::vec4 before(0.0f);  // the accumulation runs on from one draw set into the next
    for (std::size_t r = 0; r < mPickSets.size(); ++r) {
        const PickSet& ps = mPickSets[r];
        for (int i = 0; i < ps.drawn; ++i) {
            const int row = ps.base + i;
            const PickRecord& rec = records[std::size_t(row)];
            glm::vec4 after(0.0f);
            for (int c = 0; c < 4; ++c)
                after[c] = replay.at(row % replay.width, replay.height - 1 - row / replay.width, c);
            const glm::vec4 added = after - before;
            before = after;
            auto put = [&](int column, glm::vec4 v) {
                for (int c = 0; c < 4; ++c) table->at(column, row, c) = v[c];
            };
            put(kColWhere, rec.where);
            put(kColTest, rec.test);
            put(kColValue, rec.value);
            put(kColAdded, added);
            put(kColAfter, after);
            // L_air added and the unquantised value, decoded as resolve.frag decodes (sum of rgb).
            const float addedSum = t.mask ? added.r + added.g + added.b + added.a : added.r + added.g + added.b;
            const float valueSum =
                t.mask ? rec.value.r + rec.value.g + rec.value.b + rec.value.a : rec.value.r + rec.value.g + rec.value.b;
            put(kColSet, {float(ps.light), float(r), addedSum * radianceScale, valueSum * radianceScale});
        }
    }
    return table;
}

}  // namespace viz::slices_detail
