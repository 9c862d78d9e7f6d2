#include "examples/opal-view/gl/shader_program.h"

#include "schema/error.h"

#include <glad/gl.h>

namespace opal::view {
namespace {

unsigned compile(unsigned type, const std::string& source, const std::string& what) {
    const unsigned shader = glCreateShader(type);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    int ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok) return shader;
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw Error(what + ": a shader does not compile: " + log);
}

}  // namespace

std::string viewportTriangleShader(bool flipRows) {
    return std::string(R"(#version 330 core
out vec2 uv;
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    uv = )") + (flipRows ? "vec2(p.x, 1.0 - p.y)" : "p") + R"(;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";
}

unsigned linkProgram(const std::string& vertexSource, const std::string& fragmentSource, const std::string& what) {
    const unsigned vertex = compile(GL_VERTEX_SHADER, vertexSource, what);
    unsigned fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, fragmentSource, what);
    } catch (const Error&) {
        glDeleteShader(vertex);
        throw;
    }
    const unsigned program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    int ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok) return program;
    char log[2048] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    throw Error(what + ": the shaders do not link: " + log);
}

}  // namespace opal::view
