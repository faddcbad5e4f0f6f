#include "base/connectivity.hpp"

namespace eg2d {

const char *topology_name(Topology t) {
    switch (t) {
    case Topology::Single: return "single-block";
    case Topology::O: return "O-grid";
    case Topology::C: return "C-grid";
    }
    return "unknown";
}

Connectivity::Connectivity(int ni, int nj, Topology topology, int wake)
    : ni_(ni), nj_(nj), topology_(topology), wake_(topology == Topology::C ? wake : 0) {
    for (int i = 1; i < wake_; ++i) extra_.push_back(Node{i, 0});
}

void Connectivity::sync(double *f) const {
    for (const Node &n : extra_) sync_node(f, n.i, n.j);
    if (!periodic_i()) return;
    for (int j = 0; j < nj_; ++j) sync_node(f, 0, j);
}

}  // namespace eg2d
