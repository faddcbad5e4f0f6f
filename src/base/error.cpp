#include "base/error.hpp"

#include "base/c_locale.hpp"

#include <cstdarg>
#include <cstdio>
#include <vector>

namespace eg2d {

std::string format(const char *fmt, ...) {
    const CLocaleScope c;  // messages and JSON numbers: 0.5 whatever the host's locale
    va_list args;
    va_start(args, fmt);
    va_list copy;
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, fmt, copy);
    va_end(copy);
    std::string out;
    if (n > 0) {
        std::vector<char> buf(static_cast<size_t>(n) + 1);
        std::vsnprintf(buf.data(), buf.size(), fmt, args);
        out.assign(buf.data(), static_cast<size_t>(n));
    }
    va_end(args);
    return out;
}

}  // namespace eg2d
