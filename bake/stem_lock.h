// The right to write one output stem (asset_stem.h), held from before a bake starts until
// its files are committed, so that two bakes of the same stem never interleave their
// writes: flock(2) on STEM.lock. A second bake does not wait: it fails at once, naming the
// lock file and the holder's process id, before any work. The kernel releases a flock when
// its holder dies, even by SIGKILL, so a killed bake never blocks the next one; the lock
// file is removed on release (a killed holder leaves it, and the next holder removes it).
#pragma once

#include "bake/asset_stem.h"

namespace opal {

class StemLock {
public:
    // Creates STEM.lock if needed and takes it. Throws opal::Error naming the lock file:
    // when another process holds it ("another opal-bake (pid N) is writing this asset"),
    // or when it cannot be created (a missing or unwritable folder).
    explicit StemLock(AssetStem stem);
    ~StemLock();
    StemLock(const StemLock&) = delete;
    StemLock& operator=(const StemLock&) = delete;

    const AssetStem& stem() const { return stem_; }

private:
    AssetStem stem_;
    int fd_ = -1;
};

}  // namespace opal
