#include "io/unstructured.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "base/error.hpp"

namespace eg2d {

namespace {
// Shoelace area of cell (i, j) in the order (i,j), (i+1,j), (i+1,j+1), (i,j+1).
double signed_area(const Grid &g, int i, int j) {
    const std::size_t ni = static_cast<std::size_t>(g.ni());
    const std::size_t k[4] = {i + ni * j, i + 1 + ni * j, i + 1 + ni * (j + 1), i + ni * (j + 1)};
    double a = 0;
    for (int c = 0; c < 4; ++c) {
        const std::size_t p = k[c], q = k[(c + 1) % 4];
        a += g.x[p] * g.y[q] - g.x[q] * g.y[p];
    }
    return 0.5 * a;
}

std::uint64_t key(int a, int b) {
    const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
    return lo << 32 | hi;
}
}  // namespace

std::array<int, 4> UnstructuredMesh::cell(int i, int j) const {
    const std::size_t n = static_cast<std::size_t>(ni);
    const int p0 = point_of[i + n * j], p1 = point_of[i + 1 + n * j], p2 = point_of[i + 1 + n * (j + 1)],
              p3 = point_of[i + n * (j + 1)];
    if (counter_clockwise) return {p0, p1, p2, p3};
    return {p0, p3, p2, p1};
}

UnstructuredMesh unstructured_mesh(const Grid &g) {
    const std::vector<Patch> resolved = resolve_patches(g);
    UnstructuredMesh m;
    m.ni = g.ni();
    m.nj = g.nj();
    const std::size_t ni = static_cast<std::size_t>(g.ni());
    // Which node each node is merged into (itself unless it lies on the cut).
    std::vector<std::size_t> same(g.size());
    for (std::size_t k = 0; k < same.size(); ++k) same[k] = k;
    if (g.topology() == Topology::O) {
        for (int j = 0; j < g.nj(); ++j) same[ni - 1 + ni * j] = ni * j;
    } else if (g.topology() == Topology::C) {
        const int w = g.cut_wake();
        for (int i = 0; i <= w; ++i) same[ni - 1 - i] = static_cast<std::size_t>(i);
    }
    m.point_of.assign(g.size(), -1);
    for (std::size_t k = 0; k < g.size(); ++k) {
        if (same[k] != k) continue;
        m.point_of[k] = static_cast<int>(m.node_of.size());
        m.node_of.push_back(k);
    }
    for (std::size_t k = 0; k < g.size(); ++k) m.point_of[k] = m.point_of[same[k]];
    // One orientation for the whole grid: a folded cell stays folded (the
    // reader's checks report it) rather than being turned over here.
    double area = 0;
    for (int j = 0; j + 1 < g.nj(); ++j)
        for (int i = 0; i + 1 < g.ni(); ++i) area += signed_area(g, i, j);
    m.counter_clockwise = area >= 0;
    for (const PatchGroup &group : group_patches(resolved)) {
        MeshPatch mp{group.name, group.type, {}};
        for (const Patch &p : group.stretches)
            for (int q = p.first; q < p.last; ++q) {
                int i = 0, j = 0;
                // Along the side, (i, j) of the cell and whether the side's
                // increasing index runs counter-clockwise round it.
                bool forward = true;
                switch (p.side) {
                case Side::JMin: i = q; j = 0; forward = true; break;
                case Side::IMax: i = g.ni() - 2; j = q; forward = true; break;
                case Side::JMax: i = q; j = g.nj() - 2; forward = false; break;
                case Side::IMin: i = 0; j = q; forward = false; break;
                }
                const std::size_t k0 = side_node(g, p.side, q), k1 = side_node(g, p.side, q + 1);
                int a = m.point_of[k0], b = m.point_of[k1];
                if (forward != m.counter_clockwise) std::swap(a, b);
                mp.edges.push_back({a, b, i + (g.ni() - 1) * j});
            }
        m.patches.push_back(std::move(mp));
    }
    return m;
}

std::vector<InternalEdge> internal_edges(const UnstructuredMesh &m) {
    struct Seen {
        int a, b, cell, count;
    };
    std::unordered_map<std::uint64_t, Seen> edges;
    edges.reserve(m.cells() * 2 + static_cast<std::size_t>(m.ni + m.nj) * 2);
    for (int j = 0; j + 1 < m.nj; ++j)
        for (int i = 0; i + 1 < m.ni; ++i) {
            const std::array<int, 4> c = m.cell(i, j);
            const int id = i + (m.ni - 1) * j;
            for (int e = 0; e < 4; ++e) {
                const int a = c[e], b = c[(e + 1) % 4];
                auto it = edges.find(key(a, b));
                if (it == edges.end()) edges.emplace(key(a, b), Seen{a, b, id, 1});
                else ++it->second.count;
            }
        }
    // Cells are visited in increasing order: an edge's first cell is its owner.
    std::vector<InternalEdge> out;
    std::vector<std::pair<std::uint64_t, int>> neighbours;  // second visits
    for (int j = 0; j + 1 < m.nj; ++j)
        for (int i = 0; i + 1 < m.ni; ++i) {
            const std::array<int, 4> c = m.cell(i, j);
            const int id = i + (m.ni - 1) * j;
            for (int e = 0; e < 4; ++e) {
                const Seen &s = edges.at(key(c[e], c[(e + 1) % 4]));
                if (s.count == 2 && s.cell != id) out.push_back({s.a, s.b, s.cell, id});
                else if (s.count > 2)
                    fail(Failure::Argument, format("the edge of points %d and %d belongs to %d cells", s.a, s.b, s.count));
            }
        }
    std::sort(out.begin(), out.end(), [](const InternalEdge &p, const InternalEdge &q) {
        return p.owner != q.owner ? p.owner < q.owner : p.neighbour < q.neighbour;
    });
    // The boundary: every edge of one cell must be in exactly one patch.
    std::size_t boundary = 0;
    for (const auto &kv : edges) boundary += kv.second.count == 1;
    std::size_t in_patches = 0;
    for (const MeshPatch &p : m.patches)
        for (const MeshEdge &e : p.edges) {
            auto it = edges.find(key(e.a, e.b));
            if (it == edges.end() || it->second.count != 1)
                fail(Failure::Argument,
                     format("patch \"%s\": the edge of points %d and %d is not a boundary edge", p.name.c_str(), e.a, e.b));
            ++in_patches;
        }
    if (in_patches != boundary)
        fail(Failure::Argument, format("the patches hold %zu edges, the boundary has %zu", in_patches, boundary));
    return out;
}

}  // namespace eg2d
