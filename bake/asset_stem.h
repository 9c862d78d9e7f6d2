// The files one output stem owns (`opal-bake -o STEM`), all in STEM's folder:
//
//   STEM.usda              the layer; renaming it into place is the bake's commit point
//   STEM.<bake id>.opal    the sidecar of the bake with that identifier (the layer names it)
//   STEM.opal              the sidecar of an asset baked before bake identifiers existed
//   STEM.lock              held by the bake writing the stem (stem_lock.h)
//   <one of these>.tmp-*   a temporary file of an atomic write (schema/usd/atomic_file.h)
//
// A bake writes its sidecar under a name no other bake's sidecar has, then the layer that
// names it; so until the layer's rename the stem holds the previous asset, complete, and
// afterwards the new one. Sidecars the layer no longer names, and temporaries of writers
// that were killed, are removed by the bake that holds the lock. A sidecar of the stem is
// the stem's own: copies of the layer elsewhere that name it are not looked for.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

class AssetStem {
public:
    explicit AssetStem(std::filesystem::path stem);

    const std::filesystem::path& stem() const { return stem_; }
    std::filesystem::path layer() const;                       // STEM.usda
    std::filesystem::path sidecar(std::uint64_t bakeId) const;  // STEM.<bake id>.opal
    std::filesystem::path lockFile() const;                    // STEM.lock

    // Is `fileName` (a name in the stem's folder) one of the stem's sidecars, or a
    // temporary file of a write to the layer or a sidecar?
    bool isSidecar(std::string_view fileName) const;
    bool isTemporary(std::string_view fileName) const;

    // Removes the temporary files of writers that were killed; call with the lock held,
    // when no writer of this stem can be running. A file that cannot be removed adds a
    // warning (it is harmless: the next bake tries again).
    void removeStaleTemporaries(std::vector<std::string>* warnings) const;

    // Removes every sidecar of the stem but the one of `keep`; call after the commit, with
    // the lock held. Reaches the crash point "bake:pruned-one" after each removal.
    void removeSidecarsExcept(std::uint64_t keep, std::vector<std::string>* warnings) const;

private:
    // The part of `fileName` after "<stem name>.", or nothing when it does not start so.
    std::optional<std::string_view> suffix(std::string_view fileName) const;
    template <class Predicate>
    std::vector<std::filesystem::path> filesWhere(Predicate keepIt) const;

    std::filesystem::path stem_;
    std::string name_;  // the stem's file name, "candle"
};

}  // namespace opal
