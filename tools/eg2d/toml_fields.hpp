// Typed, located access to one TOML table of a case file: every value read names its
// key and line in errors, and keys nobody asked for are reported as unknown.
#pragma once

#include <toml++/toml.h>

#include <set>
#include <string>
#include <vector>

#include "formula.hpp"
#include "location.hpp"

namespace eg2dtool {

// The location of a node (its key path given by the caller).
Location locate(const Location &parent, const std::string &key, const toml::node &node);

class Fields {
public:
    // `known` lists every key this table may hold (checked by finish()).
    Fields(const toml::table &table, const Location &where, std::vector<std::string> known);

    bool has(const std::string &key) const;
    const toml::node *node(const std::string &key) const;  // nullptr if absent
    Location at(const std::string &key) const;             // the value's location, or the table's
    const Location &where() const { return where_; }

    // Required (throws "missing key") or defaulted values. A number may also be written
    // as a formula string of constants ("2*pi"); integers must be whole.
    std::string text(const std::string &key) const;
    std::string text(const std::string &key, const std::string &fallback) const;
    double number(const std::string &key, const Constants &constants) const;
    double number(const std::string &key, double fallback, const Constants &constants) const;
    long integer(const std::string &key, const Constants &constants) const;
    bool boolean(const std::string &key, bool fallback) const;
    const toml::table &table(const std::string &key) const;
    const toml::array &array(const std::string &key) const;

    // One of `choices` (the message lists them).
    std::string choice(const std::string &key, const std::string &fallback, const std::vector<std::string> &choices) const;

    // Throws on the first key not in `known` (in file order).
    void finish() const;

private:
    [[noreturn]] void type_error(const std::string &key, const char *expected) const;
    const toml::table &table_;
    Location where_;
    std::vector<std::string> known_;
};

// "a string", "an integer", ...: for messages.
std::string type_name(const toml::node &node);

// A [x, y] pair of numbers (points, corners).
void read_pair(const toml::node &node, const Location &where, const Constants &constants, double &x, double &y);

// "[solver] keys: a, b, c" style list.
std::string join(const std::vector<std::string> &items, const char *sep = ", ");

}  // namespace eg2dtool
