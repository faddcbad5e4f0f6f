// Building the text of an SVG file: printf into a std::string, and text
// escaped for XML (a title may hold a file's name).
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>

namespace eg2dtool {

// printf into the end of `out` (one call writes at most 255 characters).
template <class... Args>
void append(std::string &out, const char *fmt, Args... args) {
    char buf[256];
    const int n = std::snprintf(buf, sizeof buf, fmt, args...);
    if (n > 0) out.append(buf, static_cast<std::size_t>(std::min<int>(n, static_cast<int>(sizeof buf) - 1)));
}

inline std::string xml_text(const std::string &s) {
    std::string out;
    for (char ch : s) {
        if (ch == '&') out += "&amp;";
        else if (ch == '<') out += "&lt;";
        else if (ch == '>') out += "&gt;";
        else if (ch == '"') out += "&quot;";
        else out += ch;
    }
    return out;
}

}  // namespace eg2dtool
