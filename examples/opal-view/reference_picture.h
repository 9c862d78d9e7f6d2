// The A/B wipe's right side: the picture of the reference session (the same scene with
// opal:reference on, ViewerModel::showReference), converted for display on a converter of
// its own, as the main picture is, and drawn over the main picture right of the split.
#pragma once

#include "examples/opal-view/core/picture_converter.h"
#include "examples/opal-view/core/render_session.h"
#include "examples/opal-view/display_settings.h"
#include "examples/opal-view/gl/picture_texture.h"

namespace opal::view {

// What a session's AOV buffers hold now: passes of its frame, syncs, display settings.
PictureTag pictureTagOf(const RenderSession& session, int settingsVersion);

class ReferencePicture {
public:
    explicit ReferencePicture(const ColorConfig& config) : converter_(config) {}

    // Asks for the session's newest picture when it changed and the converter is free
    // (one pixel per 2 x 2 block while it still changes), and uploads what came back.
    // Returns the conversion's error, or "".
    std::string refresh(const RenderSession& session, const DisplayPicture& display, const DisplaySettings& settings);
    // The picture shown is the session's final one with these settings.
    bool settled(const RenderSession& session, const DisplaySettings& settings) const;
    // Right of column `splitX` of the width x height framebuffer (the GL viewport).
    void draw(int splitX, int width, int height);
    // Waits for the conversion under way: before the session goes.
    void drain();
    // The config pictures are converted with from now on.
    void reset(const ColorConfig& config);

private:
    PictureConverter converter_;
    PictureTexture texture_;
    PictureTag requested_, shown_;
};

}  // namespace opal::view
