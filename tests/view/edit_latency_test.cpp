// The drag measurement's bookkeeping on a made-up timeline: a picture counts once for the
// newest edit it shows, edits it skipped are merged into it, and latency runs from that
// edit's submission to the picture.
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
    EXPECT_EQ(latency.summary(t0 + 1000ms),
              "interface 40.0 fps, 2.0 new pictures/s, edit to picture median 70 ms (max 70), 3 edits in 1.0 s");
}

}  // namespace
}  // namespace opal::view
