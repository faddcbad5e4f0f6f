// The lines of an airfoil coordinate file, one at a time and bounded: a line
// longer than kMaxLine bytes is refused without being read whole (a 600 MB
// line once took 2 GB), and a line quoted in a message is escaped and cut.
#pragma once
#include <cstddef>
#include <cstdio>
#include <string>

namespace eg2d {

constexpr std::size_t kMaxAirfoilLine = 4096;

// What a line holds: nothing, exactly two numbers (a point), or anything else.
enum class LineKind { Blank, Pair, Text };

struct AirfoilLine {
    std::string text;      // without the line end (LF, CRLF or CR) and a UTF-8 BOM
    std::size_t number = 0;  // 1-based
    LineKind kind = LineKind::Blank;
    double x = 0.0, y = 0.0;  // a Pair's numbers
};

// Reads `path`'s lines in order. Throws Argument naming the line for one
// longer than kMaxAirfoilLine bytes or one holding control bytes (binary).
class AirfoilLines {
public:
    AirfoilLines(std::FILE *file, const char *path) : file_(file), path_(path) {}
    // The next line into `line`; false at the end of the file.
    bool next(AirfoilLine &line);

private:
    std::FILE *file_;
    const char *path_;
    std::size_t number_ = 0;
};

// `text` for a message: in double quotes, bytes outside printable ASCII as
// \xNN, cut to about 60 characters with "..." when longer.
std::string quoted(const std::string &text);

// "x y" with blanks, tabs or one comma between: true for exactly two numbers.
bool parse_pair(const std::string &text, double &x, double &y);

}  // namespace eg2d
