// Progressive, anti-aliased image formation on the render thread (image/renderer.h,
// delegate/render_thread.h): coverage against exact areas, the nearest AOVs against the
// single centre sample, restarts, pause, tile-consistent reads and the delegate's own
// description of itself, all at the shipped settings.
#include "delegate/image/pixel_filter.h"
#include "delegate/image/sample_pattern.h"
#include "delegate/render_delegate.h"

#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <numbers>
#include <thread>

namespace opal {
namespace {

constexpr int FrameWidth = 96, FrameHeight = 64;
constexpr double kCameraDistance = 30.0;
constexpr double kEdgeDegrees = 15.0;  // from the image's vertical

// A square of side 80 facing the camera whose left edge crosses the whole image, tilted by
// kEdgeDegrees; its other edges lie far outside the view.
Imath::M44d squareTransform() {
    Imath::M44d scale, facing, up, tilt;
    scale.setScale(10.0);                                    // side 8 -> 80
    facing.setAxisAngle(Imath::V3d(1, 0, 0), std::numbers::pi / 2);  // normal +Y -> +Z
    up.setTranslation(Imath::V3d(0.0, 40.0, 0.0));           // the edge spans y in [-40, 40]
    tilt.setAxisAngle(Imath::V3d(0, 0, 1), kEdgeDegrees * std::numbers::pi / 180.0);
    return scale * facing * up * tilt;
}

// A world point on the image, by the camera conventions of camera_view.h: the front camera
// (36 x 24 film, 50 mm lens) at z = 30 shows 0.72 x 0.48 of the plane at unit distance.
Imath::V2d project(const Imath::V3d& p) {
    const double depth = kCameraDistance - p.z;
    return {(p.x / depth / 0.36 + 1.0) * FrameWidth / 2.0, (1.0 - p.y / depth / 0.24) * FrameHeight / 2.0};
}

// The half-plane the square covers on the image: n.q < c.
struct HalfPlane {
    Imath::V2d n;
    double c = 0.0;
    bool inside(const Imath::V2d& q) const { return n.dot(q) < c; }
};

HalfPlane squareOnImage() {
    const Imath::M44d m = squareTransform();
    Imath::V3d a, b, centre;
    m.multVecMatrix(Imath::V3d(0, 0, 0), a);
    m.multVecMatrix(Imath::V3d(0, 0, 8), b);
    m.multVecMatrix(Imath::V3d(4, 0, 4), centre);
    const Imath::V2d pa = project(a), pb = project(b), d = pb - pa;
    HalfPlane h{Imath::V2d(-d.y, d.x).normalized(), 0.0};
    h.c = h.n.dot(pa);
    if (!h.inside(project(centre))) {
        h.n = -h.n;
        h.c = -h.c;
    }
    return h;
}

// The exact area of pixel (x, y) inside the half-plane: the unit square clipped by it.
double coveredArea(const HalfPlane& h, int x, int y) {
    const Imath::V2d corners[4] = {{double(x), double(y)}, {x + 1.0, double(y)}, {x + 1.0, y + 1.0}, {double(x), y + 1.0}};
    std::vector<Imath::V2d> clipped;
    for (int i = 0; i < 4; ++i) {
        const Imath::V2d& p = corners[i];
        const Imath::V2d& q = corners[(i + 1) % 4];
        const double dp = h.n.dot(p) - h.c, dq = h.n.dot(q) - h.c;
        if (dp < 0.0) clipped.push_back(p);
        if ((dp < 0.0) != (dq < 0.0)) clipped.push_back(p + (q - p) * (dp / (dp - dq)));
    }
    double twice = 0.0;
    for (std::size_t i = 0; i < clipped.size(); ++i) {
        const Imath::V2d& p = clipped[i];
        const Imath::V2d& q = clipped[(i + 1) % clipped.size()];
        twice += p.x * q.y - q.x * p.y;
    }
    return std::abs(twice) / 2.0;
}

// The filter-weighted covered fraction by the midpoint rule on a 64 x 64 grid.
double filteredCoverage(const HalfPlane& h, int x, int y, PixelFilter filter) {
    constexpr int n = 64;
    double inside = 0.0, total = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const Imath::V2f u((i + 0.5f) / n, (j + 0.5f) / n);
            const double w = filterWeight(filter, u);
            total += w;
            if (h.inside(Imath::V2d(x + u.x, y + u.y))) inside += w;
        }
    return inside / total;
}

struct SquareScene {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index{delegate};

    explicit SquareScene(const std::map<hd::Token, hd::Value>& settings = {}) : delegate(settings) {
        scene.meshes["/World/Square"] = hd::MeshDesc{test::squareAsset(), squareTransform(), {}, true};
        index.insertRprim(hd::PrimType::TranslucentMesh, scene, "/World/Square");
        test::addCamera(scene, index);
        index.sync();
    }
    test::Aovs render() { return test::renderAovs(delegate, index, test::CameraPath, FrameWidth, FrameHeight); }
};

TEST(Progressive, AnObliqueEdgeConvergesToItsCoverage) {
    SquareScene s;  // the shipped settings: 16 samples per pixel, box filter
    const test::Aovs a = s.render();
    const HalfPlane edge = squareOnImage();
    int edgePixels = 0, fractional = 0;
    double worst = 0.0;
    for (int y = 0; y < FrameHeight; ++y)
        for (int x = 0; x < FrameWidth; ++x) {
            const double area = coveredArea(edge, x, y);
            const float alpha = a.at("alpha", x, y)[0];
            EXPECT_NEAR(alpha, area, 1.0 / 16.0 + 0.02) << "pixel " << x << ", " << y;
            EXPECT_EQ(a.at("color", x, y)[3], alpha);
            if (area > 0.0 && area < 1.0) {
                ++edgePixels;
                worst = std::max(worst, std::abs(alpha - area));
                fractional += alpha > 0.0f && alpha < 1.0f;
            }
        }
    EXPECT_GT(edgePixels, FrameHeight);  // the edge crosses every row, some rows twice
    EXPECT_GT(fractional, FrameHeight / 2);  // anti-aliased: partly covered pixels have fractional alpha
    std::printf("oblique edge (%g degrees): %d edge pixels, worst |alpha - area| %.4f\n", kEdgeDegrees, edgePixels,
                worst);
}

TEST(Progressive, BlackmanHarrisWeighsTheSamplesByTheirPlaceInThePixel) {
    SquareScene s({{"opal:pixelFilter", std::string("blackmanHarris")}});
    const test::Aovs a = s.render();
    const HalfPlane edge = squareOnImage();
    double errorSum = 0.0, boxErrorSum = 0.0;
    int edgePixels = 0;
    for (int y = 0; y < FrameHeight; ++y)
        for (int x = 0; x < FrameWidth; ++x) {
            const double area = coveredArea(edge, x, y);
            if (area == 0.0 || area == 1.0) {
                EXPECT_EQ(a.at("alpha", x, y)[0], float(area));
                continue;
            }
            ++edgePixels;
            errorSum += std::abs(a.at("alpha", x, y)[0] - filteredCoverage(edge, x, y, PixelFilter::BlackmanHarris));
            boxErrorSum += std::abs(a.at("alpha", x, y)[0] - area);
        }
    // Closer to its own filter's coverage than to the box's: the weights are applied.
    EXPECT_LT(errorSum / edgePixels, 0.04);
    EXPECT_LT(errorSum, 0.7 * boxErrorSum);
}

TEST(Progressive, NearestAovsAreTheCentreSample) {
    SquareScene converged;
    SquareScene centre({{"opal:samplesPerPixel", 1}});
    const test::Aovs a = converged.render(), b = centre.render();
    for (const char* aov : {"depth", "primId", "normal"}) EXPECT_EQ(a.data.at(aov), b.data.at(aov)) << aov;
    // The single-sample image is jagged: its alpha is 0 or 1.
    for (float alpha : b.data.at("alpha")) EXPECT_TRUE(alpha == 0.0f || alpha == 1.0f);
}

// The dome-lit sphere of the restart test, with a key light that moves.
struct LitScene {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index{delegate};
    std::vector<std::unique_ptr<hd::RenderBuffer>> buffers;
    std::vector<hd::AovBinding> bindings;
    std::unique_ptr<hd::RenderPass> pass;
    hd::RenderPassState state{test::CameraPath, 160, 120};

    LitScene() {
        test::addSphere(scene, index);
        test::addCamera(scene, index);
        test::addLight(scene, index, "/World/Key", test::pointLight({20, 4, 12}, 300.0));
        index.sync();
        for (const hd::AovDescriptor& aov : hd::aovTable()) {
            buffers.push_back(std::make_unique<hd::RenderBuffer>("/Buffers/" + aov.name));
            bindings.push_back({aov.name, buffers.back().get()});
        }
        pass = delegate.createRenderPass(index);
    }
    void moveLight(const Imath::V3d& to) {
        scene.lights["/World/Key"] = test::pointLight(to, 300.0);
        index.changeTracker().markDirty("/World/Key", hd::Dirty::Transform);
        index.sync();
    }
    void waitForPasses(int passes) const {
        while (delegate.passesDone() < passes && !delegate.isConverged())
            std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    void waitForConvergence() const {
        while (!pass->isConverged()) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    std::vector<std::vector<float>> images() const {
        std::vector<std::vector<float>> out;
        for (const auto& b : buffers) out.emplace_back(b->data().begin(), b->data().end());
        return out;
    }
};

TEST(Progressive, AChangeWhileRenderingRestartsAndConvergesToAFreshRender) {
    LitScene s;
    s.pass->execute(s.state, s.bindings);
    s.waitForPasses(2);
    s.delegate.pause();  // hold the frame mid-way, so that the change surely comes during it
    ASSERT_FALSE(s.pass->isConverged());
    s.moveLight({-20, 4, 12});  // the commit restarts the frame on the render thread
    EXPECT_FALSE(s.pass->isConverged());
    s.delegate.resume();
    s.pass->execute(s.state, s.bindings);  // nothing else changed: the restarted frame goes on
    s.waitForConvergence();
    for (const auto& b : s.buffers) EXPECT_TRUE(b->isConverged()) << b->id();

    LitScene fresh;
    fresh.moveLight({-20, 4, 12});
    fresh.pass->execute(fresh.state, fresh.bindings);
    fresh.waitForConvergence();
    const auto a = s.images(), b = fresh.images();
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << s.bindings[i].aov;
}

double processCpuMs() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return (usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) * 1e3 + (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e3;
}

TEST(Progressive, PauseStopsTheWorkAndResumeFinishesIt) {
    LitScene s;
    s.pass->execute(s.state, s.bindings);
    s.waitForPasses(1);
    s.delegate.pause();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the running tiles end
    const int passes = s.delegate.passesDone();
    const double cpu = processCpuMs();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    EXPECT_EQ(s.delegate.passesDone(), passes);
    EXPECT_LT(processCpuMs() - cpu, 30.0);  // sleeping threads, not spinning ones
    EXPECT_FALSE(s.pass->isConverged());
    s.delegate.resume();
    s.waitForConvergence();
    EXPECT_EQ(s.delegate.passesDone(), 17);  // the centre pass and 16 samples
    EXPECT_EQ(std::get<int>(s.delegate.renderStats().at("samplesPerPixel")), 16);
    EXPECT_EQ(std::get<double>(s.delegate.renderStats().at("percentDone")), 100.0);
}

// A uniform dome and nothing else: every pixel of a frame holds the dome's colour exactly,
// whatever the pass. A tile half written would show two colours. The dome and the render
// settings change 40 times while a reader maps the buffer without pause.
TEST(Progressive, MappedBuffersNeverShowATornTile) {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index(delegate);
    test::addCamera(scene, index);
    hd::LightDesc dome;
    dome.kind = hd::LightKind::Dome;
    test::addLight(scene, index, "/World/Sky", dome);
    index.sync();
    hd::RenderBuffer color("/Buffers/color");
    const std::vector<hd::AovBinding> bindings = {{"color", &color}};
    const hd::RenderPassState state{test::CameraPath, 256, 160};
    const auto pass = delegate.createRenderPass(index);
    pass->execute(state, bindings);

    const int tile = std::get<int>(delegate.renderSetting("opal:tileSize"));
    std::atomic<bool> done{false};
    std::atomic<int> reads{0}, torn{0};
    std::thread reader([&] {
        while (!done) {
            const hd::RenderBuffer::Mapped map(color);
            for (int ty = 0; ty < 160; ty += tile)
                for (int tx = 0; tx < 256; tx += tile) {
                    const float first = map.pixel(tx, ty)[0];
                    for (int y = ty; y < std::min(ty + tile, 160); ++y)
                        for (int x = tx; x < std::min(tx + tile, 256); ++x)
                            if (map.pixel(x, y)[0] != first) {
                                ++torn;
                                y = 160;
                                break;
                            }
                }
            ++reads;
        }
    });
    for (int i = 1; i <= 40; ++i) {
        scene.lights["/World/Sky"].intensity = 1.0 + i % 2;
        index.changeTracker().markDirty("/World/Sky", hd::Dirty::Params);
        index.sync();  // restarts the frame
        // Settings that restart it too, without changing what a tile should hold.
        delegate.setRenderSetting("opal:samplesPerPixel", i % 3 == 0 ? 8 : 16);
        delegate.setRenderSetting("opal:pixelFilter", std::string(i % 4 == 0 ? "blackmanHarris" : "box"));
        pass->execute(state, bindings);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    while (!pass->isConverged()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    done = true;
    reader.join();
    EXPECT_GT(reads.load(), 10);
    EXPECT_EQ(torn.load(), 0);
    EXPECT_EQ(color.pixel(0, 0)[0], 1.0f);  // the last change (i = 40: intensity 1)
}

TEST(Progressive, RemovingAMeshGivesItsMemoryBack) {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index(delegate);
    test::addSphere(scene, index, "/World/A");
    test::addSphere(scene, index, "/World/B", test::translation(12, 0, 0));
    test::addCamera(scene, index);
    test::addLight(scene, index, "/World/Key", test::pointLight({20, 4, 12}, 300.0));
    index.sync();
    const auto stats = delegate.renderStats();
    const double a = std::get<double>(stats.at("memoryBytes:/World/A"));
    const double b = std::get<double>(stats.at("memoryBytes:/World/B"));
    EXPECT_GT(b, 0.0);
    EXPECT_EQ(std::get<double>(stats.at("memoryBytes")), a + b);

    index.removePrim("/World/B");
    index.sync();  // A is relit (B no longer shadows it) and may hold a second radiance buffer
    const auto after = delegate.renderStats();
    EXPECT_EQ(after.count("memoryBytes:/World/B"), 0u);
    const double total = std::get<double>(after.at("memoryBytes"));
    EXPECT_EQ(total, std::get<double>(after.at("memoryBytes:/World/A")));
    EXPECT_LT(total, a + b - 0.9 * b);
}

TEST(Progressive, TheDelegateDescribesItsAovsAndSettings) {
    OpalRenderDelegate delegate;
    const std::vector<hd::AovDescriptor> aovs = delegate.aovDescriptors();
    ASSERT_EQ(aovs.size(), hd::aovTable().size());
    for (std::size_t i = 0; i < aovs.size(); ++i) EXPECT_EQ(aovs[i].name, hd::aovTable()[i].name);
    const std::optional<hd::AovDescriptor> depth = delegate.defaultAovDescriptor("depth");
    ASSERT_TRUE(depth.has_value());
    EXPECT_EQ(depth->format, hd::AovFormat::Float32);
    EXPECT_EQ(depth->sampling, hd::AovSampling::Nearest);
    EXPECT_TRUE(std::isinf(depth->clearValue));
    EXPECT_EQ(delegate.defaultAovDescriptor("color")->sampling, hd::AovSampling::Filtered);
    EXPECT_FALSE(delegate.defaultAovDescriptor("beauty").has_value());

    // Every descriptor's default is what a new delegate holds, and its range is enforced.
    const auto settings = delegate.renderSettings();
    const auto descriptors = delegate.renderSettingDescriptors();
    ASSERT_EQ(descriptors.size(), settings.size());
    for (const hd::RenderSettingDescriptor& d : descriptors) {
        EXPECT_EQ(settings.at(d.key), d.defaultValue) << d.key;
        EXPECT_FALSE(d.help.empty()) << d.key;
        if (d.max) {
            EXPECT_THROW(delegate.setRenderSetting(d.key, int(*d.max) + 1), Error) << d.key;
        }
        if (d.min) {
            EXPECT_THROW(delegate.setRenderSetting(d.key, int(*d.min) - 1), Error) << d.key;
        }
        for (const std::string& choice : d.choices) EXPECT_NO_THROW(delegate.setRenderSetting(d.key, choice));
    }
}

}  // namespace
}  // namespace opal
