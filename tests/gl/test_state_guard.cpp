// render/gl/StateGuard: what a pass off the scene (the hemicube, the dome) changes comes back as the
// caller left it, values chosen unlike GL's defaults so a guard that saved nothing would fail.
#include <doctest/doctest.h>

#include <cstdlib>

#include <epoxy/gl.h>

#include "app/window/Window.h"
#include "render/gl/StateGuard.h"

using namespace radiant;

TEST_CASE("state guard: framebuffer, viewport, tests, depth and blend settings come back as they were") {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) FAIL("no X display: run the GL tests under Xvfb (scripts/test does: xvfb-run -a)");
    app::Window window{{64, 64, "state guard test", false, false}};
    glViewport(3, 5, 40, 30);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_GEQUAL);
    glEnable(GL_SCISSOR_TEST);
    {
        const render::gl::StateGuard guard;
        glViewport(0, 0, 8, 8);
        glDisable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ZERO);
        glDisable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_SCISSOR_TEST);
    }
    GLint viewport[4]{};
    glGetIntegerv(GL_VIEWPORT, viewport);
    CHECK(viewport[0] == 3);
    CHECK(viewport[1] == 5);
    CHECK(viewport[2] == 40);
    CHECK(viewport[3] == 30);
    CHECK(glIsEnabled(GL_BLEND) == GL_TRUE);
    GLint blend[4]{};
    glGetIntegerv(GL_BLEND_SRC_RGB, &blend[0]);
    glGetIntegerv(GL_BLEND_DST_RGB, &blend[1]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blend[2]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blend[3]);
    CHECK(blend[0] == GL_SRC_ALPHA);
    CHECK(blend[1] == GL_ONE);
    CHECK(blend[2] == GL_ZERO);
    CHECK(blend[3] == GL_ONE_MINUS_SRC_ALPHA);
    CHECK(glIsEnabled(GL_CULL_FACE) == GL_TRUE);
    GLint cullMode = 0, depthFunc = 0;
    glGetIntegerv(GL_CULL_FACE_MODE, &cullMode);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
    CHECK(cullMode == GL_FRONT);
    CHECK(glIsEnabled(GL_DEPTH_TEST) == GL_FALSE);
    GLboolean depthWrite = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthWrite);
    CHECK(depthWrite == GL_FALSE);
    CHECK(depthFunc == GL_GEQUAL);
    CHECK(glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE);
}
