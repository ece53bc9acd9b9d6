#include "app/gui/gl_debug_log.h"

#include <mutex>
#include <utility>

#include "glcontext/gl_functions.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace sdfwb::app::gui {
namespace {

constexpr std::size_t kMaxKept = 64;  // a broken loop must not grow the log without bound

std::mutex logMutex;
std::vector<std::string> logged;

void APIENTRY onMessage(GLenum, GLenum type, GLuint, GLenum, GLsizei length, const GLchar* message, const void*) {
    if (type != GL_DEBUG_TYPE_ERROR) return;  // performance hints and notes are not the user's business
    std::lock_guard lock(logMutex);
    if (logged.size() < kMaxKept) logged.emplace_back(message, static_cast<std::size_t>(length));
}

}  // namespace

void logGlDebugErrors() {
    auto callback = reinterpret_cast<PFNGLDEBUGMESSAGECALLBACKPROC>(glfwGetProcAddress("glDebugMessageCallback"));
    auto enable = reinterpret_cast<PFNGLENABLEPROC>(glfwGetProcAddress("glEnable"));
    if (!callback || !enable) return;
    enable(GL_DEBUG_OUTPUT);
    enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // on the thread of the call, while it runs
    callback(onMessage, nullptr);
}

std::vector<std::string> takeGlDebugErrors() {
    std::lock_guard lock(logMutex);
    return std::exchange(logged, {});
}

}  // namespace sdfwb::app::gui
