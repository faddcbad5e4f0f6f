// Bounded line reading, classification and quoting for airfoil_file.cpp.
#include "geometry/airfoil_lines.hpp"

#include <cstdlib>

#include "base/c_locale.hpp"
#include "base/error.hpp"

namespace eg2d {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

// Control bytes other than blanks mean the file is not text; bytes from 0x80
// are allowed (a name line in UTF-8 or Latin-1).
bool binary(const std::string &text) {
    for (char ch : text) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if ((c < 0x20 && !is_blank(ch)) || c == 0x7f) return true;
    }
    return false;
}

}  // namespace

std::string quoted(const std::string &text) {
    constexpr std::size_t kShown = 60;
    std::string out = "\"";
    std::size_t shown = 0, k = 0;
    for (; k < text.size() && shown < kShown; ++k) {
        const unsigned char c = static_cast<unsigned char>(text[k]);
        if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
            out += static_cast<char>(c);
            ++shown;
        } else {
            char esc[8];
            std::snprintf(esc, sizeof esc, c == '"' || c == '\\' ? "\\%c" : "\\x%02X", c);
            out += esc;
            shown += 1;
        }
    }
    out += k < text.size() ? "\"..." : "\"";
    return out;
}

bool parse_pair(const std::string &text, double &x, double &y) {
    const char *s = text.c_str();
    char *end;
    x = strtod_c(s, &end);
    if (end == s) return false;
    s = end;
    while (is_blank(*s)) ++s;
    if (*s == ',') ++s;
    while (is_blank(*s)) ++s;
    if (s == end && *s != '-' && *s != '+') return false;  // "1 2", "1,2", "1-2" (fixed columns), not "1.2.3"
    y = strtod_c(s, &end);
    if (end == s) return false;
    for (s = end; *s; ++s)
        if (!is_blank(*s)) return false;
    return true;
}

bool AirfoilLines::next(AirfoilLine &line) {
    line.text.clear();
    int c = std::fgetc(file_);
    if (c == EOF) return false;
    line.number = ++number_;
    for (; c != EOF && c != '\n'; c = std::fgetc(file_)) {
        if (c == '\r') {  // CRLF, or an old Mac's lone CR
            const int d = std::fgetc(file_);
            if (d != '\n' && d != EOF) std::ungetc(d, file_);
            break;
        }
        if (line.text.size() == kMaxAirfoilLine)  // refused before it grows further
            fail(Failure::Argument, format("airfoil file \"%s\", line %zu: longer than %zu bytes: %s", path_,
                                           line.number, kMaxAirfoilLine, quoted(line.text).c_str()));
        line.text.push_back(static_cast<char>(c));
    }
    if (line.number == 1 && line.text.compare(0, 3, "\xEF\xBB\xBF") == 0) line.text.erase(0, 3);  // UTF-8 BOM
    if (binary(line.text))
        fail(Failure::Argument, format("airfoil file \"%s\", line %zu: not text (control bytes): %s", path_,
                                       line.number, quoted(line.text).c_str()));
    line.kind = LineKind::Text;
    if (parse_pair(line.text, line.x, line.y)) {
        line.kind = LineKind::Pair;
    } else {
        std::size_t k = 0;
        while (k < line.text.size() && is_blank(line.text[k])) ++k;
        if (k == line.text.size()) line.kind = LineKind::Blank;
    }
    return true;
}

}  // namespace eg2d
