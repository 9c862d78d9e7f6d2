// Turns AOV buffers into display-referred pictures on a thread of its own, so the interface
// never waits for the OCIO transform (the ACES view takes 280 ms on a 1280x720 frame on one
// core, 100-700 ms on two shared with the renderer). One conversion at a time; the
// interface asks for the next when the last is done, always for the newest state, and
// uploads what comes back.
#pragma once

#include "examples/opal-view/core/display_picture.h"

#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

namespace opal::view {

// What a picture was made from, as the interface tracks it.
struct PictureTag {
    int passes = -1, syncs = -1, settings = -1;
    int applied = 0;       // the newest submission the frame holds (RenderSession)
    bool settled = false;  // the buffer was final when read
    friend bool operator==(const PictureTag&, const PictureTag&) = default;
};

struct PictureRequest {
    const hd::RenderBuffer* buffer = nullptr;
    std::string aov, display, view;
    DisplayGrade grade;
    PictureTag tag;
    // Convert one pixel per block x block (their mean in scene-linear): while a picture is
    // still changing, a conversion block^2 times as fast matters more than its detail. A
    // delegate's draft (opal:draftBlock) is uniform over its blocks: converted with its own
    // block size, it loses nothing.
    int block = 1;
};

struct ConvertedPicture {
    Image image;  // RGB, display-referred; empty before the buffer was allocated
    PictureTag tag;
    std::string error;  // what the conversion threw, if it did
};

class PictureConverter {
public:
    explicit PictureConverter(const ColorConfig& config);
    ~PictureConverter();
    PictureConverter(const PictureConverter&) = delete;
    PictureConverter& operator=(const PictureConverter&) = delete;

    // Starts a conversion; false (nothing done) while one is queued or running. The buffer
    // must stay alive until it is done (drain() before its session goes).
    bool request(PictureRequest request);
    bool busy() const;
    // A finished picture waits to be taken.
    bool ready() const;
    // The finished picture, once.
    std::optional<ConvertedPicture> take();
    // Waits until nothing is queued or running.
    void drain();
    // Converts with this config from now on; only after drain(), with nothing requested since.
    void setConfig(const ColorConfig& config) { display_ = DisplayPicture(config); }

private:
    void work();
    ConvertedPicture convert(const PictureRequest& request);

    DisplayPicture display_;  // the converter thread's only
    mutable std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::optional<PictureRequest> queued_;
    std::optional<ConvertedPicture> done_;
    bool running_ = false, quit_ = false;
    std::thread thread_;  // last
};

}  // namespace opal::view
