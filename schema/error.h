// Opal's one exception type. Every message says where (file, chunk, line:column,
// parameter) and what is wrong, so that a pipeline log is enough to act on it.
#pragma once

#include <stdexcept>
#include <string>

namespace opal {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace opal
