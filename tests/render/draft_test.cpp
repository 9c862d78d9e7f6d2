// The draft an interactive host shows first (opal:draftBlock, renderDraft): it is the
// single-sample image of a camera with N times fewer pixels per side, spread over N x N
// blocks; and the frame a delegate converges to is the same bits with or without it.
#include "delegate/image/camera_view.h"
#include "delegate/image/renderer.h"
#include "delegate/render_delegate.h"

#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

#include <cstring>

namespace opal {
namespace {

// The test sphere (radius 5) with made-up per-vertex radiance and irradiance (its position
// mapped to colours), no relighting and no specular layer: the renderer alone.
Frame paintedSphere() {
    const std::shared_ptr<const TranslucentAsset> asset = test::sharedSphere();
    auto rays = std::make_shared<RayScene>();
    rays->addMesh(asset->mesh, Imath::M44d());
    rays->commit();
    auto radiance = std::make_shared<std::vector<float>>();
    auto irradiance = std::make_shared<std::vector<float>>();
    for (const Imath::V3f& p : asset->mesh.points)
        for (int c = 0; c < 3; ++c) {
            radiance->push_back(0.5f + 0.1f * p[c]);
            irradiance->push_back(1.0f + 0.05f * p[(c + 1) % 3]);
        }
    auto shading = std::make_shared<MeshShading>();
    shading->asset = asset;
    shading->vertexRadiance = radiance;
    shading->vertexIrradiance = irradiance;
    shading->specular = false;
    shading->primId = 0;
    Frame frame;
    frame.rays = rays;
    frame.meshes.push_back(shading);
    return frame;
}

struct Buffers {
    std::vector<std::unique_ptr<hd::RenderBuffer>> owned;
    AovTargets targets{};

    Buffers(int width, int height) {
        for (std::size_t a = 0; a < hd::kAovCount; ++a) {
            const hd::AovDescriptor& aov = hd::aovDescriptor(hd::AovId(a));
            owned.push_back(std::make_unique<hd::RenderBuffer>("/Buffers/" + aov.name));
            owned.back()->allocate(width, height, aov.channelCount(), aov.clearValue);
            targets[a] = owned.back().get();
        }
    }
    const float* at(std::size_t aov, int x, int y) const {
        const hd::RenderBuffer& b = *owned[aov];
        return b.data().data() + (std::size_t(y) * b.width() + x) * std::size_t(b.channels());
    }
};

TEST(Draft, IsTheCentreSampleOfAnNTimesCoarserImageSpreadOverItsBlocks) {
    const Frame frame = paintedSphere();
    const hd::CameraDesc camera = test::frontCamera();
    const RenderOptions options;
    for (const int n : {2, 4}) {
        const int width = 96, height = 64;
        Buffers draft(width, height), coarse(width / n, height / n);
        ASSERT_TRUE(renderDraft(frame, CameraView(camera, width, height, "/Camera"), options, draft.targets, n));
        ASSERT_TRUE(renderPass(frame, CameraView(camera, width / n, height / n, "/Camera"), options, coarse.targets, 0));
        int hits = 0;
        for (std::size_t a = 0; a < hd::kAovCount; ++a) {
            const int channels = hd::aovDescriptor(hd::AovId(a)).channelCount();
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x)
                    for (int c = 0; c < channels; ++c) {
                        const float d = draft.at(a, x, y)[c], e = coarse.at(a, x / n, y / n)[c];
                        if (std::isinf(e)) EXPECT_EQ(d, e);  // depth where nothing is hit
                        else ASSERT_NEAR(d, e, 1e-4f * std::max(1.0f, std::abs(e)))
                            << hd::aovDescriptor(hd::AovId(a)).name << " pixel " << x << ", " << y << " block " << n;
                    }
        }
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) hits += draft.at(std::size_t(hd::AovId::PrimId), x, y)[0] == 0.0f;
        EXPECT_GT(hits, width * height / 8) << "the sphere is in view";
    }
}

TEST(Draft, BlocksClippedByTheImageEdgeHoldTheirBlocksValue) {
    const Frame frame = paintedSphere();
    const int width = 99, height = 66, n = 4;
    Buffers draft(width, height);
    ASSERT_TRUE(renderDraft(frame, CameraView(test::frontCamera(), width, height, "/Camera"), RenderOptions{},
                            draft.targets, n));
    const std::size_t color = std::size_t(hd::AovId::Color);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 4; ++c)
                ASSERT_EQ(draft.at(color, x, y)[c], draft.at(color, x / n * n, y / n * n)[c]) << x << ", " << y;
    EXPECT_THROW(renderDraft(frame, CameraView(test::frontCamera(), width, height, "/Camera"), RenderOptions{},
                             draft.targets, 0),
                 Error);
}

// The dome-and-key-light sphere rendered to convergence through the delegate.
struct Converged {
    std::vector<std::vector<float>> images;
    int passes = 0, samples = 0;
};

Converged renderWithDraft(int block) {
    OpalRenderDelegate delegate({{"opal:draftBlock", block}});
    test::CountingScene scene;
    hd::RenderIndex index(delegate);
    test::addSphere(scene, index);
    test::addCamera(scene, index);
    test::addLight(scene, index, "/World/Key", test::pointLight({20, 4, 12}, 300.0));
    hd::LightDesc dome;
    dome.kind = hd::LightKind::Dome;
    test::addLight(scene, index, "/World/Sky", dome);
    index.sync();
    const test::Aovs aovs = test::renderAovs(delegate, index, test::CameraPath, 150, 100);
    Converged out;
    for (const hd::Token& aov : test::allAovs()) out.images.push_back(aovs.data.at(aov));
    out.passes = delegate.passesDone();
    out.samples = std::get<int>(delegate.renderStats().at("samplesPerPixel"));
    return out;
}

TEST(Draft, TheConvergedFrameIsTheSameBitsWithOrWithoutIt) {
    const Converged plain = renderWithDraft(1);
    EXPECT_EQ(plain.passes, 17);
    for (const int block : {2, 3, 4}) {
        const Converged drafted = renderWithDraft(block);
        EXPECT_EQ(drafted.passes, 18) << "the draft is one more pass";
        EXPECT_EQ(drafted.samples, 16);
        const std::vector<hd::Token> names = test::allAovs();
        ASSERT_EQ(drafted.images.size(), plain.images.size());
        for (std::size_t i = 0; i < names.size(); ++i)
            EXPECT_EQ(0, std::memcmp(drafted.images[i].data(), plain.images[i].data(), plain.images[i].size() * sizeof(float)))
                << names[i] << " with draft block " << block;
    }
}

}  // namespace
}  // namespace opal
