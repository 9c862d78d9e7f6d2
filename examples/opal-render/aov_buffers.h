// The AOV buffers one render fills, and the EXR layers made from them. Opal's color AOV is
// RGBA, so a separate alpha layer is bound only when color is not written (its "A" would
// repeat color's). The preview needs color: it is rendered even when the EXR leaves it out.
#pragma once

#include "delegate/output/aov_layer.h"
#include "delegate/hd/render_pass.h"

#include <memory>
#include <string>
#include <vector>

namespace opal::render {

class AovBuffers {
public:
    // `requested`: AOV names in the order they should be written, each one of
    // hd::aovTable() (duplicates ignored); empty means all of them.
    AovBuffers(const std::vector<std::string>& requested, bool needColor);

    const std::vector<std::string>& written() const { return written_; }
    std::vector<hd::AovBinding> bindings() const;
    // After the pass ran: the written AOVs as EXR layers (AovLayer naming conventions).
    std::vector<AovLayer> exrLayers() const;
    // After the pass ran: the color AOV (RGBA, scene-linear).
    Image color() const;

private:
    struct Bound {
        std::string aov;
        std::unique_ptr<hd::RenderBuffer> buffer;
    };
    Image image(const Bound& bound) const;
    const Bound& find(const std::string& aov) const;

    std::vector<std::string> written_;
    std::vector<Bound> bound_;
};

}  // namespace opal::render
