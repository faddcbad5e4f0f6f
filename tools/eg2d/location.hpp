// Where a value of a case file came from, so that every error names the key and the line.
#pragma once

#include <string>

namespace eg2dtool {

struct Location {
    std::string file;  // the case file's path as given (or "demo:NAME")
    std::string key;   // dotted key path, e.g. "sides.top.y" or "sides.left[1].x"
    int line = 0;      // 1-based; 0 when unknown
    int column = 0;

    // "FILE:LINE:COLUMN: key 'KEY'" (the prefix of every case-file message;
    // "FILE" alone when there is no key, e.g. "channel: --lower" of a command line).
    std::string str() const {
        std::string s = file;
        if (line > 0) s += ":" + std::to_string(line) + ":" + std::to_string(column);
        if (!key.empty()) s += ": key '" + key + "'";
        return s;
    }
    Location child(const std::string &name, int l, int c) const { return Location{file, key.empty() ? name : key + "." + name, l, c}; }
};

}  // namespace eg2dtool
