// An OpenGL program from a vertex and a fragment shader's source, for the viewer's passes.
#pragma once

#include <string>

namespace opal::view {

// Needs a current OpenGL 3.3 core context. Throws opal::Error starting with `what` and
// holding the compiler's or linker's log when a shader does not build.
unsigned linkProgram(const std::string& vertexSource, const std::string& fragmentSource, const std::string& what);

// The vertex shader of one triangle covering the viewport, made from gl_VertexID (no vertex
// buffer), passing `uv`: texture row 0 at the viewport's top (`flipRows`, an image on a
// window) or at its bottom (texel for texel into a framebuffer).
std::string viewportTriangleShader(bool flipRows);

}  // namespace opal::view
