// EG2D_FORMAT_CGNS: finds and loads the optional plugin (cgns_plugin.h) and
// lets it fill the temporary file. Where it looks: only $EG2D_PLUGIN_DIR
// when that is set; else the directory libeg2d itself was loaded from, then
// the dynamic linker's search path. A successful load is kept for the life
// of the process; a failed one is retried on the next call.
#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "base/patches.hpp"
#include "io/cgns_plugin.h"
#include "io/formats.hpp"
#include "quality/quality.hpp"

namespace eg2d {

namespace {
std::string own_directory() {
    Dl_info info;
    if (dladdr(reinterpret_cast<void *>(&own_directory), &info) == 0 || !info.dli_fname) return "";
    const std::string file = info.dli_fname;
    const std::size_t slash = file.rfind('/');
    return slash == std::string::npos ? "" : file.substr(0, slash);
}

struct Plugin {
    eg2d_cgns_write_fn write = nullptr;
    eg2d_cgns_write_zones_fn write_zones = nullptr;
};

Plugin try_load(const std::string &file, std::string &why) {
    void *h = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *e = dlerror();
        why += format("\n  %s: %s", file.c_str(), e ? e : "cannot load");
        return {};
    }
    auto abi = reinterpret_cast<eg2d_cgns_abi_fn>(dlsym(h, "eg2d_cgns_plugin_abi"));
    Plugin p{reinterpret_cast<eg2d_cgns_write_fn>(dlsym(h, "eg2d_cgns_plugin_write")),
             reinterpret_cast<eg2d_cgns_write_zones_fn>(dlsym(h, "eg2d_cgns_plugin_write_zones"))};
    if (!abi || !p.write || !p.write_zones || abi() != EG2D_CGNS_PLUGIN_ABI) {
        why += format("\n  %s: not an eg2d CGNS plugin of ABI %d", file.c_str(), EG2D_CGNS_PLUGIN_ABI);
        dlclose(h);
        return {};
    }
    return p;
}

Plugin load_plugin() {
    static std::mutex lock;
    static Plugin loaded;
    std::lock_guard<std::mutex> hold(lock);
    if (loaded.write) return loaded;
    std::string why;
    if (const char *dir = std::getenv("EG2D_PLUGIN_DIR")) {
        loaded = try_load(std::string(dir) + "/" + EG2D_CGNS_PLUGIN_NAME, why);
    } else {
        const std::string own = own_directory();
        if (!own.empty()) loaded = try_load(own + "/" + EG2D_CGNS_PLUGIN_NAME, why);
        if (!loaded.write) loaded = try_load(EG2D_CGNS_PLUGIN_NAME, why);
    }
    if (!loaded.write)
        fail(Failure::Unsupported,
             format("EG2D_FORMAT_CGNS needs the optional plugin %s (built when libcgns is found, installed next to "
                    "libeg2d), and it could not be loaded:%s",
                    EG2D_CGNS_PLUGIN_NAME, why.c_str()));
    return loaded;
}
// The patches as BC_t ranges and the cut as 1-to-1 connections (CGNS SIDS,
// 1-based node ranges); the strings live in `names`.
struct CgnsBoundary {
    std::vector<std::string> names;
    std::vector<eg2d_cgns_patch> patches;
    std::vector<eg2d_cgns_connection> connections;
};

// A 1-based node range {i1, j1, i2, j2} of nodes first..last of side s.
void side_range(const Grid &g, Side s, int first, int last, int *range) {
    const NodeIJ a = side_ij(g.ni(), g.nj(), s, first), e = side_ij(g.ni(), g.nj(), s, last);
    range[0] = a.i + 1;
    range[1] = a.j + 1;
    range[2] = e.i + 1;
    range[3] = e.j + 1;
}

// The patches' stretches less the edges `joined` marks (per side, edge q:
// nodes q..q+1; empty: none), split where a join cuts one.
std::vector<Patch> unjoined(const std::vector<Patch> &resolved, const std::array<std::vector<char>, 4> *joined) {
    if (!joined) return resolved;
    std::vector<Patch> out;
    for (const Patch &p : resolved) {
        const std::vector<char> &e = (*joined)[static_cast<std::size_t>(p.side)];
        int q = p.first;
        while (q < p.last) {
            while (q < p.last && !e.empty() && e[static_cast<std::size_t>(q)]) ++q;
            const int start = q;
            while (q < p.last && (e.empty() || !e[static_cast<std::size_t>(q)])) ++q;
            if (q > start) out.push_back(Patch{p.side, start, q, p.type, p.name});
        }
    }
    return out;
}

CgnsBoundary cgns_boundary(const Grid &g, const std::array<std::vector<char>, 4> *joined = nullptr) {
    const std::vector<Patch> resolved = unjoined(resolve_patches(g), joined);
    const std::vector<PatchGroup> groups = group_patches(resolved);
    CgnsBoundary b;
    b.names.reserve(2 * resolved.size() + 4);  // c_str()s stay valid: no reallocation
    const int ni = g.ni(), nj = g.nj();
    for (const PatchGroup &group : groups)
        for (std::size_t k = 0; k < group.stretches.size(); ++k) {
            const Patch &p = group.stretches[k];
            // BC_t names are unique in a zone: a name's second stretch is name_2.
            b.names.push_back(k == 0 ? group.name : format("%s_%zu", group.name.c_str(), k + 1));
            const char *name = b.names.back().c_str();
            b.names.push_back(group.name);
            eg2d_cgns_patch c{name, b.names.back().c_str(), static_cast<int>(p.type), {0, 0, 0, 0}};
            const int a = p.first + 1, e = p.last + 1;
            switch (p.side) {
            case Side::JMin: c.range[0] = a; c.range[1] = 1; c.range[2] = e; c.range[3] = 1; break;
            case Side::IMax: c.range[0] = ni; c.range[1] = a; c.range[2] = ni; c.range[3] = e; break;
            case Side::JMax: c.range[0] = a; c.range[1] = nj; c.range[2] = e; c.range[3] = nj; break;
            case Side::IMin: c.range[0] = 1; c.range[1] = a; c.range[2] = 1; c.range[3] = e; break;
            }
            b.patches.push_back(c);
        }
    // Each cut from both of its sides, as the SIDS list a 1-to-1 interface.
    if (g.topology() == Topology::O) {
        b.connections.push_back({"cut_imin", "eg2d", {1, 1, 1, nj}, {ni, 1, ni, nj}, {1, 2}});
        b.connections.push_back({"cut_imax", "eg2d", {ni, 1, ni, nj}, {1, 1, 1, nj}, {1, 2}});
    } else if (g.topology() == Topology::C) {
        // Lower wake i = 0..w runs outflow to trailing edge; the upper wake
        // i = ni-1-w..ni-1 back out: i maps to ni-1-i, and across the cut
        // +j on one side is -j on the other.
        const int w = g.cut_wake();
        b.connections.push_back({"wake_lower", "eg2d", {1, 1, w + 1, 1}, {ni, 1, ni - w, 1}, {-1, -2}});
        b.connections.push_back({"wake_upper", "eg2d", {ni - w, 1, ni, 1}, {w + 1, 1, 1, 1}, {-1, -2}});
    }
    return b;
}

// SIDS's short transform of a join seen from block a: a's normal index
// (outward from its side) is b's normal index inward; a's index along the
// side is b's along its side, the same way when both ranges run alike.
void join_transform(const ZoneJoin &j, int *t) {
    auto normal = [](Side s) { return (s == Side::IMin || s == Side::IMax) ? 1 : 2; };
    auto outward = [](Side s) { return (s == Side::IMax || s == Side::JMax) ? 1 : -1; };
    const int step_a = j.first_a <= j.last_a ? 1 : -1, step_b = j.first_b <= j.last_b ? 1 : -1;
    t[normal(j.side_a) - 1] = -outward(j.side_a) * outward(j.side_b) * normal(j.side_b);
    t[2 - normal(j.side_a)] = step_a * step_b * (3 - normal(j.side_b));
}
}  // namespace

// A set of blocks: a zone a block (named as the blocks), its patches less the
// joined edges, each join a 1-to-1 connection listed from both zones.
void write_cgns_blocks(const BlocksRequest &r, OutputFile &out) {
    const Plugin plugin = load_plugin();
    const std::size_t n = r.grids.size();
    std::vector<std::array<std::vector<char>, 4>> joined(n);
    for (std::size_t b = 0; b < n; ++b)
        for (int s = 0; s < 4; ++s)
            joined[b][static_cast<std::size_t>(s)].assign(static_cast<std::size_t>(r.grids[b]->side_length(Side(s))), 0);
    for (const ZoneJoin &j : r.joins)
        for (int k = 0; k < 2; ++k) {
            const int first = k == 0 ? j.first_a : j.first_b, last = k == 0 ? j.last_a : j.last_b;
            std::vector<char> &e = joined[static_cast<std::size_t>(k == 0 ? j.a : j.b)][static_cast<std::size_t>(k == 0 ? j.side_a : j.side_b)];
            for (int q = std::min(first, last); q < std::max(first, last); ++q) e[static_cast<std::size_t>(q)] = 1;
        }
    std::vector<std::string> zone_names;
    for (std::size_t b = 0; b < n; ++b) zone_names.push_back(r.name(b));
    std::vector<CgnsBoundary> boundaries;
    std::vector<std::vector<CellField>> fields(n);
    std::vector<std::vector<const char *>> names(n);
    std::vector<std::vector<const double *>> values(n);
    for (std::size_t b = 0; b < n; ++b) {
        boundaries.push_back(cgns_boundary(*r.grids[b], &joined[b]));
        fields[b] = cell_fields(*r.grids[b]);
    }
    // Zones and the patches' families are children of one base: one set of names.
    for (std::size_t b = 0; b < n; ++b)
        for (std::size_t o = 0; o < n; ++o)
            for (const eg2d_cgns_patch &p : boundaries[o].patches)
                if (zone_names[b] == p.family)
                    fail(Failure::Argument,
                         format("%s: block %zu's name \"%s\" is also a patch's (block %zu): a CGNS base holds its "
                                "zones and the patches' families under one set of names; rename the block "
                                "(eg2d_blocks_set_name)",
                                out.path().c_str(), b, zone_names[b].c_str(), o));
    for (std::size_t b = 0; b < n; ++b) {
        for (const CellField &f : fields[b]) {
            names[b].push_back(f.name.c_str());
            values[b].push_back(f.values.data());
        }
    }
    // A join's name in both zones; a block joined to itself holds both
    // records in one zone, whose children need names of their own.
    std::vector<std::string> join_names, back_names;
    join_names.reserve(r.joins.size());
    back_names.reserve(r.joins.size());
    for (std::size_t k = 0; k < r.joins.size(); ++k) {
        const bool self = r.joins[k].a == r.joins[k].b;
        join_names.push_back(format(self ? "join%zu_a" : "join%zu", k + 1));
        back_names.push_back(format(self ? "join%zu_b" : "join%zu", k + 1));
    }
    for (std::size_t k = 0; k < r.joins.size(); ++k) {
        const ZoneJoin &j = r.joins[k];
        const Grid &ga = *r.grids[static_cast<std::size_t>(j.a)], &gb = *r.grids[static_cast<std::size_t>(j.b)];
        eg2d_cgns_connection ca{join_names[k].c_str(), zone_names[static_cast<std::size_t>(j.b)].c_str(), {}, {}, {}};
        side_range(ga, j.side_a, j.first_a, j.last_a, ca.range);
        side_range(gb, j.side_b, j.first_b, j.last_b, ca.donor);
        join_transform(j, ca.transform);
        const ZoneJoin back{j.b, j.side_b, j.first_b, j.last_b, j.a, j.side_a, j.first_a, j.last_a};
        eg2d_cgns_connection cb{back_names[k].c_str(), zone_names[static_cast<std::size_t>(j.a)].c_str(), {}, {}, {}};
        side_range(gb, j.side_b, j.first_b, j.last_b, cb.range);
        side_range(ga, j.side_a, j.first_a, j.last_a, cb.donor);
        join_transform(back, cb.transform);
        boundaries[static_cast<std::size_t>(j.a)].connections.push_back(ca);
        boundaries[static_cast<std::size_t>(j.b)].connections.push_back(cb);
    }
    std::vector<eg2d_cgns_zone> zones;
    for (std::size_t b = 0; b < n; ++b) {
        const Grid &g = *r.grids[b];
        const CgnsBoundary &bd = boundaries[b];
        zones.push_back(eg2d_cgns_zone{zone_names[b].c_str(), g.ni(), g.nj(), g.x.data(), g.y.data(),
                                       static_cast<int>(names[b].size()), names[b].data(), values[b].data(),
                                       static_cast<int>(bd.patches.size()), bd.patches.data(),
                                       static_cast<int>(bd.connections.size()), bd.connections.data()});
    }
    out.close_stream();  // the plugin writes the temporary by its name
    char message[512] = "";
    if (plugin.write_zones(out.temp_path().c_str(), static_cast<int>(zones.size()), zones.data(), message,
                           sizeof message) != 0)
        fail(Failure::Io, format("%s: %s", out.path().c_str(), message));
}

void write_cgns(const WriteRequest &r, OutputFile &out) {
    const eg2d_cgns_write_fn write = load_plugin().write;
    const std::vector<CellField> fields = cell_fields(r.grid);
    std::vector<const char *> names;
    std::vector<const double *> values;
    for (const CellField &f : fields) {
        names.push_back(f.name.c_str());
        values.push_back(f.values.data());
    }
    const CgnsBoundary b = cgns_boundary(r.grid);
    out.close_stream();  // the plugin writes the temporary by its name
    char message[512] = "";
    if (write(out.temp_path().c_str(), r.grid.ni(), r.grid.nj(), r.grid.x.data(), r.grid.y.data(),
              static_cast<int>(fields.size()), names.data(), values.data(), static_cast<int>(b.patches.size()),
              b.patches.data(), static_cast<int>(b.connections.size()), b.connections.data(), message,
              sizeof message) != 0)
        fail(Failure::Io, format("%s: %s", out.path().c_str(), message));
}

}  // namespace eg2d
