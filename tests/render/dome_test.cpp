// Dome lights: irradiance through the baked environment vectors, the background, the
// specular reflection, and textures read and converted to the working space.
#include "delegate/render_delegate.h"

#include "schema/scatter/dipole.h"
#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <numbers>
#include <unistd.h>

namespace opal {
namespace {

constexpr int DomeWidth = 96, DomeHeight = 64;
const hd::SdfPath SkyPath = "/World/Sky";

// 2 pi integral_0^1 F_t(eta, mu) mu dmu: what a uniform unit sky gives an unoccluded surface.
double skyIrradiance(double eta) {
    double sum = 0.0;
    for (int q = 0; q < 20000; ++q) {
        const double mu = (q + 0.5) / 20000.0;
        sum += fresnelTransmittance(eta, mu) * mu / 20000.0;
    }
    return 2.0 * std::numbers::pi * sum;
}

struct DomeScene {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index{delegate};

    DomeScene(const hd::LightDesc& dome, const std::map<hd::Token, hd::Value>& settings = {}) : delegate(settings) {
        test::addSphere(scene, index);
        test::addCamera(scene, index);
        test::addLight(scene, index, SkyPath, dome);
        index.sync();
    }
    test::Aovs render() { return test::renderAovs(delegate, index, test::CameraPath, DomeWidth, DomeHeight); }
};

hd::LightDesc uniformDome(Rgb color) {
    hd::LightDesc dome;
    dome.kind = hd::LightKind::Dome;
    dome.color = color;
    return dome;
}

TEST(Dome, AUniformDomeIsTheBackgroundAndLightsTheSphereEvenly) {
    const Rgb sky(0.5, 0.7, 1.0);
    DomeScene s(uniformDome(sky));
    const test::Aovs a = s.render();
    const double eta = test::sharedSphere()->defaultMaterial.eta;
    const double expectedE = skyIrradiance(eta);
    // The camera sits at (0, 0, 30) looking down -Z.
    const auto viewDirection = [](int x, int y) {
        const double sx = (2.0 * (x + 0.5) / DomeWidth - 1.0) * 0.36, sy = (1.0 - 2.0 * (y + 0.5) / DomeHeight) * 0.24;
        return Imath::V3d(sx, sy, -1.0).normalized();
    };
    double minRatio = 1e30, maxRatio = 0.0, minRaw = 1e30, maxRaw = 0.0;
    int hits = 0;
    for (int y = 0; y < DomeHeight; ++y)
        for (int x = 0; x < DomeWidth; ++x) {
            EXPECT_EQ(a.at("alpha", x, y)[0], 1.0f);  // the dome covers what the sphere does not
            EXPECT_EQ(a.at("color", x, y)[3], 1.0f);
            if (test::background(a, x, y)) {
                for (int c = 0; c < 3; ++c) EXPECT_EQ(a.at("color", x, y)[c], float(sky[c]));
            }
            if (!test::interior(a, x, y)) continue;
            ++hits;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(a.at("irradiance", x, y)[c], expectedE * sky[c], 0.03 * expectedE * sky[c]);
            // Under uniform light the sphere's L is nearly uniform (up to the coarse sampling),
            // so subsurface / F_t(eta, n.w_o) varies much less than the subsurface itself:
            // the outgoing Fresnel factor is applied per pixel.
            const float* n = a.at("normal", x, y);
            const double mu = -Imath::V3d(n[0], n[1], n[2]).dot(viewDirection(x, y));
            if (mu < 0.3) continue;
            const double ratio = a.at("subsurface", x, y)[0] / fresnelTransmittance(eta, mu);
            minRaw = std::min(minRaw, double(a.at("subsurface", x, y)[0]));
            maxRaw = std::max(maxRaw, double(a.at("subsurface", x, y)[0]));
            minRatio = std::min(minRatio, ratio);
            maxRatio = std::max(maxRatio, ratio);
        }
    EXPECT_GT(hits, 100);
    EXPECT_LT(maxRatio / minRatio - 1.0, 0.4 * (maxRaw / minRaw - 1.0));
    EXPECT_LT(maxRatio / minRatio, 1.08);
    // The specular layer reflects the dome: F_r(eta, n.w_o) x sky radiance.
    const float* centre = a.at("specular", DomeWidth / 2, DomeHeight / 2);
    const float* normal = a.at("normal", DomeWidth / 2, DomeHeight / 2);
    const double fr = 1.0 - fresnelTransmittance(eta, -Imath::V3d(normal[0], normal[1], normal[2]).dot(viewDirection(DomeWidth / 2, DomeHeight / 2)));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], fr * sky[c], 1e-5);
}

TEST(Dome, ReferenceModeIntegratesTheDomeInsteadOfTheBakedVectors) {
    // The sphere with baked vectors that claim it hides its whole sky: the engine's E is 0,
    // while the reference integrates the sky against the mesh itself, which is convex and
    // sees every sample's hemisphere: E = 2 pi int F_t mu dmu x sky.
    auto blind = std::make_shared<TranslucentAsset>(*test::sharedSphere());
    blind->environment = test::environmentTransfer(*blind, blind->environment.cubeFaceSize, 3,
                                                   [](std::size_t, const Imath::V3f&) { return false; });
    const Rgb sky(0.5, 0.7, 1.0);
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index{delegate};
    scene.meshes[test::SpherePath] = hd::MeshDesc{blind, Imath::M44d(), {}, true};
    index.insertRprim(hd::PrimType::TranslucentMesh, scene, test::SpherePath);
    test::addCamera(scene, index);
    test::addLight(scene, index, SkyPath, uniformDome(sky));
    index.sync();
    const double expectedE = skyIrradiance(blind->defaultMaterial.eta);
    for (bool reference : {false, true}) {
        delegate.setRenderSetting("opal:reference", reference);
        const test::Aovs a = test::renderAovs(delegate, index, test::CameraPath, DomeWidth, DomeHeight);
        int hits = 0;
        for (int y = 0; y < DomeHeight; ++y)
            for (int x = 0; x < DomeWidth; ++x) {
                if (!test::interior(a, x, y)) continue;
                ++hits;
                for (int c = 0; c < 3; ++c) {
                    const double expected = reference ? expectedE * sky[c] : 0.0;
                    EXPECT_NEAR(a.at("irradiance", x, y)[c], expected, 0.005 * expectedE * sky[c])
                        << (reference ? "reference" : "engine") << " at " << x << ", " << y;
                }
            }
        EXPECT_GT(hits, 100);
    }
}

TEST(Dome, TheBackgroundCanBeTransparentOrHidden) {
    DomeScene transparent(uniformDome({1.0, 1.0, 1.0}), {{"opal:transparentBackground", true}});
    const test::Aovs t = transparent.render();
    hd::LightDesc hidden = uniformDome({1.0, 1.0, 1.0});
    hidden.visibleToCamera = false;
    DomeScene invisible(hidden);
    const test::Aovs i = invisible.render();
    DomeScene visible(uniformDome({1.0, 1.0, 1.0}));
    const test::Aovs v = visible.render();
    for (int y = 0; y < DomeHeight; ++y)
        for (int x = 0; x < DomeWidth; ++x)
            for (const test::Aovs* a : {&t, &i}) {
                if (test::interior(*a, x, y)) {
                    EXPECT_EQ(a->at("alpha", x, y)[0], 1.0f);
                }
                if (!test::background(*a, x, y)) continue;
                EXPECT_EQ(a->at("alpha", x, y)[0], 0.0f);
                for (int c = 0; c < 4; ++c) EXPECT_EQ(a->at("color", x, y)[c], 0.0f);
            }
    // The objects look the same whatever the background.
    EXPECT_EQ(t.data.at("subsurface"), v.data.at("subsurface"));
    EXPECT_EQ(i.data.at("specular"), v.data.at("specular"));
}

TEST(Dome, RotatingTheDomeRecomputesOnlyTheDome) {
    DomeScene s(uniformDome({1.0, 1.0, 1.0}));
    test::addLight(s.scene, s.index, "/World/Key", test::pointLight({20, 4, 12}, 300.0));
    s.index.sync();
    const auto evaluations = s.delegate.totals().lightEvaluations;
    s.scene.lights[SkyPath].transform.setAxisAngle(Imath::V3d(0, 1, 0), 0.5);
    s.index.changeTracker().markDirty(SkyPath, hd::Dirty::Transform);
    s.index.sync();
    EXPECT_EQ(s.delegate.totals().lightEvaluations, evaluations + 1);
}

class TempDir {
public:
    TempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "opal-render-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~TempDir() { std::filesystem::remove_all(path_); }
    std::string operator/(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

void writeUniformExr(const std::string& file, int width, int height, const float rgb[3]) {
    std::vector<float> pixels(std::size_t(width) * height * 3);
    for (std::size_t p = 0; p < pixels.size(); ++p) pixels[p] = rgb[p % 3];
    auto out = OIIO::ImageOutput::create(file);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(out->open(file, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
}

TEST(Dome, TexturesAreConvertedToTheWorkingSpace) {
    TempDir dir;
    const float rec709[3] = {0.2f, 0.5f, 0.9f};
    writeUniformExr(dir / "sky.exr", 16, 8, rec709);
    hd::LightDesc dome = uniformDome({1.0, 1.0, 1.0});
    dome.textureFile = dir / "sky.exr";
    dome.textureColorSpace = "Linear Rec.709 (sRGB)";
    const std::string shipped = std::string(OPAL_SOURCE_DIR) + "/delegate/output/ocio/config.ocio";
    DomeScene s(dome, {{"opal:ocioConfig", shipped}});
    const test::Aovs a = s.render();
    // Linear Rec.709 -> ACEScg (the shipped config's scene_linear), Bradford D65 -> D60.
    const double m[3][3] = {{0.613097, 0.339523, 0.047379}, {0.070194, 0.916354, 0.013452}, {0.020616, 0.109570, 0.869815}};
    for (int c = 0; c < 3; ++c) {
        const double expected = m[c][0] * rec709[0] + m[c][1] * rec709[1] + m[c][2] * rec709[2];
        EXPECT_NEAR(a.at("color", 0, 0)[c], expected, 2e-3) << c;
    }

    // Editing the dome's intensity reuses the texture (the file is gone: it is not re-read).
    std::filesystem::remove(dir / "sky.exr");
    s.scene.lights[SkyPath].intensity = 2.0;
    s.index.changeTracker().markDirty(SkyPath, hd::Dirty::Params);
    EXPECT_NO_THROW(s.index.sync());
    const test::Aovs brighter = s.render();
    EXPECT_NEAR(brighter.at("color", 0, 0)[1], 2.0f * a.at("color", 0, 0)[1], 1e-5);

    // Another file that does not exist: the error names the light and the file.
    s.scene.lights[SkyPath].textureFile = dir / "missing.exr";
    s.index.changeTracker().markDirty(SkyPath, hd::Dirty::Params);
    try {
        s.index.sync();
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(SkyPath), std::string::npos) << message;
        EXPECT_NE(message.find("missing.exr"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace opal
