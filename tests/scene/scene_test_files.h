// What the scene tests share: a fresh directory per test, scene text written into it, and
// a small translucent asset on disk (the lossless cube-sphere of tests/render, written as
// a real asset layer + sidecar pair, so readAsset validates it like a baked one).
#pragma once

#include "schema/asset/asset_layer.h"
#include "schema/asset/sidecar.h"
#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace opal::test {

class SceneDir {
public:
    SceneDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string(info->test_suite_name()) + "-" + info->name();
        std::replace(name.begin(), name.end(), '/', '_');  // parameterized tests: "Table/Case/0"
        path_ = std::filesystem::temp_directory_path() / ("opal-scene-" + std::to_string(::getpid()) + "-" + name);
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~SceneDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    SceneDir(const SceneDir&) = delete;
    SceneDir& operator=(const SceneDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const std::filesystem::path file = path_ / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

    // STEM.usda + STEM.opal: a 5 mm cube-sphere (6 x 4 x 4 samples), scene units = mm,
    // with a bake identifier in both halves as a bake writes it; without environment
    // vectors unless `domeLit` (then 6 x 8 x 8 texels each, so that a dome light lights it).
    std::filesystem::path writeSphereAsset(const std::string& stem, bool domeLit = false) const {
        static const std::shared_ptr<const TranslucentAsset> plain = sphere(0, 0x5e1f0b5e55ed0001ull);
        static const std::shared_ptr<const TranslucentAsset> lit = sphere(8, 0x5e1f0b5e55ed0002ull);
        const TranslucentAsset& asset = domeLit ? *lit : *plain;
        writeSidecar(path_ / (stem + ".opal"), asset);
        writeAssetLayer(path_ / (stem + ".usda"), asset, "./" + stem + ".opal");
        return path_ / (stem + ".usda");
    }

private:
    static std::shared_ptr<const TranslucentAsset> sphere(std::uint32_t envFaceSize, std::uint64_t identifier) {
        auto asset = std::make_shared<TranslucentAsset>(*sphereAsset(2, 5.0f, envFaceSize));
        asset->bake.identifier = identifier;
        return asset;
    }

    std::filesystem::path path_;
};

}  // namespace opal::test
