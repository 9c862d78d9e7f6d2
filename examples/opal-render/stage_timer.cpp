#include "examples/opal-render/stage_timer.h"

#include <cstdio>

namespace opal::render {

std::string StageTimer::summary() const {
    std::string text;
    for (const auto& [stage, seconds] : stages_) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.2f s", seconds);
        text += (text.empty() ? "" : ", ") + stage + " " + buffer;
    }
    return text;
}

}  // namespace opal::render
