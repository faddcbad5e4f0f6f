#include "toml_fields.hpp"

#include <algorithm>
#include <cmath>

#include "failure.hpp"

namespace eg2dtool {

std::string join(const std::vector<std::string> &items, const char *sep) {
    std::string s;
    for (std::size_t k = 0; k < items.size(); ++k) s += (k ? sep : "") + items[k];
    return s;
}

std::string type_name(const toml::node &node) {
    switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
    }
}

Location locate(const Location &parent, const std::string &key, const toml::node &node) {
    const auto &src = node.source();
    return parent.child(key, static_cast<int>(src.begin.line), static_cast<int>(src.begin.column));
}

Fields::Fields(const toml::table &table, const Location &where, std::vector<std::string> known)
    : table_(table), where_(where), known_(std::move(known)) {}

bool Fields::has(const std::string &key) const { return table_.contains(key); }

const toml::node *Fields::node(const std::string &key) const { return table_.get(key); }

Location Fields::at(const std::string &key) const {
    const toml::node *n = node(key);
    if (n) return locate(where_, key, *n);
    return where_.child(key, where_.line, where_.column);
}

void Fields::type_error(const std::string &key, const char *expected) const {
    throw Failure(EXIT_CASE, at(key).str() + ": expected " + expected + ", found " + type_name(*node(key)));
}

std::string Fields::text(const std::string &key) const {
    if (!has(key)) throw Failure(EXIT_CASE, at(key).str() + ": missing (a string is required)");
    return text(key, "");
}

std::string Fields::text(const std::string &key, const std::string &fallback) const {
    const toml::node *n = node(key);
    if (!n) return fallback;
    if (!n->is_string()) type_error(key, "a string");
    return std::string(*n->value<std::string>());
}

double Fields::number(const std::string &key, const Constants &constants) const {
    if (!has(key)) throw Failure(EXIT_CASE, at(key).str() + ": missing (a number is required)");
    return number(key, 0, constants);
}

double Fields::number(const std::string &key, double fallback, const Constants &constants) const {
    const toml::node *n = node(key);
    if (!n) return fallback;
    double v;
    if (n->is_integer() || n->is_floating_point()) v = *n->value<double>();
    else if (n->is_string()) v = evaluate_constant(std::string(*n->value<std::string>()), constants, at(key));
    else type_error(key, "a number");
    if (!std::isfinite(v)) throw Failure(EXIT_CASE, at(key).str() + ": expected a finite number");
    return v;
}

long Fields::integer(const std::string &key, const Constants &constants) const {
    const double v = number(key, constants);
    if (v != std::floor(v) || std::fabs(v) > 1e9)
        throw Failure(EXIT_CASE, at(key).str() + ": expected a whole number, found " + std::to_string(v));
    return static_cast<long>(v);
}

bool Fields::boolean(const std::string &key, bool fallback) const {
    const toml::node *n = node(key);
    if (!n) return fallback;
    if (!n->is_boolean()) type_error(key, "a boolean (true or false)");
    return *n->value<bool>();
}

const toml::table &Fields::table(const std::string &key) const {
    const toml::node *n = node(key);
    if (!n) throw Failure(EXIT_CASE, at(key).str() + ": missing (a table is required)");
    if (!n->is_table()) type_error(key, "a table");
    return *n->as_table();
}

const toml::array &Fields::array(const std::string &key) const {
    const toml::node *n = node(key);
    if (!n) throw Failure(EXIT_CASE, at(key).str() + ": missing (an array is required)");
    if (!n->is_array()) type_error(key, "an array");
    return *n->as_array();
}

std::string Fields::choice(const std::string &key, const std::string &fallback,
                           const std::vector<std::string> &choices) const {
    const std::string v = text(key, fallback);
    if (std::find(choices.begin(), choices.end(), v) == choices.end())
        throw Failure(EXIT_CASE, at(key).str() + ": \"" + v + "\" is not one of: " + join(choices));
    return v;
}

void Fields::finish() const {
    for (const auto &kv : table_) {
        const std::string k(kv.first.str());
        if (std::find(known_.begin(), known_.end(), k) != known_.end()) continue;
        const auto &src = kv.first.source();
        const Location l = where_.child(k, static_cast<int>(src.begin.line), static_cast<int>(src.begin.column));
        throw Failure(EXIT_CASE, l.str() + ": unknown key (expected one of: " + join(known_) + ")");
    }
}

void read_pair(const toml::node &node, const Location &where, const Constants &constants, double &x, double &y) {
    const toml::array *a = node.as_array();
    if (!a || a->size() != 2)
        throw Failure(EXIT_CASE, where.str() + ": expected a pair [x, y], found " +
                                     (a ? "an array of " + std::to_string(a->size()) : type_name(node)));
    double v[2];
    for (int k = 0; k < 2; ++k) {
        const toml::node &e = *a->get(static_cast<std::size_t>(k));
        if (e.is_integer() || e.is_floating_point()) v[k] = *e.value<double>();
        else if (e.is_string()) v[k] = evaluate_constant(std::string(*e.value<std::string>()), constants, where);
        else throw Failure(EXIT_CASE, where.str() + ": expected a number, found " + type_name(e));
        if (!std::isfinite(v[k])) throw Failure(EXIT_CASE, where.str() + ": expected a finite number");
    }
    x = v[0];
    y = v[1];
}

}  // namespace eg2dtool
