#include "examples/opal-view/gl/ocio_display_program.h"

#include "examples/opal-view/gl/shader_program.h"
#include "schema/error.h"

#include <glad/gl.h>

#include <cmath>

namespace opal::view {
namespace {

// After OCIO's function: the grade around it, as DisplayPicture::toDisplay.
constexpr const char* FragmentMain = R"(
in vec2 uv;
out vec4 colour;
uniform sampler2D picture;
uniform float gain;
uniform float inverseGamma;
void main() {
    vec3 display = OCIODisplay(vec4(texture(picture, uv).rgb * gain, 1.0)).rgb;
    if (inverseGamma != 1.0) display = pow(max(display, vec3(0.0)), vec3(inverseGamma));
    colour = vec4(display, 1.0);
}
)";

constexpr unsigned FirstLutUnit = 1;  // unit 0 holds the picture

void setFiltering(unsigned target, OCIO::Interpolation interpolation) {
    const int filter = interpolation == OCIO::INTERP_NEAREST ? GL_NEAREST : GL_LINEAR;
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

}  // namespace

OcioDisplayProgram::OcioDisplayProgram(const ColorConfig& config, const std::string& display, const std::string& view)
    : display_(display), view_(view) {
    const std::string what = "the OCIO display '" + display + "', view '" + view + "' on the GPU";
    try {
        shader_ = OCIO::GpuShaderDesc::CreateShaderDesc();
        shader_->setLanguage(OCIO::GPU_LANGUAGE_GLSL_1_3);  // GLSL 1.30 syntax compiles as 3.30 core
        shader_->setFunctionName("OCIODisplay");
        shader_->setResourcePrefix("ocio_");
        config.workingToDisplay(display, view)->getDefaultGPUProcessor()->extractGpuShaderInfo(shader_);
    } catch (const OCIO::Exception& e) {
        throw Error(what + ": " + e.what());
    }
    program_ = linkProgram(viewportTriangleShader(false), std::string("#version 330 core\n") + shader_->getShaderText() + FragmentMain, what);
    try {
        uploadLuts(shader_);
        setUniforms();  // throws for a uniform type it cannot set
    } catch (...) {
        for (const Lut& lut : luts_) glDeleteTextures(1, &lut.texture);
        glDeleteProgram(program_);
        throw;
    }
}

OcioDisplayProgram::~OcioDisplayProgram() {
    for (const Lut& lut : luts_) glDeleteTextures(1, &lut.texture);
    glDeleteProgram(program_);
}

void OcioDisplayProgram::uploadLuts(const OCIO::GpuShaderDescRcPtr& shader) {
    for (unsigned i = 0; i < shader->getNum3DTextures(); ++i) {
        const char *name = nullptr, *sampler = nullptr;
        unsigned edge = 0;
        OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
        shader->get3DTexture(i, name, sampler, edge, interpolation);
        const float* values = nullptr;
        shader->get3DTextureValues(i, values);
        if (!values || edge == 0) throw Error("OCIO's 3D LUT '" + std::string(name ? name : "?") + "' has no values");
        Lut lut{0, GL_TEXTURE_3D, sampler};
        glGenTextures(1, &lut.texture);
        luts_.push_back(lut);
        glBindTexture(GL_TEXTURE_3D, lut.texture);
        setFiltering(GL_TEXTURE_3D, interpolation);
        glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB32F, int(edge), int(edge), int(edge), 0, GL_RGB, GL_FLOAT, values);
    }
    for (unsigned i = 0; i < shader->getNumTextures(); ++i) {
        const char *name = nullptr, *sampler = nullptr;
        unsigned width = 0, height = 0;
        OCIO::GpuShaderDesc::TextureType channel = OCIO::GpuShaderDesc::TEXTURE_RGB_CHANNEL;
        OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
        shader->getTexture(i, name, sampler, width, height, channel, interpolation);
        const float* values = nullptr;
        shader->getTextureValues(i, values);
        if (!values || width == 0) throw Error("OCIO's LUT '" + std::string(name ? name : "?") + "' has no values");
        const bool red = channel == OCIO::GpuShaderDesc::TEXTURE_RED_CHANNEL;
        const int internal = red ? GL_R32F : GL_RGB32F;
        const unsigned format = red ? GL_RED : GL_RGB;
        // OCIO folds a long 1D LUT into rows of a 2D texture (and samples it so).
        Lut lut{0, height > 1 ? unsigned(GL_TEXTURE_2D) : unsigned(GL_TEXTURE_1D), sampler};
        glGenTextures(1, &lut.texture);
        luts_.push_back(lut);
        glBindTexture(lut.target, lut.texture);
        setFiltering(lut.target, interpolation);
        if (height > 1) glTexImage2D(GL_TEXTURE_2D, 0, internal, int(width), int(height), 0, format, GL_FLOAT, values);
        else glTexImage1D(GL_TEXTURE_1D, 0, internal, int(width), 0, format, GL_FLOAT, values);
    }
}

void OcioDisplayProgram::setUniforms() const {
    glUseProgram(program_);
    for (unsigned i = 0; i < shader_->getNumUniforms(); ++i) {
        OCIO::GpuShaderDesc::UniformData data;
        const char* name = shader_->getUniform(i, data);
        const int at = glGetUniformLocation(program_, name);
        switch (data.m_type) {
        case OCIO::UNIFORM_DOUBLE: glUniform1f(at, float(data.m_getDouble())); break;
        case OCIO::UNIFORM_BOOL: glUniform1i(at, data.m_getBool() ? 1 : 0); break;
        case OCIO::UNIFORM_FLOAT3: {
            const OCIO::Float3& v = data.m_getFloat3();
            glUniform3f(at, v[0], v[1], v[2]);
            break;
        }
        case OCIO::UNIFORM_VECTOR_FLOAT:
            glUniform1fv(at, int(data.m_vectorFloat.m_getSize()), data.m_vectorFloat.m_getVector());
            break;
        case OCIO::UNIFORM_VECTOR_INT:
            glUniform1iv(at, int(data.m_vectorInt.m_getSize()), data.m_vectorInt.m_getVector());
            break;
        default: throw Error("OCIO's shader uniform '" + std::string(name) + "' has a type the viewer cannot set");
        }
    }
}

void OcioDisplayProgram::draw(const DisplayGrade& grade, unsigned vertexArray) const {
    setUniforms();
    glUniform1i(glGetUniformLocation(program_, "picture"), 0);
    glUniform1f(glGetUniformLocation(program_, "gain"), float(std::exp2(grade.exposure)));
    glUniform1f(glGetUniformLocation(program_, "inverseGamma"), float(1.0 / grade.gamma));
    for (std::size_t i = 0; i < luts_.size(); ++i) {
        glActiveTexture(GL_TEXTURE0 + FirstLutUnit + unsigned(i));
        glBindTexture(luts_[i].target, luts_[i].texture);
        glUniform1i(glGetUniformLocation(program_, luts_[i].sampler.c_str()), int(FirstLutUnit + i));
    }
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

}  // namespace opal::view
