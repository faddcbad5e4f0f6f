// A registry's table: a fixed array of rows, each with a public `id` and a
// `name`, found by id. Every registry (solvers, parameters, formats, metrics,
// systems, initialisers, orthogonality methods, topologies, distributions)
// is one of these, and the API lists them all through it (api/lists_api.cpp).
#pragma once
#include <cstddef>

namespace eg2d {

template <class Row>
struct Table {
    const Row *rows;
    std::size_t size;

    const Row *begin() const { return rows; }
    const Row *end() const { return rows + size; }
    // nullptr: no row has that id.
    const Row *find(int id) const {
        for (const Row &r : *this)
            if (r.id == id) return &r;
        return nullptr;
    }
};

template <class Row, std::size_t N>
constexpr Table<Row> table_of(const Row (&rows)[N]) {
    return {rows, N};
}

}  // namespace eg2d

namespace eg2d {

// The row of a registry that is names alone: its list name ("winslow") and
// the title messages use ("Winslow").
struct NamedId {
    int id;
    const char *name;
    const char *title;
};

// The title of a named table's row for messages, or "unknown".
inline const char *title_of(Table<NamedId> table, int id) {
    const NamedId *row = table.find(id);
    return row ? row->title : "unknown";
}

}  // namespace eg2d
