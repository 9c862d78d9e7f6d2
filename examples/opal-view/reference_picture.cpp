#include "examples/opal-view/reference_picture.h"

#include <glad/gl.h>

#include <algorithm>

namespace opal::view {

PictureTag pictureTagOf(const RenderSession& session, int settingsVersion) {
    const auto stats = session.delegate().renderStats();
    const auto passes = stats.find("passes");
    const int* count = passes == stats.end() ? nullptr : std::get_if<int>(&passes->second);
    PictureTag tag;
    tag.passes = count ? *count : 0;
    tag.syncs = session.status().syncs;
    tag.settings = settingsVersion;
    return tag;
}

std::string ReferencePicture::refresh(const RenderSession& session, const DisplayPicture& display,
                                      const DisplaySettings& settings) {
    std::string error;
    if (std::optional<ConvertedPicture> done = converter_.take()) {
        error = done->error;
        if (error.empty() && !done->image.empty()) texture_.upload(done->image);
        shown_ = done->tag;
    }
    // Read before the buffer is: a settled session writes nothing more into it.
    const bool settled = session.settled();
    PictureTag tag = pictureTagOf(session, settings.version);
    tag.settled = settled;
    if (tag == requested_ || converter_.busy()) return error;
    PictureRequest request{&session.buffer(settings.aov), settings.aov, display.display(), display.view(),
                           settings.grade, tag, settled ? 1 : 2};
    if (converter_.request(std::move(request))) requested_ = tag;
    return error;
}

bool ReferencePicture::settled(const RenderSession& session, const DisplaySettings& settings) const {
    PictureTag tag = pictureTagOf(session, settings.version);
    tag.settled = true;
    return session.settled() && shown_ == tag;
}

void ReferencePicture::draw(int splitX, int width, int height) {
    if (texture_.empty() || splitX >= width) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(std::max(splitX, 0), 0, width - std::max(splitX, 0), height);
    texture_.draw();
    glDisable(GL_SCISSOR_TEST);
}

void ReferencePicture::drain() {
    converter_.drain();
    converter_.take();
}

void ReferencePicture::reset(const ColorConfig& config) {
    drain();
    converter_.setConfig(config);
    requested_ = shown_ = {};
}

}  // namespace opal::view
