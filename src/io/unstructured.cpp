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

// The patches of one grid's sides, less the edges `joined` marks (empty: none).
std::vector<PatchGroup> patch_groups(const Grid &g) { return group_patches(resolve_patches(g)); }

// Appends grid g's cells (ids from m.cells()) and its patches' edges to m,
// its node k being point point_of[k]; the edges `joined` marks are left out.
void append_grid(UnstructuredMesh &m, const Grid &g, const std::vector<int> &point_of,
                 const std::array<std::vector<char>, 4> *joined) {
    // One orientation for the whole grid: a folded cell stays folded (the
    // reader's checks report it) rather than being turned over here.
    double area = 0;
    for (int j = 0; j + 1 < g.nj(); ++j)
        for (int i = 0; i + 1 < g.ni(); ++i) area += signed_area(g, i, j);
    const bool ccw = area >= 0;
    const int first_cell = static_cast<int>(m.cells());
    const std::size_t ni = static_cast<std::size_t>(g.ni());
    for (int j = 0; j + 1 < g.nj(); ++j)
        for (int i = 0; i + 1 < g.ni(); ++i) {
            const int p0 = point_of[i + ni * j], p1 = point_of[i + 1 + ni * j], p2 = point_of[i + 1 + ni * (j + 1)],
                      p3 = point_of[i + ni * (j + 1)];
            m.quads.push_back(ccw ? std::array<int, 4>{p0, p1, p2, p3} : std::array<int, 4>{p0, p3, p2, p1});
        }
    for (const PatchGroup &group : patch_groups(g)) {
        auto it = std::find_if(m.patches.begin(), m.patches.end(), [&](const MeshPatch &p) { return p.name == group.name; });
        if (it == m.patches.end()) {
            m.patches.push_back(MeshPatch{group.name, group.type, {}});
            it = m.patches.end() - 1;
        }
        for (const Patch &p : group.stretches)
            for (int q = p.first; q < p.last; ++q) {
                if (joined && !(*joined)[static_cast<int>(p.side)].empty() &&
                    (*joined)[static_cast<int>(p.side)][static_cast<std::size_t>(q)])
                    continue;
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
                int a = point_of[side_node(g, p.side, q)], b = point_of[side_node(g, p.side, q + 1)];
                if (forward != ccw) std::swap(a, b);
                it->edges.push_back({a, b, first_cell + i + (g.ni() - 1) * j});
            }
    }
    // A patch all of whose edges were joined is no patch.
    m.patches.erase(std::remove_if(m.patches.begin(), m.patches.end(), [](const MeshPatch &p) { return p.edges.empty(); }),
                    m.patches.end());
}
}  // namespace

UnstructuredMesh unstructured_mesh(const Grid &g) {
    UnstructuredMesh m;
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
    std::vector<int> point_of(g.size(), -1);
    for (std::size_t k = 0; k < g.size(); ++k) {
        if (same[k] != k) continue;
        point_of[k] = static_cast<int>(m.x.size());
        m.x.push_back(g.x[k]);
        m.y.push_back(g.y[k]);
    }
    for (std::size_t k = 0; k < g.size(); ++k) point_of[k] = point_of[same[k]];
    append_grid(m, g, point_of, nullptr);
    return m;
}

UnstructuredMesh unstructured_mesh(const std::vector<MeshBlock> &blocks, const std::vector<MeshTwin> &twins) {
    // Global node ids block after block; twins merged by union-find into the
    // lowest id, which is the point's first appearance.
    std::vector<std::size_t> offset(blocks.size() + 1, 0);
    for (std::size_t b = 0; b < blocks.size(); ++b) offset[b + 1] = offset[b] + blocks[b].grid->size();
    std::vector<std::size_t> root(offset.back());
    for (std::size_t k = 0; k < root.size(); ++k) root[k] = k;
    auto find = [&](std::size_t k) {
        while (root[k] != k) k = root[k] = root[root[k]];
        return k;
    };
    for (const MeshTwin &t : twins) {
        const std::size_t a = find(offset[static_cast<std::size_t>(t.block_a)] + t.node_a);
        const std::size_t b = find(offset[static_cast<std::size_t>(t.block_b)] + t.node_b);
        root[std::max(a, b)] = std::min(a, b);
    }
    UnstructuredMesh m;
    std::vector<int> point(root.size(), -1);
    for (std::size_t k = 0; k < root.size(); ++k) {
        const std::size_t r = find(k);
        if (r != k) continue;
        const std::size_t b = static_cast<std::size_t>(std::upper_bound(offset.begin(), offset.end(), k) - offset.begin()) - 1;
        point[k] = static_cast<int>(m.x.size());
        m.x.push_back(blocks[b].grid->x[k - offset[b]]);
        m.y.push_back(blocks[b].grid->y[k - offset[b]]);
    }
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        std::vector<int> point_of(blocks[b].grid->size());
        for (std::size_t k = 0; k < point_of.size(); ++k) point_of[k] = point[find(offset[b] + k)];
        append_grid(m, *blocks[b].grid, point_of, &blocks[b].joined);
    }
    return m;
}

std::vector<InternalEdge> internal_edges(const UnstructuredMesh &m) {
    struct Seen {
        int a, b, cell, count;
    };
    std::unordered_map<std::uint64_t, Seen> edges;
    edges.reserve(m.cells() * 3);
    for (std::size_t id = 0; id < m.cells(); ++id) {
        const std::array<int, 4> &c = m.quads[id];
        for (int e = 0; e < 4; ++e) {
            const int a = c[e], b = c[(e + 1) % 4];
            auto it = edges.find(key(a, b));
            if (it == edges.end()) edges.emplace(key(a, b), Seen{a, b, static_cast<int>(id), 1});
            else ++it->second.count;
        }
    }
    // Cells are visited in increasing order: an edge's first cell is its owner.
    std::vector<InternalEdge> out;
    for (std::size_t id = 0; id < m.cells(); ++id) {
        const std::array<int, 4> &c = m.quads[id];
        for (int e = 0; e < 4; ++e) {
            const Seen &s = edges.at(key(c[e], c[(e + 1) % 4]));
            if (s.count == 2 && s.cell != static_cast<int>(id)) out.push_back({s.a, s.b, s.cell, static_cast<int>(id)});
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
