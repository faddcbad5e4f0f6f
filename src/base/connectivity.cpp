#include "base/connectivity.hpp"

#include "eg2d.h"

namespace eg2d {

namespace {
const NamedId kTopologies[] = {
    {EG2D_TOPO_SINGLE, "single", "single-block"},
    {EG2D_TOPO_O, "o", "O-grid"},
    {EG2D_TOPO_C, "c", "C-grid"},
};
}  // namespace

Table<NamedId> topology_table() { return table_of(kTopologies); }

const char *topology_name(Topology t) { return title_of(topology_table(), static_cast<int>(t)); }

Connectivity::Connectivity(int ni, int nj, Topology topology, int wake)
    : ni_(ni), nj_(nj), topology_(topology), wake_(topology == Topology::C ? wake : 0) {
    for (int i = 1; i < wake_; ++i) extra_.push_back(Node{i, 0});
}

Connectivity Connectivity::with_fixed(const std::vector<int> &columns, const std::vector<int> &rows) const {
    Connectivity c(*this);
    c.fixed_i_.clear();
    c.fixed_j_.clear();
    c.fixed_mask_.clear();
    if (columns.empty() && rows.empty()) return c;
    c.fixed_i_.assign(static_cast<std::size_t>(ni_), 0);
    c.fixed_j_.assign(static_cast<std::size_t>(nj_), 0);
    for (int i : columns) c.fixed_i_[static_cast<std::size_t>(i)] = 1;
    for (int j : rows) c.fixed_j_[static_cast<std::size_t>(j)] = 1;
    c.fixed_mask_.assign(static_cast<std::size_t>(ni_) * static_cast<std::size_t>(nj_), 0);
    for (int j = 0; j < nj_; ++j)
        for (int i = 0; i < ni_; ++i)
            c.fixed_mask_[static_cast<std::size_t>(i) + static_cast<std::size_t>(ni_) * static_cast<std::size_t>(j)] =
                static_cast<char>(c.fixed_i_[static_cast<std::size_t>(i)] | c.fixed_j_[static_cast<std::size_t>(j)]);
    return c;
}

Connectivity Connectivity::with_fixed_nodes(const std::vector<char> &mask) const {
    Connectivity c(*this);
    if (c.fixed_mask_.empty()) c.fixed_mask_.assign(mask.size(), 0);
    for (std::size_t k = 0; k < mask.size(); ++k)
        if (mask[k]) c.fixed_mask_[k] = 1;
    return c;
}

std::vector<int> Connectivity::marked(const std::vector<char> &m) {
    std::vector<int> out;
    for (std::size_t k = 0; k < m.size(); ++k)
        if (m[k]) out.push_back(static_cast<int>(k));
    return out;
}

void Connectivity::sync(double *f) const {
    for (const Node &n : extra_) sync_node(f, n.i, n.j);
    if (!periodic_i()) return;
    for (int j = 0; j < nj_; ++j) sync_node(f, 0, j);
}

}  // namespace eg2d
