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
    out.close_stream();  // the plugin writes the temporary by its name
    char message[512] = "";
    if (write(out.temp_path().c_str(), r.grid.ni(), r.grid.nj(), r.grid.x.data(), r.grid.y.data(),
              static_cast<int>(fields.size()), names.data(), values.data(), message, sizeof message) != 0)
        fail(Failure::Io, format("%s: %s", out.path().c_str(), message));
}

}  // namespace eg2d
