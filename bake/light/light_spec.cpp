#include "bake/light/light_spec.h"

#include "bake/light/emitter_shapes.h"
#include "bake/light/flame_emitter.h"
#include "schema/error.h"

#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace opal {
namespace {

struct KindKeys {
    std::string_view kind;
    std::vector<std::string_view> required, optional;
};

const std::vector<KindKeys>& kinds() {
    static const std::vector<KindKeys> table = {
        {"sphere", {"radius"}, {"radiance"}},
        {"disk", {"radius"}, {"radiance"}},
        {"rectangle", {"width", "height"}, {"radiance"}},
        {"lamp", {"radius", "height"}, {"shade_radius", "shade_height", "radiance"}},
        {"mesh", {"file"}, {"radiance"}},
        {"flame", {"height", "radius"}, {"core_k", "rim_k", "luminance"}},
    };
    return table;
}

std::string join(const std::vector<std::string_view>& words) {
    std::string text;
    for (std::string_view w : words) text += (text.empty() ? "" : ", ") + std::string(w);
    return text;
}

class SpecReader {
public:
    explicit SpecReader(std::string_view spec) : spec_(spec) {
        const std::size_t colon = spec.find(':');
        kind_ = spec.substr(0, colon);
        keys_ = findKind();
        if (colon == std::string_view::npos) fail("expected KIND:KEY=VALUE,... (" + lightSpecHelp() + ")");
        parsePairs(spec.substr(colon + 1));
        for (std::string_view key : keys_->required)
            if (!values_.count(std::string(key))) fail("missing " + std::string(key) + "=");
    }

    const std::string& kind() const { return kind_; }

    double number(std::string_view key, double fallback) const {
        const auto it = values_.find(std::string(key));
        return it == values_.end() ? fallback : parseNumber(key, it->second);
    }
    double positive(std::string_view key, double fallback = NAN) const {
        const double v = number(key, fallback);
        if (!(v > 0.0)) fail(std::string(key) + "=" + text(key) + " must be positive");
        return v;
    }
    std::string text(std::string_view key) const {
        const auto it = values_.find(std::string(key));
        return it == values_.end() ? std::string() : it->second;
    }
    Imath::V3f radiance() const {
        const std::string value = text("radiance");
        if (value.empty()) return Imath::V3f(1.0f);
        std::vector<double> channels;
        std::size_t start = 0;
        for (std::size_t slash; (slash = value.find('/', start)) != std::string::npos; start = slash + 1)
            channels.push_back(parseNumber("radiance", value.substr(start, slash - start)));
        channels.push_back(parseNumber("radiance", value.substr(start)));
        if (channels.size() != 1 && channels.size() != 3) fail("radiance=" + value + " must be L or R/G/B");
        for (double c : channels)
            if (c < 0.0) fail("radiance=" + value + " must not be negative");
        if (channels.size() == 1) return Imath::V3f(float(channels[0]));
        return {float(channels[0]), float(channels[1]), float(channels[2])};
    }
    [[noreturn]] void fail(const std::string& problem) const {
        throw Error("light spec '" + std::string(spec_) + "': " + problem);
    }

private:
    const KindKeys* findKind() const {
        for (const KindKeys& k : kinds())
            if (k.kind == kind_) return &k;
        std::vector<std::string_view> names;
        for (const KindKeys& k : kinds()) names.push_back(k.kind);
        fail("unknown kind '" + kind_ + "' (kinds: " + join(names) + ")");
    }

    void parsePairs(std::string_view list) {
        std::size_t start = 0;
        while (start <= list.size()) {
            const std::size_t comma = std::min(list.find(',', start), list.size());
            const std::string_view pair = list.substr(start, comma - start);
            const std::size_t equals = pair.find('=');
            if (equals == std::string_view::npos || equals == 0 || equals + 1 == pair.size())
                fail(std::string(pair).insert(0, 1, '\'') + "' is not KEY=VALUE");
            const std::string key(pair.substr(0, equals));
            if (!known(key)) {
                std::vector<std::string_view> all = keys_->required;
                all.insert(all.end(), keys_->optional.begin(), keys_->optional.end());
                fail("unknown key '" + key + "' for " + kind_ + " (keys: " + join(all) + ")");
            }
            if (!values_.emplace(key, pair.substr(equals + 1)).second) fail("key '" + key + "' given twice");
            start = comma + 1;
        }
    }
    bool known(const std::string& key) const {
        for (const auto* list : {&keys_->required, &keys_->optional})
            for (std::string_view k : *list)
                if (k == key) return true;
        return false;
    }
    double parseNumber(std::string_view key, const std::string& value) const {
        double v = 0.0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), v);
        if (error != std::errc() || end != value.data() + value.size() || !std::isfinite(v))
            fail(std::string(key) + "=" + value + " is not a finite number");
        return v;
    }

    std::string_view spec_;
    std::string kind_;
    const KindKeys* keys_ = nullptr;
    std::map<std::string, std::string> values_;
};

Emitter build(const SpecReader& r) {
    const std::string& kind = r.kind();
    if (kind == "sphere") return sphereEmitter(r.positive("radius"), r.radiance());
    if (kind == "disk") return diskEmitter(r.positive("radius"), r.radiance());
    if (kind == "rectangle") return rectangleEmitter(r.positive("width"), r.positive("height"), r.radiance());
    if (kind == "lamp") {
        LampShape s;
        s.radius = r.positive("radius");
        s.height = r.positive("height");
        s.shadeRadius = r.positive("shade_radius", 1.5 * s.radius);
        s.shadeHeight = r.positive("shade_height", 1.25 * s.height);
        if (!(s.shadeRadius > s.radius)) r.fail("shade_radius must exceed radius");
        return lampEmitter(s, r.radiance());
    }
    if (kind == "mesh") {
        try {
            return meshEmitter(r.text("file"), r.radiance());
        } catch (const Error& e) {
            r.fail(e.what());
        }
    }
    FlameShape s;
    s.height = r.positive("height");
    s.radius = r.positive("radius");
    s.coreKelvin = r.positive("core_k", s.coreKelvin);
    s.rimKelvin = r.positive("rim_k", s.rimKelvin);
    s.luminance = r.positive("luminance", s.luminance);
    for (double k : {s.coreKelvin, s.rimKelvin})
        if (k < 500.0 || k > 40000.0) r.fail("colour temperatures must be within 500 to 40000 K");
    return flameEmitter(s);
}

}  // namespace

Emitter parseLightSpec(std::string_view spec) {
    return build(SpecReader(spec));
}

std::string lightSpecHelp() {
    std::string text;
    for (const KindKeys& k : kinds()) {
        std::vector<std::string_view> keys = k.required;
        for (std::string_view o : k.optional) keys.push_back(o);
        text += (text.empty() ? "" : "; ") + std::string(k.kind) + ":" + join(keys);
    }
    return text;
}

}  // namespace opal
