#pragma once
// The GUI's GL contexts as glcontext::GlContext: the window's own, and hidden
// 1x1 windows sharing its objects for worker threads (shader builds,
// snapshot exports). Create and destroy them on the main thread (GLFW's
// rule); make them current on any thread.

#include <memory>

#include "glcontext/gl_context.h"

struct GLFWwindow;

namespace sdfwb::app::gui {

class GlfwContext final : public glcontext::GlContext {
public:
    // The context of `window`, which must be current on the calling thread;
    // the window stays owned by the caller.
    static std::unique_ptr<GlfwContext> forWindow(GLFWwindow* window);
    ~GlfwContext() override;

    void makeCurrent() override;
    void releaseCurrent() override;
    // A hidden window whose context shares this one's objects.
    std::unique_ptr<glcontext::GlContext> createShared() override;
    const glcontext::GlFunctions& gl() const override { return gl_; }
    const glcontext::GlContextInfo& info() const override { return info_; }

private:
    GlfwContext(GLFWwindow* window, bool ownsWindow, glcontext::GlFunctions gl, glcontext::GlContextInfo info);

    GLFWwindow* window_;
    bool ownsWindow_;
    glcontext::GlFunctions gl_;
    glcontext::GlContextInfo info_;
    bool debugLogged_ = false;  // gl_debug_log.h installed for this context
};

}  // namespace sdfwb::app::gui
