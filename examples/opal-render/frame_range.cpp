#include "examples/opal-render/frame_range.h"

#include "schema/error.h"

#include <charconv>
#include <cstdio>
#include <string>

namespace opal::render {
namespace {

constexpr long kMaxFrames = 100000;

int parseInt(std::string_view text, std::string_view whole) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || text.empty())
        throw Error("--frames '" + std::string(whole) + "': '" + std::string(text) +
                    "' is not an integer time code (expected START:END, e.g. 1:48)");
    return value;
}

}  // namespace

RenderOptions::Frames parseFrameRange(std::string_view text, int step) {
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos)
        throw Error("--frames '" + std::string(text) + "': expected START:END, e.g. 1:48");
    RenderOptions::Frames frames{parseInt(text.substr(0, colon), text), parseInt(text.substr(colon + 1), text), step};
    if (frames.end < frames.start)
        throw Error("--frames '" + std::string(text) + "': END is before START");
    if (step < 1) throw Error("--step " + std::to_string(step) + ": expected a step of at least 1");
    if ((long(frames.end) - frames.start) / step + 1 > kMaxFrames)
        throw Error("--frames '" + std::string(text) + "': more than " + std::to_string(kMaxFrames) + " frames");
    return frames;
}

std::vector<int> framesOf(const RenderOptions::Frames& frames) {
    std::vector<int> list;
    for (long f = frames.start; f <= frames.end; f += frames.step) list.push_back(int(f));
    return list;
}

std::filesystem::path numberedPath(const std::filesystem::path& file, int frame) {
    char number[16];
    std::snprintf(number, sizeof number, ".%04d", frame);
    std::filesystem::path numbered = file;
    numbered.replace_filename(file.stem().string() + number + file.extension().string());
    return numbered;
}

}  // namespace opal::render
