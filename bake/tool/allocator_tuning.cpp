#include "bake/tool/allocator_tuning.h"

#include <malloc.h>

namespace opal {

void keepAllocatorMemory() {
    constexpr int kLargestHeapBlock = 32 << 20;  // glibc's maximum mmap threshold on 64-bit
    mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace opal
