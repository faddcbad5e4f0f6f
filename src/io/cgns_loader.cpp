// EG2D_FORMAT_CGNS: finds and loads the optional plugin (cgns_plugin.h) and
// lets it fill the temporary file. Where it looks: only $EG2D_PLUGIN_DIR
// when that is set; else the directory libeg2d itself was loaded from, then
// the dynamic linker's search path. A successful load is kept for the life
// of the process; a failed one is retried on the next call.
#include <dlfcn.h>

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

eg2d_cgns_write_fn try_load(const std::string &file, std::string &why) {
    void *h = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *e = dlerror();
        why += format("\n  %s: %s", file.c_str(), e ? e : "cannot load");
        return nullptr;
    }
    auto abi = reinterpret_cast<eg2d_cgns_abi_fn>(dlsym(h, "eg2d_cgns_plugin_abi"));
    auto write = reinterpret_cast<eg2d_cgns_write_fn>(dlsym(h, "eg2d_cgns_plugin_write"));
    if (!abi || !write || abi() != EG2D_CGNS_PLUGIN_ABI) {
        why += format("\n  %s: not an eg2d CGNS plugin of ABI %d", file.c_str(), EG2D_CGNS_PLUGIN_ABI);
        dlclose(h);
        return nullptr;
    }
    return write;
}

eg2d_cgns_write_fn load_plugin() {
    static std::mutex lock;
    static eg2d_cgns_write_fn loaded = nullptr;
    std::lock_guard<std::mutex> hold(lock);
    if (loaded) return loaded;
    std::string why;
    if (const char *dir = std::getenv("EG2D_PLUGIN_DIR")) {
        loaded = try_load(std::string(dir) + "/" + EG2D_CGNS_PLUGIN_NAME, why);
    } else {
        const std::string own = own_directory();
        if (!own.empty()) loaded = try_load(own + "/" + EG2D_CGNS_PLUGIN_NAME, why);
        if (!loaded) loaded = try_load(EG2D_CGNS_PLUGIN_NAME, why);
    }
    if (!loaded)
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

CgnsBoundary cgns_boundary(const Grid &g) {
    const std::vector<Patch> resolved = resolve_patches(g);
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
        b.connections.push_back({"cut_imin", {1, 1, 1, nj}, {ni, 1, ni, nj}, {1, 2}});
        b.connections.push_back({"cut_imax", {ni, 1, ni, nj}, {1, 1, 1, nj}, {1, 2}});
    } else if (g.topology() == Topology::C) {
        // Lower wake i = 0..w runs outflow to trailing edge; the upper wake
        // i = ni-1-w..ni-1 back out: i maps to ni-1-i, and across the cut
        // +j on one side is -j on the other.
        const int w = g.cut_wake();
        b.connections.push_back({"wake_lower", {1, 1, w + 1, 1}, {ni, 1, ni - w, 1}, {-1, -2}});
        b.connections.push_back({"wake_upper", {ni - w, 1, ni, 1}, {w + 1, 1, 1, 1}, {-1, -2}});
    }
    return b;
}
}  // namespace

void write_cgns(const WriteRequest &r, OutputFile &out) {
    const eg2d_cgns_write_fn write = load_plugin();
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
