// Plots and handouts drawn off-screen (ui::renderOffscreen) after other GL work. The UI renderer saves the
// program and vertex array it finds bound and binds them back. A program deleted while current stays
// current, under a name that is no longer a program, until another is used, and binding that name back is
// GL_INVALID_VALUE: gl::Program's deleter unbinds it first (gl/handle.h). (A vertex array deleted while
// bound is unbound by GL itself.)
#include <gtest/gtest.h>

#include "gl/program.h"
#include "gl/vertex_array.h"
#include "gl_test_fixture.h"
#include "ui/font.h"
#include "ui/offscreen.h"

namespace viz::gl {
namespace {

class UiOffscreen : public GlTest {
protected:
    static const ui::FontAtlas& font() {
        static const ui::FontAtlas sFont = ui::FontAtlas::bake(ui::FontAtlas::kDefaultFontPath, 14.0f);
        return sFont;
    }
    // A black square in the middle of a white 32x32 image: returns the middle pixel's red.
    static float middleOfASquare() {
        ui::DrawList list(font());
        list.rect({{8.0f, 8.0f}, {24.0f, 24.0f}}, {0.0f, 0.0f, 0.0f, 1.0f});
        const Image image = ui::renderOffscreen(list, {32, 32}, {1.0f, 1.0f, 1.0f, 1.0f});
        EXPECT_FLOAT_EQ(image.at(1, 1, 0), 1.0f) << "the background";
        return image.at(16, 16, 0);
    }
};

TEST_F(UiOffscreen, DrawsWhatTheListHolds) {
    EXPECT_FLOAT_EQ(middleOfASquare(), 0.0f);
}

TEST_F(UiOffscreen, AProgramAndVertexArrayDeletedWhileBoundLeaveNothingBoundAndNoErrorAfterAPlot) {
    {
        const Program program = Program::compile({.stages = {"ui/text.vert", "ui/text.frag"}, .label = "test.deleted"});
        const VertexArray vertexArray = VertexArray::create("test.deleted_vao");
        program.use();
        vertexArray.bind();
    }  // both deleted here while still bound
    GLint program = -1, vertexArray = -1;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
    EXPECT_EQ(program, 0) << "no dead program is left current";
    EXPECT_EQ(vertexArray, 0);
    EXPECT_FLOAT_EQ(middleOfASquare(), 0.0f);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    EXPECT_EQ(program, 0) << "the plot binds back what it found";
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    // The fixture's TearDown counts the debug output's errors: none.
}

TEST_F(UiOffscreen, AProgramAndVertexArrayStillAliveAreBoundBack) {
    const Program program = Program::compile({.stages = {"ui/text.vert", "ui/text.frag"}, .label = "test.kept"});
    const VertexArray vertexArray = VertexArray::create("test.kept_vao");
    program.use();
    vertexArray.bind();
    EXPECT_FLOAT_EQ(middleOfASquare(), 0.0f);
    GLint bound = 0, boundArray = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &bound);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &boundArray);
    EXPECT_EQ(GLuint(bound), program.id());
    EXPECT_EQ(GLuint(boundArray), vertexArray.id());
    glUseProgram(0);
    glBindVertexArray(0);
}

}  // namespace
}  // namespace viz::gl
