#include "case_file.hpp"

#include <eg2d.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cerrno>
#include <cstring>
#include <fstream>

#include <sys/stat.h>

#include "failure.hpp"
#include "features.hpp"
#include "toml_fields.hpp"

namespace eg2dtool {

namespace {

const std::vector<std::string> top_keys = {"title", "size", "topology", "system", "initial", "solve",
                                           "constants", "solver", "sides", "controls", "output", "patches", "interior_lines",
                                           "blocks", "joins"};
// [controls]: the orthogonality, the growth limit, the command's control
// kinds (features.cpp) and the controls' parameters (read with them).
std::vector<std::string> controls_keys() {
    std::vector<std::string> keys = {"orthogonality", "wall_growth_limit"};
    for (const auto &k : names(controls())) keys.push_back(k);
    return keys;
}

// A name of `table`, or EXIT_CASE (unknown) / EXIT_UNSUPPORTED (not in this build).
const Feature &pick(const std::vector<Feature> &table, const std::string &name, const Location &at) {
    for (const auto &f : table)
        if (name == f.name) {
            if (!f.available)
                throw Failure(EXIT_UNSUPPORTED, at.str() + ": \"" + name + "\" is not available in this build of eg2d");
            return f;
        }
    throw Failure(EXIT_CASE, at.str() + ": \"" + name + "\" is not one of: " + join(names(table)));
}

const Feature &pick_key(const Fields &f, const std::string &key, const std::string &fallback,
                        const std::vector<Feature> &table) {
    return pick(table, f.text(key, fallback), f.at(key));
}

// On the doubles as read, before any cast: converting 1e300, inf or nan to an
// integer is undefined (found by tests/fuzz/fuzz_case).
void check_size(double ni, double nj, const Location &at) {
    if (!(ni >= 3 && nj >= 3 && ni <= 100000 && nj <= 100000))
        throw Failure(EXIT_CASE, at.str() + ": each of ni, nj must be in [3, 100000], found [" + fmt(ni) + ", " +
                                     fmt(nj) + "]");
}

// The keys of `section` that are EG2D_PARAM_* settings.
std::vector<std::string> parameter_keys(const char *section) {
    std::vector<std::string> keys;
    for (const auto &p : parameters())
        if (!std::strcmp(p.section, section)) keys.push_back(p.name);
    return keys;
}

// `except`: a key of the section read otherwise (by name).
void read_parameters(const Fields &f, const char *section, Case &c, const char *except = "") {
    for (const auto &p : parameters()) {
        if (std::strcmp(p.section, section) || !f.has(p.name) || !std::strcmp(p.name, except)) continue;
        if (!p.available)
            throw Failure(EXIT_UNSUPPORTED, f.at(p.name).str() + ": is not available in this build of eg2d");
        // on/off settings are written true/false (1/0 are accepted too)
        const double v = p.flag && f.node(p.name)->is_boolean() ? (f.boolean(p.name, true) ? 1 : 0) : f.number(p.name, c.constants);
        c.parameters.push_back({p.id, v, f.at(p.name)});
    }
}

void read_solver(const Fields &top, Case &c) {
    if (!top.has("solver")) return;
    std::vector<std::string> keys = {"method"};
    for (const auto &k : parameter_keys("solver")) keys.push_back(k);
    Fields f(top.table("solver"), top.at("solver"), keys);
    f.finish();
    const Feature &s = pick_key(f, "method", "multigrid", solvers());
    c.solver = s.id;
    c.solver_at = f.at("method");
    read_parameters(f, "solver", c);
}

// The sides of `parent`'s [sides] table (a case's, or a block's).
std::vector<SideSpec> read_side_table(const Fields &parent, int topology, const std::string &dir,
                                      const Constants &constants) {
    const auto &valid = side_names(topology);
    std::vector<std::string> keys;
    for (const auto &s : valid) keys.push_back(s.first);
    const Location where = parent.at("sides");
    Fields f(parent.table("sides"), where, keys);
    f.finish();
    std::vector<SideSpec> sides;
    for (const auto &s : valid) {
        if (!f.has(s.first))
            throw Failure(EXIT_CASE, f.at(s.first).str() + ": missing (a " +
                                         (topology == EG2D_TOPO_O ? "O-grid" : topology == EG2D_TOPO_C ? "C-grid" : "single-block") +
                                         " case needs the sides " + join(keys) + ")");
        sides.push_back(parse_side(*f.node(s.first), s.second, s.first, f.at(s.first), dir, constants));
    }
    return sides;
}

void read_sides(const Fields &top, Case &c) { c.sides = read_side_table(top, c.topology, c.dir, c.constants); }

// wall_spacing (of [controls], or of a block of a set): a first-cell height
// per wall side, a table {yplus, reynolds, chord} turned into one by
// eg2d_first_cell_height, or an array of heights, one per node of the side
// (eg2d_set_wall_spacing_nodes).
void read_wall_spacing(const Fields &f, int topology, const Constants &constants, std::vector<WallSpacing> &spacings) {
    if (!f.has("wall_spacing")) return;
    const auto &valid = side_names(topology);
    std::vector<std::string> side_keys;
    for (const auto &s : valid) side_keys.push_back(s.first);
    Fields w(f.table("wall_spacing"), f.at("wall_spacing"), side_keys);
    w.finish();
    for (const auto &s : valid) {
        if (!w.has(s.first)) continue;
        double h;
        if (const toml::array *a = w.node(s.first)->as_array()) {  // node by node
            std::vector<double> nodes;
            for (std::size_t k = 0; k < a->size(); ++k) {
                const toml::node &e = *a->get(k);
                const Location at = locate(w.where(), s.first + "[" + std::to_string(k) + "]", e);
                double v = 0;
                if (e.is_integer() || e.is_floating_point()) v = *e.value<double>();
                else if (e.is_string()) v = evaluate_constant(std::string(*e.value<std::string>()), constants, at);
                else throw Failure(EXIT_CASE, at.str() + ": expected a number, found " + type_name(e));
                if (!(std::isfinite(v) && v > 0)) throw Failure(EXIT_CASE, at.str() + ": must be a finite number > 0");
                nodes.push_back(v);
            }
            if (nodes.empty()) throw Failure(EXIT_CASE, w.at(s.first).str() + ": an empty array of heights");
            spacings.push_back({s.second, *std::min_element(nodes.begin(), nodes.end()), w.at(s.first), nodes});
            continue;
        }
        if (w.node(s.first)->is_table()) {  // from a target y+ (eg2d_first_cell_height)
            Fields y(w.table(s.first), w.at(s.first), {"yplus", "reynolds", "chord"});
            y.finish();
            const int status = eg2d_first_cell_height(y.number("yplus", constants), y.number("reynolds", constants),
                                                      y.number("chord", 1, constants), &h);
            if (status != EG2D_OK)
                throw Failure(EXIT_GEOMETRY, w.at(s.first).str() + ": " + eg2d_last_error(nullptr));
        } else {
            h = w.number(s.first, constants);
        }
        if (h < 0) throw Failure(EXIT_CASE, w.at(s.first).str() + ": must be >= 0 (0 = orthogonality only)");
        spacings.push_back({s.second, h, w.at(s.first), {}});
    }
}

void read_growth_limit(const Fields &f, Case &c) {
    if (f.has("wall_growth_limit")) {
        c.wall_growth_limit = f.number("wall_growth_limit", c.constants);
        if (!(c.wall_growth_limit >= 1))
            throw Failure(EXIT_CASE, f.at("wall_growth_limit").str() + ": must be >= 1");
    }
}

void read_wall_controls(const Fields &f, Case &c) {
    read_wall_spacing(f, c.topology, c.constants, c.wall_spacings);
    read_growth_limit(f, c);
}

// A set's [controls]: the growth its walls' layers may have (the walls'
// heights are each block's wall_spacing; a set has no other controls).
void read_set_controls(const Fields &top, Case &c) {
    if (!top.has("controls")) return;
    Fields f(top.table("controls"), top.at("controls"), {"wall_growth_limit"});
    f.finish();
    read_growth_limit(f, c);
}

// Calls fn(table, location) for key's table, or for each table of key's array.
template <class Fn>
void each_table(const Fields &f, const char *key, Fn &&fn) {
    if (!f.has(key)) return;
    const toml::node &n = *f.node(key);
    if (n.is_table()) return fn(*n.as_table(), f.at(key));
    const toml::array &a = f.array(key);
    for (std::size_t k = 0; k < a.size(); ++k) {
        Location l = locate(f.where(), std::string(key) + "[" + std::to_string(k) + "]", *a.get(k));
        if (!a.get(k)->is_table()) throw Failure(EXIT_CASE, l.str() + ": expected a table, found " + type_name(*a.get(k)));
        fn(*a.get(k)->as_table(), l);
    }
}

// [controls] line_source, point_source (tables or arrays of tables), and
// source_arrays {P, Q} (formulas in i, j).
void read_sources(const Fields &f, Case &c) {
    each_table(f, "line_source", [&](const toml::table &t, const Location &l) {
        Fields s(t, l, {"direction", "line", "amplitude", "decay"});
        s.finish();
        const std::string d = s.choice("direction", "", {"xi", "eta"});
        c.line_sources.push_back({d == "xi" ? EG2D_XI : EG2D_ETA, s.number("line", c.constants),
                                  s.number("amplitude", c.constants), s.number("decay", c.constants), l});
    });
    each_table(f, "point_source", [&](const toml::table &t, const Location &l) {
        Fields s(t, l, {"xi", "eta", "amplitude", "decay"});
        s.finish();
        c.point_sources.push_back({s.number("xi", c.constants), s.number("eta", c.constants),
                                   s.number("amplitude", c.constants), s.number("decay", c.constants), l});
    });
    if (f.has("source_arrays")) {
        Fields s(f.table("source_arrays"), f.at("source_arrays"), {"P", "Q"});
        s.finish();
        c.source_p = s.text("P", "0");
        c.source_q = s.text("Q", "0");
        c.source_p_at = s.at("P");
        c.source_q_at = s.at("Q");
        // compile now, so that a bad formula is reported before any work
        Formula(c.source_p, {"i", "j"}, c.constants, c.source_p_at);
        Formula(c.source_q, {"i", "j"}, c.constants, c.source_q_at);
    }
}

// [controls] weight: a formula in i, j.
void read_weight(const Fields &f, Case &c) {
    if (!f.has("weight")) return;
    c.weight = f.text("weight");
    c.weight_at = f.at("weight");
    Formula(c.weight, {"i", "j"}, c.constants, c.weight_at);
}

// [controls] parameter_grid {i, j}: Khattri's (2006) tensor grid of
// clustering maps, one per direction (uniform where absent).
void read_parameter_grid(const Fields &f, Case &c) {
    if (!f.has("parameter_grid")) return;
    Fields g(f.table("parameter_grid"), f.at("parameter_grid"), {"i", "j"});
    g.finish();
    for (const char *dir : {"i", "j"}) {
        Clustering &k = dir[0] == 'i' ? c.cluster_i : c.cluster_j;
        k.where = g.at(dir);
        if (!g.has(dir)) continue;  // uniform in that direction
        Fields m(g.table(dir), k.where, {"kind", "a", "b", "strength"});
        m.finish();
        const std::string kind = m.choice("kind", "", {"uniform", "line", "two_lines", "boundaries"});
        k.kind = kind == "uniform" ? -1 : kind == "line" ? EG2D_CLUSTER_LINE
                                        : kind == "two_lines" ? EG2D_CLUSTER_TWO_LINES : EG2D_CLUSTER_BOUNDARIES;
        k.a = m.number("a", 0.5, c.constants);
        k.b = m.number("b", 0, c.constants);
        k.strength = m.number("strength", 0, c.constants);
    }
    c.parameter_grid = true;
}

void read_controls(const Fields &top, Case &c) {
    if (!top.has("controls")) return;
    std::vector<std::string> keys = controls_keys();
    for (const auto &k : parameter_keys("controls")) keys.push_back(k);
    Fields f(top.table("controls"), top.at("controls"), keys);
    f.finish();
    read_parameters(f, "controls", c);
    if (f.has("orthogonality")) {
        c.orthogonality = pick_key(f, "orthogonality", "none", orthogonality()).id;
        c.orthogonality_at = f.at("orthogonality");
    }
    read_wall_controls(f, c);
    read_sources(f, c);
    read_weight(f, c);
    read_parameter_grid(f, c);
}

// [[patches]]: side (a name of [sides]), first and last node (default: the
// whole side), type and name, as eg2d_set_patch takes them; of a case or a block.
void read_patch_array(const Fields &parent, int topology, int ni, int nj, const Constants &constants,
                      std::vector<PatchSetting> &patches) {
    if (!parent.has("patches")) return;
    const toml::array &a = parent.array("patches");
    const auto &valid = side_names(topology);
    std::vector<std::string> sides;
    for (const auto &s : valid) sides.push_back(s.first);
    for (std::size_t k = 0; k < a.size(); ++k) {
        const Location l = locate(parent.where(), "patches[" + std::to_string(k) + "]", *a.get(k));
        if (!a.get(k)->is_table()) throw Failure(EXIT_CASE, l.str() + ": expected a table, found " + type_name(*a.get(k)));
        Fields f(*a.get(k)->as_table(), l, {"side", "first", "last", "type", "name"});
        f.finish();
        const std::string side = f.choice("side", "", sides);
        int id = 0;
        for (const auto &s : valid)
            if (s.first == side) id = s.second;
        const int n = (id == EG2D_SIDE_JMIN || id == EG2D_SIDE_JMAX) ? ni : nj;
        const std::string type = f.choice("type", "", {"wall", "farfield", "outflow", "inflow", "symmetry"});
        const int t = type == "wall" ? EG2D_PATCH_WALL : type == "farfield" ? EG2D_PATCH_FARFIELD
                    : type == "outflow" ? EG2D_PATCH_OUTFLOW : type == "inflow" ? EG2D_PATCH_INFLOW
                    : EG2D_PATCH_SYMMETRY;
        const double first = f.number("first", 0, constants), last = f.number("last", n - 1, constants);
        if (!(first >= 0 && first < last && last <= n - 1) || first != static_cast<long>(first) ||
            last != static_cast<long>(last))
            throw Failure(EXIT_CASE, f.at(f.has("first") ? "first" : "last").str() + ": first = " + fmt(first) +
                                         ", last = " + fmt(last) + ": need whole numbers 0 <= first < last <= " +
                                         std::to_string(n - 1) + " (side " + side + " has " + std::to_string(n) +
                                         " nodes)");
        patches.push_back({id, static_cast<int>(first), static_cast<int>(last), t, f.text("name"), l});
    }
}

void read_patches(const Fields &top, Case &c) { read_patch_array(top, c.topology, c.ni, c.nj, c.constants, c.patches); }

// [[blocks]]: name, size, sides (as a single-block case's [sides]),
// [[blocks.patches]] and wall_spacing (as [controls] wall_spacing, for this
// block's sides); each block's formulas see its own ni, nj.
void read_blocks(const Fields &top, Case &c) {
    c.blocks_at = top.at("blocks");
    const toml::array &a = top.array("blocks");
    if (a.empty()) throw Failure(EXIT_CASE, c.blocks_at.str() + ": a set needs at least one block");
    for (std::size_t k = 0; k < a.size(); ++k) {
        const Location l = locate(top.where(), "blocks[" + std::to_string(k) + "]", *a.get(k));
        if (!a.get(k)->is_table()) throw Failure(EXIT_CASE, l.str() + ": expected a table, found " + type_name(*a.get(k)));
        Fields f(*a.get(k)->as_table(), l, {"name", "size", "sides", "patches", "wall_spacing"});
        f.finish();
        BlockSpec b;
        b.where = l;
        // Its form is the library's to check (eg2d_blocks_set_name); the joins
        // refer to blocks by name, so two blocks of one name are refused here.
        b.name = f.text("name");
        b.name_at = f.at("name");
        for (const auto &other : c.blocks)
            if (other.name == b.name)
                throw Failure(EXIT_CASE, f.at("name").str() + ": \"" + b.name + "\" names two blocks (the other at line " +
                                             std::to_string(other.where.line) + ")");
        b.size_at = f.at("size");
        double dni = 0, dnj = 0;
        read_pair(f.array("size"), b.size_at, c.constants, dni, dnj);
        check_size(dni, dnj, b.size_at);
        if (dni != static_cast<long>(dni) || dnj != static_cast<long>(dnj))
            throw Failure(EXIT_CASE, b.size_at.str() + ": expected whole numbers [ni, nj]");
        b.ni = static_cast<int>(dni);
        b.nj = static_cast<int>(dnj);
        b.constants = c.constants;
        b.constants["ni"] = b.ni;
        b.constants["nj"] = b.nj;
        b.sides = read_side_table(f, EG2D_TOPO_SINGLE, c.dir, b.constants);
        for (const SideSpec &sd : b.sides)
            for (const SidePiece &p : sd.pieces)
                if (p.sliding) throw Failure(EXIT_CASE, p.where.str() + ": a block's side does not slide (sets of blocks)");
        read_patch_array(f, EG2D_TOPO_SINGLE, b.ni, b.nj, b.constants, b.patches);
        read_wall_spacing(f, EG2D_TOPO_SINGLE, b.constants, b.wall_spacings);
        c.blocks.push_back(std::move(b));
    }
}

// One end of a join: {block, side, first, last}; first and last default to
// the side's ends.
// One end of a join from its fields (block, side, first, last).
// compact: from "BLOCK.SIDE", whose messages name `where`.
JoinEnd read_join_end_fields(const Fields &f, const Location &where, const Case &c, bool compact) {
    JoinEnd e;
    e.where = where;
    const Location block_at = compact ? where : f.at("block"), side_at = compact ? where : f.at("side");
    const std::string block = f.text("block");
    std::vector<std::string> known;
    e.block = -1;
    for (std::size_t k = 0; k < c.blocks.size(); ++k) {
        known.push_back(c.blocks[k].name);
        if (c.blocks[k].name == block) e.block = static_cast<int>(k);
    }
    if (e.block < 0)
        throw Failure(EXIT_CASE, block_at.str() + ": no block is named \"" + block + "\" (the blocks: " + join(known) + ")");
    const BlockSpec &b = c.blocks[static_cast<std::size_t>(e.block)];
    const auto &valid = side_names(EG2D_TOPO_SINGLE);
    std::vector<std::string> sides;
    for (const auto &s : valid) sides.push_back(s.first);
    const std::string side = f.text("side");
    if (std::find(sides.begin(), sides.end(), side) == sides.end())
        throw Failure(EXIT_CASE, side_at.str() + ": \"" + side + "\" is not one of: " + join(sides));
    for (const auto &s : valid)
        if (s.first == side) e.side = s.second;
    const int n = (e.side == EG2D_SIDE_JMIN || e.side == EG2D_SIDE_JMAX) ? b.ni : b.nj;
    const double first = f.number("first", 0, b.constants), last = f.number("last", n - 1, b.constants);
    for (const char *k : {"first", "last"}) {
        const double v = k[0] == 'f' ? first : last;
        if (!(v >= 0 && v <= n - 1) || v != static_cast<long>(v))
            throw Failure(EXIT_CASE, f.at(k).str() + ": " + k + " = " + fmt(v) + ": need a whole number in [0, " +
                                         std::to_string(n - 1) + "] (side " + side + " of block " + b.name + " has " +
                                         std::to_string(n) + " nodes)");
    }
    if (first == last)
        throw Failure(EXIT_CASE, f.at("last").str() + ": first = last = " + fmt(first) + ": a join spans at least two nodes");
    e.first = static_cast<int>(first);
    e.last = static_cast<int>(last);
    return e;
}

// The compact form "BLOCK.SIDE" is the whole side.
JoinEnd read_join_end(const Fields &parent, const char *key, const Case &c) {
    if (parent.has(key) && parent.node(key)->is_string()) {
        const std::string text = parent.text(key);
        const auto dot = text.rfind('.');
        if (dot == std::string::npos)
            throw Failure(EXIT_CASE, parent.at(key).str() + ": \"" + text +
                                         "\": expected \"BLOCK.SIDE\" (a whole side) or {block, side, first, last}");
        toml::table t;
        t.insert("block", text.substr(0, dot));
        t.insert("side", text.substr(dot + 1));
        Fields f(t, parent.at(key), {"block", "side"});
        return read_join_end_fields(f, parent.at(key), c, true);
    }
    Fields f(parent.table(key), parent.at(key), {"block", "side", "first", "last"});
    f.finish();
    return read_join_end_fields(f, parent.at(key), c, false);
}

// [[joins]]: a = {block, side, first, last}, b = {...}: node first of a is
// node first of b, and so on (eg2d_blocks_join); held = true keeps its
// nodes where the sides put them (eg2d_blocks_hold_join).
void read_joins(const Fields &top, Case &c) {
    if (!top.has("joins")) return;
    const toml::array &a = top.array("joins");
    for (std::size_t k = 0; k < a.size(); ++k) {
        const Location l = locate(top.where(), "joins[" + std::to_string(k) + "]", *a.get(k));
        if (!a.get(k)->is_table()) throw Failure(EXIT_CASE, l.str() + ": expected a table, found " + type_name(*a.get(k)));
        Fields f(*a.get(k)->as_table(), l, {"a", "b", "held"});
        f.finish();
        JoinSpec j;
        j.where = l;
        j.held = f.boolean("held", false);
        j.a = read_join_end(f, "a", c);
        j.b = read_join_end(f, "b", c);
        const int na = std::abs(j.a.last - j.a.first) + 1, nb = std::abs(j.b.last - j.b.first) + 1;
        if (na != nb)
            throw Failure(EXIT_CASE, j.b.where.str() + ": spans " + std::to_string(nb) + " nodes (" +
                                         std::to_string(j.b.first) + " to " + std::to_string(j.b.last) + ") but a spans " +
                                         std::to_string(na) + " (" + std::to_string(j.a.first) + " to " +
                                         std::to_string(j.a.last) + "): a join is node to node");
        c.joins.push_back(j);
    }
}

// [[interior_lines]]: direction ("xi", a column i = index; "eta", a row
// j = index), index, and curve: the line's curve, written as a side is
// (formulas in s, points, a chain of pieces, a distribution).
void read_interior_lines(const Fields &top, Case &c) {
    if (!top.has("interior_lines")) return;
    const toml::array &a = top.array("interior_lines");
    for (std::size_t k = 0; k < a.size(); ++k) {
        const Location l = locate(top.where(), "interior_lines[" + std::to_string(k) + "]", *a.get(k));
        if (!a.get(k)->is_table()) throw Failure(EXIT_CASE, l.str() + ": expected a table, found " + type_name(*a.get(k)));
        Fields f(*a.get(k)->as_table(), l, {"direction", "index", "curve"});
        f.finish();
        const bool xi = f.choice("direction", "", {"xi", "eta"}) == "xi";
        const long index = f.integer("index", c.constants);
        const long limit = (xi ? c.ni : c.nj) - 2;
        if (index < 1 || index > limit)
            throw Failure(EXIT_CASE, f.at("index").str() + ": index = " + std::to_string(index) + ": an interior " +
                                         (xi ? "column" : "row") + " in [1, " + std::to_string(limit) + "]");
        if (!f.has("curve")) throw Failure(EXIT_CASE, f.at("curve").str() + ": missing (the line's curve)");
        SideSpec curve = parse_side(*f.node("curve"), -1, "curve", f.at("curve"), c.dir, c.constants);
        for (const SidePiece &p : curve.pieces)
            if (p.sliding) throw Failure(EXIT_CASE, p.where.str() + ": an interior line does not slide");
        c.interior_lines.push_back({xi ? EG2D_XI : EG2D_ETA, static_cast<int>(index), std::move(curve), l});
    }
}

void read_output(const Fields &top, Case &c, const std::string &stem) {
    std::string name = stem;
    std::vector<std::pair<std::string, Location>> wanted;
    if (top.has("output")) {
        std::vector<std::string> keys = {"name", "formats"};
        for (const auto &k : parameter_keys("output")) keys.push_back(k);  // span, svg_quality
        Fields f(top.table("output"), top.at("output"), keys);
        f.finish();
        read_parameters(f, "output", c, "svg_quality");
        if (f.has("svg_quality")) {  // colour the picture's cells by a per-cell metric
            c.svg_quality = pick_key(f, "svg_quality", "", cell_metrics()).id;
            c.svg_quality_at = f.at("svg_quality");
        }
        name = f.text("name", stem);
        if (name.empty() || name.find('/') != std::string::npos)
            throw Failure(EXIT_CASE, f.at("name").str() + ": a file name without '/' is required");
        if (f.has("formats")) {
            const toml::array &a = f.array("formats");
            for (std::size_t k = 0; k < a.size(); ++k) {
                Location l = locate(f.where(), "formats[" + std::to_string(k) + "]", *a.get(k));
                if (!a.get(k)->is_string()) throw Failure(EXIT_CASE, l.str() + ": expected a string, found " + type_name(*a.get(k)));
                wanted.emplace_back(std::string(*a.get(k)->value<std::string>()), l);
            }
        }
    }
    if (wanted.empty()) wanted.emplace_back("svg", top.where());
    for (const auto &w : wanted) {
        const Feature &fmt = pick(formats(), w.first, w.second);
        c.outputs.push_back({fmt.id, name + fmt.extension, w.second, fmt.directory, fmt.tool});
    }
}

std::string stem_of(const std::string &file) {
    std::string base = file.substr(file.find_last_of("/:") + 1);
    const auto dot = base.rfind('.');
    return dot == std::string::npos || dot == 0 ? base : base.substr(0, dot);
}

}  // namespace

Case read_case(const std::string &text, const std::string &file, const std::string &dir, int ni, int nj) {
    toml::table root;
    try {
        root = toml::parse(text, file);
    } catch (const toml::parse_error &e) {
        const auto &b = e.source().begin;
        throw Failure(EXIT_CASE, file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                                     ": TOML syntax error: " + std::string(e.description()));
    }
    Case c;
    c.file = file;
    c.dir = dir;
    const Location where{file, "", 1, 1};
    std::vector<std::string> top_level = top_keys;
    for (const auto &k : parameter_keys("top")) top_level.push_back(k);
    Fields top(root, where, top_level);
    top.finish();
    c.title = top.text("title", stem_of(file));

    // A set of blocks: each block has its size; the one-grid keys are not at the top.
    const bool set = top.has("blocks");
    if (set) {
        for (const char *k : {"size", "topology", "sides", "patches", "interior_lines"})
            if (top.has(k))
                throw Failure(EXIT_CASE, top.at(k).str() + ": not in a case of [[blocks]] (each block has its own size, "
                                         "sides and patches; a set of blocks is single-block grids without controls or "
                                         "interior lines)");
        if (ni > 0 || nj > 0)
            throw Failure(EXIT_USAGE, file + ": --size does not apply to a case of [[blocks]] (each block has its size)");
    } else if (top.has("joins")) {
        throw Failure(EXIT_CASE, top.at("joins").str() + ": joins belong to a case of [[blocks]]");
    } else {
        // size first: ni and nj are constants of every formula
        const toml::array &size = top.array("size");
        c.size_at = top.at("size");
        double dni = 0, dnj = 0;
        read_pair(size, c.size_at, {}, dni, dnj);
        check_size(dni, dnj, c.size_at);
        if (dni != static_cast<long>(dni) || dnj != static_cast<long>(dnj))
            throw Failure(EXIT_CASE, c.size_at.str() + ": expected whole numbers [ni, nj]");
        c.ni = ni > 0 ? ni : static_cast<int>(dni);
        c.nj = nj > 0 ? nj : static_cast<int>(dnj);
        c.constants["ni"] = c.ni;
        c.constants["nj"] = c.nj;
    }
    if (top.has("constants")) {
        const Location at = top.at("constants");
        const toml::table &t = top.table("constants");
        // in the file's order: a constant may use the ones above it (and ni, nj, pi, e)
        std::vector<std::pair<std::size_t, std::string>> order;
        for (const auto &kv : t) order.emplace_back(kv.first.source().begin.line, std::string(kv.first.str()));
        std::sort(order.begin(), order.end());
        std::vector<std::string> keys;
        for (const auto &o : order) keys.push_back(o.second);
        Fields f(t, at, keys);
        for (const auto &k : keys) {
            if (c.constants.count(k) || k == "pi" || k == "e" || k == "s" || k == "i" || k == "j" ||
                k == "ni" || k == "nj")
                throw Failure(EXIT_CASE, f.at(k).str() + ": is a reserved or repeated name (pi, e, s, i, j, ni, nj)");
            c.constants[k] = f.number(k, c.constants);
        }
    }
    c.topology = pick_key(top, "topology", "single", topologies()).id;
    c.system = pick_key(top, "system", "winslow", systems()).id;
    c.initial = pick_key(top, "initial", "tfi", initializers()).id;
    c.topology_at = top.at("topology");
    c.system_at = top.at("system");
    c.initial_at = top.at("initial");
    c.solve = top.boolean("solve", true);
    read_parameters(top, "top", c);
    read_solver(top, c);
    if (set) {
        if (c.initial != EG2D_INIT_TFI)
            throw Failure(EXIT_CASE, c.initial_at.str() + ": a set of blocks starts from each block's TFI grid");
        if (!c.solve) throw Failure(EXIT_CASE, top.at("solve").str() + ": a set of blocks is solved (solve = true)");
        read_set_controls(top, c);
        read_blocks(top, c);
        read_joins(top, c);
        read_output(top, c, stem_of(file));
        for (const auto &out : c.outputs)
            if (out.tool && out.tool != kGridPng)
                throw Failure(EXIT_CASE, out.where.str() + ": is not written for a set of blocks (su2 and openfoam "
                                         "are one mesh, svg and png one picture, the others one file per block)");
        return c;
    }
    read_sides(top, c);
    read_controls(top, c);
    read_patches(top, c);
    read_interior_lines(top, c);
    read_output(top, c, stem_of(file));
    return c;
}

// The largest case file read (examples/ are 1 to 3 KB).
constexpr std::size_t kMaxCaseBytes = std::size_t{1} << 20;

Case read_case_file(const std::string &path, int ni, int nj) {
    struct stat st;
    if (stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw Failure(EXIT_IO, path + ": " + (S_ISDIR(st.st_mode) ? "a directory" : "not a regular file") +
                                   ", not a case file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Failure(EXIT_IO, path + ": cannot read the case file: " + std::strerror(errno));
    // Case files are written by hand: a bound keeps a wrong path (a grid, a
    // log) from costing the TOML parser many times its size in memory.
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMaxCaseBytes)
            throw Failure(EXIT_CASE, path + ": more than " + std::to_string(kMaxCaseBytes >> 20) +
                                         " MiB, too large for a case file (large point sets go in point files: "
                                         "file = \"...\")");
    }
    const auto slash = path.find_last_of('/');
    return read_case(text, path, slash == std::string::npos ? "." : path.substr(0, slash), ni, nj);
}

}  // namespace eg2dtool
