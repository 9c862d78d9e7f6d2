#include "schema/asset/bake_id.h"

namespace opal {

std::string formatBakeId(std::uint64_t id) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string text(kBakeIdDigits, '0');
    for (std::size_t i = kBakeIdDigits; i-- > 0; id >>= 4) text[i] = kDigits[id & 0xf];
    return text;
}

std::optional<std::uint64_t> parseBakeId(std::string_view text) {
    if (text.size() != kBakeIdDigits) return std::nullopt;
    std::uint64_t id = 0;
    for (char c : text) {
        int digit = -1;
        if (c >= '0' && c <= '9') digit = c - '0';
        if (c >= 'a' && c <= 'f') digit = c - 'a' + 10;
        if (digit < 0) return std::nullopt;
        id = (id << 4) | std::uint64_t(digit);
    }
    return id;
}

}  // namespace opal
