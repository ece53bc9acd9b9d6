#include "app/gui/glfw_context.h"

#include "app/gui/gl_debug_log.h"
#include "glcontext/gl_functions.h"
#define GLFW_INCLUDE_NONE  // GL/gl.h would hide glcorearb.h's GL 1.x typedefs
#include <GLFW/glfw3.h>

namespace sdfwb::app::gui {

GlfwContext::GlfwContext(GLFWwindow* window, bool ownsWindow, glcontext::GlFunctions gl,
                         glcontext::GlContextInfo info)
    : window_(window), ownsWindow_(ownsWindow), gl_(gl), info_(std::move(info)) {}

std::unique_ptr<GlfwContext> GlfwContext::forWindow(GLFWwindow* window) {
    glcontext::GlFunctions gl = glcontext::GlFunctions::load(
        [](const char* name) { return reinterpret_cast<glcontext::GlProc>(glfwGetProcAddress(name)); });
    glcontext::GlContextInfo info = glcontext::queryContextInfo(gl);
    glcontext::requireVersion(info, 3, 3);
    logGlDebugErrors();
    return std::unique_ptr<GlfwContext>(new GlfwContext(window, false, gl, info));
}

GlfwContext::~GlfwContext() {
    releaseCurrent();
    if (ownsWindow_) glfwDestroyWindow(window_);
}

void GlfwContext::makeCurrent() {
    glfwMakeContextCurrent(window_);
    if (!debugLogged_) logGlDebugErrors();  // a worker's context: once, on its thread
    debugLogged_ = true;
}

void GlfwContext::releaseCurrent() {
    if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
}

std::unique_ptr<glcontext::GlContext> GlfwContext::createShared() {
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* hidden = glfwCreateWindow(1, 1, "sdf-workbench worker", nullptr, window_);
    glfwDefaultWindowHints();
    if (!hidden) {
        throw glcontext::GlError("could not create a GL context sharing the window's (GLFW refused)");
    }
    // GLX entry points do not depend on the context; the table loaded for the
    // window serves the shared context too.
    return std::unique_ptr<GlfwContext>(new GlfwContext(hidden, true, gl_, info_));
}

}  // namespace sdfwb::app::gui
