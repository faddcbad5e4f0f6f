#include "grid/connectivity.hpp"

namespace eg2d {

const char *topology_name(Topology t) {
    switch (t) {
    case Topology::Single: return "single-block";
    case Topology::O: return "O-grid";
    case Topology::C: return "C-grid";
    }
    return "unknown";
}

void Connectivity::sync(double *f) const {
    if (!periodic_i()) return;
    for (int j = 0; j < nj_; ++j) sync_node(f, 0, j);
}

}  // namespace eg2d
