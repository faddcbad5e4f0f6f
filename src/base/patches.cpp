#include "base/patches.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "base/error.hpp"
#include "base/grid.hpp"

namespace eg2d {

const char *patch_type_name(PatchType t) {
    switch (t) {
    case PatchType::Wall: return "wall";
    case PatchType::FarField: return "farfield";
    case PatchType::Outflow: return "outflow";
    case PatchType::Inflow: return "inflow";
    case PatchType::Symmetry: return "symmetry";
    case PatchType::Cut: return "cut";
    }
    return "?";
}

void check_patch_name(const char *name) {
    const std::size_t n = std::strlen(name);
    if (n == 0 || n > static_cast<std::size_t>(kMaxPatchName))
        fail(Failure::Argument, format("name \"%.40s\": must have 1 to %d characters, has %zu", name, kMaxPatchName, n));
    // Letters first: OpenFOAM reads a leading digit as a number, and SU2 and
    // CGNS names are identifiers in the tools that read them back.
    if (!std::isalpha(static_cast<unsigned char>(name[0])))
        fail(Failure::Argument, format("name \"%s\": must start with a letter", name));
    for (std::size_t k = 0; k < n; ++k) {
        const unsigned char c = static_cast<unsigned char>(name[k]);
        if (c > 127 || !(std::isalnum(c) || c == '_' || c == '-'))
            fail(Failure::Argument, format("name \"%s\": character %zu is not a letter, digit, '_' or '-'", name, k + 1));
    }
    if (!std::strcmp(name, "frontAndBack"))
        fail(Failure::Argument, "name \"frontAndBack\": reserved for the OpenFOAM case's front and back (empty) patch");
}

namespace {
// The C-grid's cut stretches of JMIN: nodes [0, w] and [ni-1-w, ni-1].
bool on_wake(const Grid &g, int edge) {
    const int w = g.cut_wake();
    return g.topology() == Topology::C && w > 0 && (edge < w || edge >= g.ni() - 1 - w);
}

const char *default_name(const Grid &g, Side s) {
    switch (g.topology()) {
    case Topology::Single: {
        static const char *const names[4] = {"jmin", "imax", "jmax", "imin"};
        return names[static_cast<int>(s)];
    }
    case Topology::O: return s == Side::JMin ? "wall" : "farfield";
    case Topology::C: return s == Side::JMin ? "wall" : s == Side::JMax ? "farfield" : "outflow";
    }
    return "";
}

PatchType default_type(const Grid &g, Side s) {
    if (g.topology() == Topology::Single || s == Side::JMin) return PatchType::Wall;
    if (s == Side::JMax) return PatchType::FarField;
    return PatchType::Outflow;
}

void check_against_cut(const Grid &g, const Patch &p) {
    if (static_cast<int>(p.side) != static_cast<int>(Side::JMin) || g.topology() != Topology::C || g.cut_wake() <= 0)
        return;
    const int w = g.cut_wake();
    if (p.first < w || p.last > g.ni() - 1 - w)
        fail(Failure::Argument,
             format("side JMIN nodes [%d, %d]: the C-grid's wake cut is nodes [0, %d] and [%d, %d], which are "
                    "internal (merged) and take no patch; the airfoil is [%d, %d]",
                    p.first, p.last, w, g.ni() - 1 - w, g.ni() - 1, w, g.ni() - 1 - w));
}
}  // namespace

std::vector<Patch> with_patch(const Grid &g, const std::vector<Patch> &patches, const Patch &p) {
    if (!g.has_side(p.side))
        fail(Failure::Argument, format("side %s: the %s topology has no such side (its i-cut is periodic)",
                                       side_name(p.side), topology_name(g.topology())));
    const int n = g.side_length(p.side);
    if (!(p.first >= 0 && p.first < p.last && p.last <= n - 1))
        fail(Failure::Argument, format("first = %d, last = %d: need 0 <= first < last <= %d (side %s has %d nodes)",
                                       p.first, p.last, n - 1, side_name(p.side), n));
    if (!(static_cast<int>(p.type) >= 0 && static_cast<int>(p.type) < static_cast<int>(PatchType::Cut)))
        fail(Failure::Argument, format("type = %d: not one of EG2D_PATCH_WALL (0), FARFIELD (1), OUTFLOW (2), "
                                       "INFLOW (3), SYMMETRY (4); a cut is the topology's",
                                       static_cast<int>(p.type)));
    check_patch_name(p.name.c_str());
    check_against_cut(g, p);
    std::vector<Patch> out;
    for (const Patch &q : patches) {
        if (q.side == p.side && q.first == p.first && q.last == p.last) continue;  // replaced
        if (q.side == p.side && p.first < q.last && q.first < p.last)
            fail(Failure::Argument, format("side %s nodes [%d, %d] overlap patch \"%s\" [%d, %d]; set the same range "
                                           "to replace it, or eg2d_clear_patches",
                                           side_name(p.side), p.first, p.last, q.name.c_str(), q.first, q.last));
        if (q.name == p.name && q.type != p.type)
            fail(Failure::Argument, format("name \"%s\": already used with type %s (a name is one marker of one type)",
                                           p.name.c_str(), patch_type_name(q.type)));
        out.push_back(q);
    }
    out.push_back(p);
    return out;
}

std::vector<Patch> resolve_patches(const Grid &g) {
    if (g.topology() == Topology::C && g.cut_wake() <= 0)
        fail(Failure::State, "the C-grid's wake cut is read from JMIN: set JMIN before asking for patches");
    for (const Patch &p : g.patches) check_against_cut(g, p);
    std::vector<Patch> out;
    for (int si = 0; si < 4; ++si) {
        const Side s = static_cast<Side>(si);
        if (!g.has_side(s)) {
            if (s == Side::IMin) out.push_back({s, 0, g.nj() - 1, PatchType::Cut, "cut"});
            continue;
        }
        const int edges = g.side_length(s) - 1;
        // owner[e]: index of the user patch holding edge e, -1 default, -2 cut.
        std::vector<int> owner(static_cast<std::size_t>(edges), -1);
        if (s == Side::JMin)
            for (int e = 0; e < edges; ++e)
                if (on_wake(g, e)) owner[e] = -2;
        for (std::size_t k = 0; k < g.patches.size(); ++k) {
            const Patch &p = g.patches[k];
            if (p.side != s) continue;
            for (int e = p.first; e < p.last; ++e) owner[e] = static_cast<int>(k);
        }
        for (int e = 0; e < edges;) {
            int f = e;
            while (f < edges && owner[f] == owner[e]) ++f;
            if (owner[e] >= 0) {
                const Patch &p = g.patches[static_cast<std::size_t>(owner[e])];
                out.push_back({s, e, f, p.type, p.name});
            } else if (owner[e] == -2) {
                out.push_back({s, e, f, PatchType::Cut, "wake"});
            } else {
                out.push_back({s, e, f, default_type(g, s), default_name(g, s)});
            }
            e = f;
        }
    }
    return out;
}

std::vector<PatchGroup> group_patches(const std::vector<Patch> &resolved) {
    std::vector<PatchGroup> groups;
    for (const Patch &p : resolved) {
        if (p.type == PatchType::Cut) continue;
        auto it = std::find_if(groups.begin(), groups.end(), [&](const PatchGroup &q) { return q.name == p.name; });
        if (it == groups.end()) {
            groups.push_back({p.name, p.type, {p}});
        } else {
            // A default name the user gave another type: a name is one marker of one type.
            if (it->type != p.type)
                fail(Failure::Argument, format("patch name \"%s\" has types %s and %s: a default stretch is named so; "
                                               "rename the patch",
                                               p.name.c_str(), patch_type_name(it->type), patch_type_name(p.type)));
            it->stretches.push_back(p);
        }
    }
    return groups;
}

}  // namespace eg2d
