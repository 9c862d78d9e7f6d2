// The error every USDA reader/writer failure throws: an opal::Error whose message
// starts with file:line:column, and which keeps the location for callers that want it.
#pragma once

#include "schema/error.h"
#include "schema/usd/usda_location.h"

#include <string>

namespace opal::usda {

class UsdaError : public opal::Error {
public:
    UsdaError(SourceLocation where, const std::string& message)
        : opal::Error(where.str() + ": " + message), where_(std::move(where)) {}

    const SourceLocation& where() const { return where_; }

private:
    SourceLocation where_;
};

}  // namespace opal::usda
