// `opal-bench shadow-field`: what moving a shadow-field light costs (issue 14's measured
// item; docs/ARCHITECTURE.md#shadow-field-light). For each asset (default: the built-in
// candle and the Stanford bunny, baked at --samples through the bench's bake cache) and one
// baked local light (default: the candle's flame, `opal-bake light flame:height=24,radius=4`,
// cached the same way):
//
//   move         the light is placed at the next point of a path and its E recomputed, as the
//                delegate's commit does for a moved light: MeshIrradiance::setLight (the
//                light's arrivals, their Fresnel moments, the re-sum of every light's term;
//                a fixed point light is the other term). Median over the path's moves.
//   stages       the same arrivals again with each stage timed (ShadowFieldStages, in
//                thread-ms summed over the workers): setup (frame change, stencil),
//                interpolation (the weighted sparse maps), cosine (texel cosine integrals
//                and visibility blocks), visibility (occlusion rays); and what it did:
//                samples beyond the field, terms, texels, rays
//   move back    the light back at the path's start gives the first moments bit for bit
//   direct       the peer, in the same run: direct Embree integration of the same emitter
//                over the same samples (bake/light/direct_irradiance.h, the tests'
//                reference), timed, and the shadow field's relative RMSE against it
//   light bake   the light's bake time and sidecar size (from its report; a reused bake
//                says so)
//
// Paths: around the candle's wick, the flame's place in examples/scenes/candlelight.usda
// moved by up to 2 mm (an artist nudging it, a flicker's sway); around any other mesh, a
// horizontal circle about its bounding box's centre, pushed out until the emitter's bounding
// sphere clears the mesh.
#include "bench/cached_bake.h"
#include "bench/cached_light.h"
#include "bench/cpu_time.h"
#include "bench/median.h"
#include "bench/shared_assets.h"
#include "bench/subcommand.h"

#include "bake/light/direct_irradiance.h"
#include "delegate/relight/analytic_light.h"
#include "delegate/relight/mesh_irradiance.h"
#include "delegate/relight/shadow_field_light.h"
#include "delegate/relight/stopwatch.h"
#include "raytrace/ray_scene.h"
#include "schema/asset/shadow_field_file.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

namespace opal::bench {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// Issue 14's target on this 2-core machine: one light move at 65,536 samples.
constexpr double kMoveTargetMs = 40.0;
constexpr double kPi = std::numbers::pi;
// The candle scene's flame (examples/scenes/candlelight.usda): its light frame's origin.
const Imath::V3d kCandleFlame(1.5, 84.5, 0.0);

struct Options {
    std::vector<std::string> meshes;
    std::uint64_t samples = 65536;
    std::string light = "flame:height=24,radius=4";
    int moves = 21;
    int directSide = 32;
    fs::path cacheDir;
    fs::path jsonFile;
    bool rebakeLight = false;
    bool direct = true;
};

double loadAverage() {
    double load = -1.0;
    return getloadavg(&load, 1) == 1 ? load : -1.0;
}

Imath::M44d translation(const Imath::V3d& t) {
    Imath::M44d m;
    m.setTranslation(t);
    return m;
}

// The light frame's origins along the path, the first the light's home.
using Path = std::vector<Imath::V3d>;

Path wickPath(int moves) {
    Path path;
    for (int k = 0; k <= moves; ++k) {
        const double a = 2.0 * kPi * k / moves;
        path.push_back(kCandleFlame + Imath::V3d(1.5 * std::sin(a), 0.5 * std::sin(2.0 * a), 1.5 * (1.0 - std::cos(a))));
    }
    return path;
}

// True when a sphere at c of radius r is outside the mesh and does not cut it: no ray from c
// in 26 directions meets a back face first (c inside) or anything within r.
bool clearOfMesh(const RayScene& scene, const Imath::V3d& c, double r) {
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) {
                if (!x && !y && !z) continue;
                const Imath::V3f d = Imath::V3f(float(x), float(y), float(z)).normalized();
                const std::optional<RayHit> hit = scene.intersect(Ray(Imath::V3f(c), d, 0.0f, 1e30f));
                if (hit && (hit->t <= r || hit->geometricNormal.dot(d) > 0.0f)) return false;
            }
    return true;
}

Path aroundPath(const RayScene& scene, const ShadowField& field, int moves) {
    const Imath::Box3f box = scene.bounds();
    const Imath::V3d centre((box.min + box.max) * 0.5f);
    double radius = 0.5 * std::max(box.size().x, box.size().z);
    const auto at = [&](int k) {
        const double a = 2.0 * kPi * k / moves;
        return centre + Imath::V3d(radius * std::cos(a), 0.0, radius * std::sin(a));
    };
    for (int tries = 0; tries < 100; ++tries) {
        bool clear = true;
        for (int k = 0; k < moves && clear; ++k) clear = clearOfMesh(scene, at(k), field.emitterRadius);
        if (clear) break;
        radius *= 1.05;
    }
    Path path;
    for (int k = 0; k <= moves; ++k) path.push_back(at(k) - field.centre);
    return path;
}

AnalyticLight keyLight(const RayScene& scene);

// The asset (baked or reused), its shadow rays' scene and its irradiance with a fixed point light.
struct Subject {
    std::string label, input;
    CachedBake bake;
    RayScene scene;
    std::unique_ptr<MeshIrradiance> irradiance;

    Subject(const std::string& mesh, std::uint64_t samples, const fs::path& cacheDir) : label(bakeLabel(mesh)), input(mesh) {
        BakeOptions options;
        options.input = mesh;
        options.samples = samples;
        bake = bakeOrReuse(options, label, cacheDir / "bakes");
        std::printf("opal-bench shadow-field: %s %s (%zu samples)\n", bake.reused ? "reusing" : "baked",
                    bake.layer.c_str(), bake.asset->samples.size());
        scene.addMesh(bake.asset->mesh, Imath::M44d());
        scene.commit();
        irradiance = std::make_unique<MeshIrradiance>(bake.asset, Imath::M44d());
        irradiance->setLight("/Lights/Key", keyLight(scene), scene);
    }
};

hd::LightDesc fieldDesc(const CachedLight& light, const Imath::V3d& at) {
    hd::LightDesc d;
    d.kind = hd::LightKind::ShadowField;
    d.transform = translation(at);
    d.shadowField = light.sidecar.string();
    return d;
}

// A point light above the asset's box: the other term of the re-sum.
AnalyticLight keyLight(const RayScene& scene) {
    const Imath::Box3f box = scene.bounds();
    hd::LightDesc d;
    d.kind = hd::LightKind::Sphere;
    d.treatAsPoint = true;
    d.intensity = 1e4;
    d.transform = translation(Imath::V3d((box.min + box.max) * 0.5f) + Imath::V3d(0.0, 2.0 * box.size().y, 0.0));
    return AnalyticLight::fromDesc(d);
}

struct MoveSeries {
    std::vector<double> wall, cpu, arrivals, moments, resum;
};

struct StageSeries {
    std::vector<double> wall, setup, interpolation, cosine, visibility, farField;
    std::vector<ShadowFieldStages> counts;
};

struct Accuracy {
    double relativeRmse = 0.0, directMs = 0.0, directCpuMs = 0.0, arrivalsMs = 0.0;
    std::size_t litSamples = 0;
};

// The path's moves through MeshIrradiance::setLight; move 0 (the home) is untimed.
MoveSeries timeMoves(Subject& s, const std::shared_ptr<const LoadedShadowField>& field, const CachedLight& light,
                     const Path& path, bool& movesBackIdentical) {
    MoveSeries m;
    std::vector<float> home;
    for (std::size_t k = 0; k <= path.size(); ++k) {
        const Imath::V3d at = path[k % path.size()];  // the last move goes home again
        const double cpu = processCpuMilliseconds();
        const Stopwatch clock;
        s.irradiance->setLight("/Lights/Flame", std::make_shared<const ShadowFieldLight>(field, fieldDesc(light, at)),
                               s.scene);
        const double wall = clock.ms();
        if (k == 0) {
            home = s.irradiance->moments().values;
            continue;
        }
        if (k == path.size()) {
            const std::vector<float>& back = s.irradiance->moments().values;
            movesBackIdentical = back.size() == home.size() &&
                                 std::memcmp(back.data(), home.data(), home.size() * sizeof(float)) == 0;
            continue;
        }
        m.wall.push_back(wall);
        m.cpu.push_back(processCpuMilliseconds() - cpu);
        const MeshIrradiance::UpdateTimes& t = s.irradiance->lastUpdate();
        m.arrivals.push_back(t.arrivalsMs);
        m.moments.push_back(t.momentsMs);
        m.resum.push_back(t.resumMs);
    }
    return m;
}

float shadowOffset(const RayScene& scene) { return MeshIrradiance::kShadowOffset * scene.extent(); }

StageSeries timeStages(const Subject& s, const std::shared_ptr<const LoadedShadowField>& field,
                       const CachedLight& light, const Path& path) {
    StageSeries st;
    for (std::size_t k = 1; k < path.size(); ++k) {
        const ShadowFieldLight moved(field, fieldDesc(light, path[k]));
        ShadowFieldStages stages;
        const Stopwatch clock;
        (void)moved.arrivals(s.irradiance->samples(), &s.scene, shadowOffset(s.scene), &stages);
        st.wall.push_back(clock.ms());
        st.setup.push_back(stages.setupMs);
        st.interpolation.push_back(stages.interpolationMs);
        st.cosine.push_back(stages.cosineMs);
        st.visibility.push_back(stages.visibilityMs);
        st.farField.push_back(stages.farFieldMs);
        st.counts.push_back(stages);
    }
    return st;
}

// The shadow field's E against direct integration at the path's home, over every sample.
Accuracy measureAccuracy(const Subject& s, const std::shared_ptr<const LoadedShadowField>& field,
                         const CachedLight& light, const Imath::V3d& at, int side) {
    Accuracy a;
    const ShadowFieldLight home(field, fieldDesc(light, at));
    const PlacedSamples& placed = s.irradiance->samples();
    const float offset = shadowOffset(s.scene);
    const Stopwatch fieldClock;
    const std::vector<LightArrival> arrivals = home.arrivals(placed, &s.scene, offset);
    a.arrivalsMs = fieldClock.ms();
    const EmitterScene emitter(light.emitter);
    std::vector<Imath::V3d> direct(placed.positions.size());
    const double cpu = processCpuMilliseconds();
    const Stopwatch clock;
    tbb::parallel_for(std::size_t(0), direct.size(), [&](std::size_t i) {
        direct[i] = directIrradiance(emitter, &s.scene, at, Imath::V3d(placed.positions[i]),
                                     Imath::V3d(placed.normals[i]), offset, side);
    });
    a.directMs = clock.ms();
    a.directCpuMs = processCpuMilliseconds() - cpu;
    std::vector<Imath::V3d> fieldE(direct.size());
    for (std::size_t i = 0; i < direct.size(); ++i) {
        fieldE[i] = Imath::V3d(arrivals[i].irradiance) * double(arrivals[i].cosTheta);
        a.litSamples += direct[i].x + direct[i].y + direct[i].z > 0.0;
    }
    a.relativeRmse = relativeRmse(fieldE, direct);
    return a;
}

Json seriesJson(const std::vector<double>& v) {
    return {{"median", median(v)},
            {"min", v.empty() ? 0.0 : *std::min_element(v.begin(), v.end())},
            {"max", v.empty() ? 0.0 : *std::max_element(v.begin(), v.end())},
            {"all", v}};
}

// The median over moves of one count.
double countMedian(const StageSeries& st, const std::function<double(const ShadowFieldStages&)>& of) {
    std::vector<double> v;
    for (const ShadowFieldStages& c : st.counts) v.push_back(of(c));
    return median(v);
}

Json countsJson(const StageSeries& st) {
    const auto perSample = [&](auto field) {
        return countMedian(st, [&](const ShadowFieldStages& c) { return double(c.*field) / double(c.samples); });
    };
    return {{"samples", countMedian(st, [](const ShadowFieldStages& c) { return double(c.samples); })},
            {"beyond", countMedian(st, [](const ShadowFieldStages& c) { return double(c.beyond); })},
            {"facing_away", countMedian(st, [](const ShadowFieldStages& c) { return double(c.facingAway); })},
            {"terms_per_sample", perSample(&ShadowFieldStages::terms)},
            {"texels_per_sample", perSample(&ShadowFieldStages::texels)},
            {"rays_per_sample", perSample(&ShadowFieldStages::rays)},
            {"blocked_per_sample", perSample(&ShadowFieldStages::blocked)}};
}

void printSubject(const std::string& label, const MoveSeries& m, const StageSeries& st, bool back,
                  const std::optional<Accuracy>& a) {
    const double move = median(m.wall);
    std::printf("\n%s: light move %.1f ms median (min %.1f, max %.1f; CPU %.1f ms), target <= %.0f ms: %s (%.2fx "
                "the target)\n",
                label.c_str(), move, *std::min_element(m.wall.begin(), m.wall.end()),
                *std::max_element(m.wall.begin(), m.wall.end()), median(m.cpu), kMoveTargetMs,
                move <= kMoveTargetMs ? "met" : "MISSED", move / kMoveTargetMs);
    std::printf("  parts (wall ms): arrivals %.1f, moments %.2f, re-sum %.2f\n", median(m.arrivals),
                median(m.moments), median(m.resum));
    const double total = median(st.setup) + median(st.interpolation) + median(st.cosine) + median(st.visibility) +
                         median(st.farField);
    std::printf("  stages (thread-ms over the workers; staged call %.1f ms wall):", median(st.wall));
    const std::pair<const char*, const std::vector<double>*> parts[] = {
        {"setup", &st.setup}, {"interpolation", &st.interpolation}, {"cosine", &st.cosine},
        {"visibility", &st.visibility}, {"far field", &st.farField}};
    for (const auto& [name, series] : parts)
        std::printf(" %s %.1f (%.0f%%)", name, median(*series), 100.0 * median(*series) / total);
    std::printf("\n");
    const Json c = countsJson(st);
    std::printf("  per move: %.0f samples, %.0f facing away (skipped), %.0f beyond the field; per sample %.0f terms, "
                "%.0f texels, %.2f rays (%.2f blocked)\n",
                c["samples"].get<double>(), c["facing_away"].get<double>(), c["beyond"].get<double>(),
                c["terms_per_sample"].get<double>(), c["texels_per_sample"].get<double>(),
                c["rays_per_sample"].get<double>(), c["blocked_per_sample"].get<double>());
    std::printf("  moved back home: moments %s\n", back ? "identical bit for bit" : "DIFFER");
    if (a)
        std::printf("  direct integration (peer): %.0f ms (CPU %.0f ms), %.0fx the move; shadow field's relative RMSE "
                    "against it %.4f over %zu lit samples\n",
                    a->directMs, a->directCpuMs, a->directMs / move, a->relativeRmse, a->litSamples);
}

Json runSubject(const std::string& input, const Options& options, const CachedLight& light,
                const std::shared_ptr<const LoadedShadowField>& field) {
    Subject s(input, options.samples, options.cacheDir);
    const bool candle = input == "builtin:candle";
    const Path path = candle ? wickPath(options.moves) : aroundPath(s.scene, field->field, options.moves);
    bool back = false;
    const MoveSeries moves = timeMoves(s, field, light, path, back);
    const StageSeries stages = timeStages(s, field, light, path);
    std::optional<Accuracy> accuracy;
    if (options.direct) accuracy = measureAccuracy(s, field, light, path.front(), options.directSide);
    printSubject(s.label, moves, stages, back, accuracy);
    Json j = {{"label", s.label},
              {"input", input},
              {"samples", s.bake.asset->samples.size()},
              {"layer", s.bake.layer.string()},
              {"bake_reused", s.bake.reused},
              {"path", candle ? "around the wick, within 2 mm of the scene's flame" : "circle about the mesh"},
              {"path_origins", Json::array()},
              {"move_ms", seriesJson(moves.wall)},
              {"move_cpu_ms", seriesJson(moves.cpu)},
              {"target_ms", kMoveTargetMs},
              {"target_met", median(moves.wall) <= kMoveTargetMs},
              {"parts_ms", {{"arrivals", seriesJson(moves.arrivals)},
                            {"moments", seriesJson(moves.moments)},
                            {"resum", seriesJson(moves.resum)}}},
              {"stages_thread_ms", {{"staged_call_wall", seriesJson(stages.wall)},
                                    {"setup", seriesJson(stages.setup)},
                                    {"interpolation", seriesJson(stages.interpolation)},
                                    {"cosine", seriesJson(stages.cosine)},
                                    {"visibility", seriesJson(stages.visibility)},
                                    {"far_field", seriesJson(stages.farField)}}},
              {"counts", countsJson(stages)},
              {"moved_back_identical", back}};
    for (const Imath::V3d& p : path) j["path_origins"].push_back({p.x, p.y, p.z});
    if (accuracy)
        j["direct"] = {{"side", options.directSide},
                       {"ms", accuracy->directMs},
                       {"cpu_ms", accuracy->directCpuMs},
                       {"ratio_to_move", accuracy->directMs / median(moves.wall)},
                       {"shadow_field_arrivals_ms", accuracy->arrivalsMs},
                       {"relative_rmse", accuracy->relativeRmse},
                       {"lit_samples", accuracy->litSamples}};
    return j;
}

int run(const Options& options) {
    const double loadBefore = loadAverage();
    const CachedLight light = bakeLightOrReuse(options.light, options.cacheDir / "lights", options.rebakeLight);
    std::printf("opal-bench shadow-field: light %s: %s %s (%.1f MB sidecar, baked in %.1f s)\n", options.light.c_str(),
                light.reused ? "reusing" : "baked", light.sidecar.c_str(),
                light.report["sizes"]["sidecarBytes"].get<double>() / 1e6,
                light.report["time"]["totalSeconds"].get<double>());
    const Stopwatch loadClock;
    const auto field = std::make_shared<const LoadedShadowField>(readShadowFieldFile(light.sidecar));
    const double loadMs = loadClock.ms();
    std::fflush(stdout);
    Json subjects = Json::array();
    for (const std::string& mesh : options.meshes) subjects.push_back(runSubject(mesh, options, light, field));
    const double loadAfter = loadAverage();
    std::printf("\n%u hardware threads; load average %.1f before, %.1f after\n", std::thread::hardware_concurrency(),
                loadBefore, loadAfter);
    if (!options.jsonFile.empty()) {
        const Json results = {{"light", {{"spec", options.light},
                                         {"sidecar", light.sidecar.string()},
                                         {"reused", light.reused},
                                         {"load_ms", loadMs},
                                         {"sparse_entries", field->maps.entries()},
                                         {"bake_report", light.report}}},
                              {"subjects", subjects},
                              {"machine", {{"hardware_concurrency", std::thread::hardware_concurrency()},
                                           {"load_average_before", loadBefore},
                                           {"load_average_after", loadAfter}}}};
        writeFileAtomically(options.jsonFile, results.dump(2) + "\n");
        std::printf("wrote %s\n", options.jsonFile.c_str());
    }
    return 0;
}

int runShadowFieldBench(int argc, char** argv) {
    CLI::App app{"Shadow-field light move time, its stages, and its accuracy against direct integration",
                 "opal-bench shadow-field"};
    Options options;
    options.meshes = {"builtin:candle", (sharedAssets() / "meshes" / "stanford-bunny_watertight_quartet.obj").string()};
    options.cacheDir = fs::temp_directory_path() / "opal-bench-shadow-field";
    app.add_option("--mesh", options.meshes, "mesh to bake and light (repeatable; a file or builtin:candle)")
        ->capture_default_str();
    app.add_option("--samples", options.samples, "samples per baked asset")
        ->check(CLI::Range(std::uint64_t(64), std::uint64_t(1) << 22))
        ->capture_default_str();
    app.add_option("--light", options.light, "the light's spec, as `opal-bake light SPEC`")->capture_default_str();
    app.add_option("--moves", options.moves, "timed moves along the path")
        ->check(CLI::Range(2, 10000))
        ->capture_default_str();
    app.add_option("--direct-side", options.directSide, "direct integration: side x side directions per sample")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    app.add_flag("!--no-direct", options.direct, "skip the direct integration (no accuracy, no peer)");
    app.add_option("--cache-dir", options.cacheDir, "where baked assets and lights are kept and reused")
        ->capture_default_str();
    app.add_flag("--rebake-light", options.rebakeLight, "bake the light again even when a cached bake exists");
    app.add_option("--json", options.jsonFile, "also write the results as JSON to this file");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bench shadow-field: %s\n", e.what());
        return 1;
    }
}

}  // namespace

Subcommand shadowFieldSubcommand() {
    return {"shadow-field", "shadow-field light move time, stages, light bake, accuracy against direct integration",
            runShadowFieldBench};
}

}  // namespace opal::bench
