// The drag measurement's bookkeeping on a made-up timeline: a picture counts once for the
// newest edit it shows, edits it skipped are merged into it, latency runs from that edit's
// submission to the picture, and the rates cover the drag up to its last new picture.
#include "examples/opal-view/core/edit_latency.h"

#include <gtest/gtest.h>

namespace opal::view {
namespace {

TEST(EditLatency, CountsPicturesOfNewEditsAndTheirDelay) {
    using namespace std::chrono_literals;
    const EditLatency::Clock::time_point t0{};
    EditLatency latency(t0);
    for (int frame = 0; frame < 40; ++frame) latency.frame();
    latency.edited(1, t0 + 100ms);
    latency.edited(2, t0 + 150ms);
    latency.shown(2, t0 + 180ms);  // edit 1 merged into 2: one picture, 30 ms after edit 2
    latency.shown(2, t0 + 300ms);  // a refinement of the same edit: not a new picture
    latency.edited(3, t0 + 400ms);
    latency.shown(3, t0 + 470ms);
    for (int frame = 0; frame < 60; ++frame) latency.frame();  // waiting for convergence: not the drag's
    // Rates over the drag: from its start to the last new picture (470 ms), 40 frames.
    EXPECT_EQ(latency.summary(t0 + 1000ms),
              "interface 85.1 fps, 4.3 new pictures/s, edit to picture median 70 ms (max 70), 3 edits in 0.5 s");
    EditLatency none(t0);
    for (int frame = 0; frame < 30; ++frame) none.frame();
    none.edited(1, t0 + 100ms);
    EXPECT_EQ(none.summary(t0 + 1500ms),
              "interface 20.0 fps, 0.0 new pictures/s, edit to picture median 0 ms (max 0), 1 edits in 1.5 s");
}

}  // namespace
}  // namespace opal::view
