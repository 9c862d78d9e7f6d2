// Where something was read from: file, 1-based line and column (columns count bytes).
// Prims, properties, metadata and values keep one, so that consumers (the asset and
// scene readers) can report semantic errors as file:line:column too.
#pragma once

#include <memory>
#include <string>

namespace opal::usda {

struct SourceLocation {
    std::shared_ptr<const std::string> file;  // null for things built in memory
    int line = 0;                             // 0: unknown
    int column = 0;

    // "scene.usda:7:9"; "scene.usda" without a line; "<memory>" without a file.
    std::string str() const {
        std::string where = file ? *file : std::string("<memory>");
        if (line > 0) {
            where += ':' + std::to_string(line) + ':' + std::to_string(column);
        }
        return where;
    }

    // Provenance is not content: two layers that say the same thing compare equal
    // wherever they were read from. This lets models compare with defaulted ==.
    friend bool operator==(const SourceLocation&, const SourceLocation&) { return true; }
};

}  // namespace opal::usda
