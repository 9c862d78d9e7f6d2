#include "bake/bake_identifier.h"

#include "schema/asset/sidecar.h"
#include "schema/asset/xxhash64.h"
#include "schema/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <span>
#include <sstream>
#include <vector>

#ifndef OPAL_VERSION
#error "bake/CMakeLists.txt defines OPAL_VERSION for this file"
#endif

namespace opal {
namespace {

std::string hex(std::uint64_t v) {
    char text[24];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

// Doubles as C99 hexadecimal floats: exact, so no two settings share a line.
std::string exact(double v) {
    char text[48];
    std::snprintf(text, sizeof text, "%a", v);
    return text;
}

std::uint64_t hashFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot read the input to identify the bake: " + std::strerror(errno));
    Xxh64 hash;
    std::vector<char> buffer(1 << 20);
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        hash.update(std::as_bytes(std::span(buffer.data(), std::size_t(in.gcount()))));
    }
    if (in.bad()) throw Error(path + ": cannot read the input to identify the bake");
    return hash.digest();
}

template <class T>
void hashVector(Xxh64& hash, const std::vector<T>& values) {
    const std::uint64_t count = values.size();
    hash.update(std::as_bytes(std::span(&count, 1)));
    hash.update(std::as_bytes(std::span(values)));
}

std::uint64_t hashRenderMesh(const RenderMesh& mesh) {
    Xxh64 hash;
    hashVector(hash, mesh.points);
    hashVector(hash, mesh.normals);
    hashVector(hash, mesh.faceVertexCounts);
    hashVector(hash, mesh.faceVertexIndices);
    return hash.digest();
}

}  // namespace

std::string bakeIdentity(const BakeOptions& options, const TranslucentAsset& asset) {
    const bool builtin = options.input.starts_with("builtin:");
    const EditableRange& r = asset.range;
    const Material& m = asset.defaultMaterial;
    std::ostringstream s;
    s << "tool opal-bake " << OPAL_VERSION << '\n'
      << "input " << options.input << '\n'
      << "input bytes " << (builtin ? std::string("built in") : hex(hashFile(options.input))) << '\n'
      // Only when given, so that every other bake keeps its identifier.
      << (options.applyTo.empty() ? std::string() : "apply to <" + options.applyTo + ">\n")
      << "render mesh " << hex(hashRenderMesh(asset.mesh)) << '\n'
      << "name " << asset.name << '\n'
      << "scheme " << asset.bake.scheme << '\n'
      << "level " << asset.bake.level << '\n'
      << "samples " << asset.layout.charts << " charts x 4^" << asset.layout.log2Size << '\n'
      << "units per mm " << exact(asset.unitsPerMm) << '\n'
      << "range " << exact(r.sigmaSPrimeMin) << ' ' << exact(r.sigmaSPrimeMax) << ' ' << exact(r.sigmaAMin) << ' '
      << exact(r.sigmaAMax) << ' ' << exact(r.etaMin) << ' ' << exact(r.etaMax) << '\n'
      << "material " << options.material;
    for (int c = 0; c < 3; ++c) s << ' ' << exact(m.sigmaSPrime[c]) << ' ' << exact(m.sigmaA[c]);
    s << ' ' << exact(m.eta) << '\n' << compressionIdentity(options);
    return s.str();
}

std::string compressionIdentity(const BakeOptions& options) {
    std::ostringstream s;
    s << "sidecar " << kSidecarKind.version.major << '.' << kSidecarKind.version.minor << '\n'
      << "basis " << options.basisCount << '\n'
      << "keep " << exact(options.transfer.keepFraction) << ' ' << options.transfer.minPerRow << '\n'
      << "energy " << exact(options.transfer.energyFraction) << '\n'
      << "environment " << options.visibility.cubeFaceSize << ' ' << options.visibility.terms << ' '
      << exact(options.visibility.error) << ' ' << options.visibility.fresnelTerms << ' ' << std::uint32_t(options.visibility.fresnelBasis) << '\n'
      << "seed " << options.seed << '\n';
    return s.str();
}

std::uint64_t bakeIdentifier(const BakeOptions& options, const TranslucentAsset& asset) {
    const std::string identity = bakeIdentity(options, asset);
    return xxh64(std::as_bytes(std::span(identity.data(), identity.size())));
}

}  // namespace opal
