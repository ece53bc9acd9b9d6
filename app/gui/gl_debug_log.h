#pragma once
// The driver's own account of GL errors in the GUI's contexts (KHR_debug,
// core since GL 4.3; Mesa's llvmpipe has it): glGetError says only which
// kind of error is pending, and whoever polls next (the viewport's render)
// was blamed for a call the UI had made frames earlier. With the callback,
// synchronous, the message names the call that raised it ("GL_INVALID_OPERATION
// in glBindTexture(non-gen name)") as it happens, and the GUI reports it.

#include <string>
#include <vector>

namespace sdfwb::app::gui {

// Routes the current context's error messages to the log below; does nothing
// when the context has no glDebugMessageCallback. Once per context.
void logGlDebugErrors();

// The messages logged since the last call, from any context and thread.
std::vector<std::string> takeGlDebugErrors();

}  // namespace sdfwb::app::gui
