#include "runner.hpp"
#include "wall_summary.hpp"

#include <eg2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "failure.hpp"
#include "features.hpp"
#include "grid_lines.hpp"
#include "grid_views.hpp"
#include "view_lines.hpp"
#include "piece_curve.hpp"
#include "output_set.hpp"
#include "progress.hpp"
#include "run_files.hpp"
#include "view_picture.hpp"

namespace eg2dtool {

int exit_code_for_status(int status) {
    switch (status) {
    case EG2D_OK: return EXIT_OK;
    case EG2D_ERR_ARGUMENT:
    case EG2D_ERR_BOUNDARY:
    case EG2D_ERR_STATE: return EXIT_GEOMETRY;
    case EG2D_ERR_NOT_CONVERGED: return EXIT_NOT_CONVERGED;
    case EG2D_ERR_DIVERGED: return EXIT_DIVERGED;
    case EG2D_ERR_FOLDED: return EXIT_FOLDED;
    case EG2D_ERR_IO: return EXIT_IO;
    case EG2D_ERR_UNSUPPORTED: return EXIT_UNSUPPORTED;
    case EG2D_ERR_INTERRUPTED: return EXIT_INTERRUPTED;
    case EG2D_ERR_MEMORY: return EXIT_MEMORY;
    default: return EXIT_INTERNAL;
    }
}

namespace {

struct GridDeleter {
    void operator()(eg2d_grid *g) const { eg2d_destroy(g); }
};
using GridPtr = std::unique_ptr<eg2d_grid, GridDeleter>;

// A failed library call: the location in the case file and the library's message.
void check(eg2d_grid *g, int status, const Location &at) {
    // Out of memory is the grid's size, not the key that happened to allocate.
    if (status == EG2D_ERR_MEMORY)
        throw Failure(EXIT_MEMORY, std::string("out of memory: the grid is too large for this machine (") +
                                       eg2d_last_error(g) + ")");
    if (status != EG2D_OK) throw Failure(exit_code_for_status(status), at.str() + ": " + eg2d_last_error(g));
}

const char *name_of(const std::vector<Feature> &table, int id) {
    for (const auto &f : table)
        if (f.id == id) return f.name;
    return "?";
}

// Everything that can be checked before the solve is (output_set.hpp):
// the formats' writers, the output directory and what is at each path.
void preflight(const Case &c, const RunOptions &o) {
    std::vector<PlannedPath> paths;
    for (const auto &out : c.outputs) paths.push_back({out.name, out.tool ? -1 : out.format, out.directory, out.where.str()});
    check_before_solving(o.out_dir, paths);
}

// The walls' first cells: a height >= 0 turns EG2D_ORTHO_WALL on (eg2d.h), so
// a single block's wall_spacing and a block's of a set need nothing more.
void apply_wall_spacings(eg2d_grid *g, const std::vector<WallSpacing> &spacings) {
    for (const auto &w : spacings)
        check(g, w.nodes.empty() ? eg2d_set_wall_spacing(g, w.side, w.height)
                                 : eg2d_set_wall_spacing_nodes(g, w.side, static_cast<int>(w.nodes.size()), w.nodes.data()),
              w.where);
}

void apply_controls(eg2d_grid *g, const Case &c) {
    if (c.orthogonality >= 0) check(g, eg2d_set_orthogonality(g, c.orthogonality), c.orthogonality_at);
    apply_wall_spacings(g, c.wall_spacings);
    for (const auto &s : c.line_sources)
        check(g, eg2d_add_line_source(g, s.direction, s.line, s.amplitude, s.decay), s.where);
    for (const auto &s : c.point_sources)
        check(g, eg2d_add_point_source(g, s.xi, s.eta, s.amplitude, s.decay), s.where);
    if (!c.source_p.empty()) {
        const Formula fp(c.source_p, {"i", "j"}, c.constants, c.source_p_at);
        const Formula fq(c.source_q, {"i", "j"}, c.constants, c.source_q_at);
        std::vector<double> p(static_cast<std::size_t>(c.ni) * c.nj), q(p.size());
        for (int j = 0; j < c.nj; ++j)
            for (int i = 0; i < c.ni; ++i) {
                const std::size_t k = static_cast<std::size_t>(i) + static_cast<std::size_t>(c.ni) * j;
                p[k] = fp({double(i), double(j)});
                q[k] = fq({double(i), double(j)});
            }
        check(g, eg2d_set_source_arrays(g, p.data(), q.data()), c.source_p_at);
    }
    if (!c.weight.empty()) {
        const Formula fw(c.weight, {"i", "j"}, c.constants, c.weight_at);
        std::vector<double> w(static_cast<std::size_t>(c.ni) * c.nj);
        for (int j = 0; j < c.nj; ++j)
            for (int i = 0; i < c.ni; ++i) w[static_cast<std::size_t>(i) + static_cast<std::size_t>(c.ni) * j] = fw({double(i), double(j)});
        check(g, eg2d_set_weight(g, w.data()), c.weight_at);
    }
    if (c.parameter_grid) {  // Khattri (2006): the tensor grid of two clustering maps
        auto map = [&](const Clustering &k, int n) {
            std::vector<double> u(static_cast<std::size_t>(n));
            if (k.kind < 0) {
                for (int q = 0; q < n; ++q) u[static_cast<std::size_t>(q)] = static_cast<double>(q) / (n - 1);
            } else {
                check(nullptr, eg2d_clustering_map(k.kind, k.a, k.b, k.strength, n, u.data()), k.where);
            }
            return u;
        };
        const std::vector<double> u = map(c.cluster_i, c.ni), v = map(c.cluster_j, c.nj);
        std::vector<double> s(static_cast<std::size_t>(c.ni) * c.nj), t(s.size());
        check(nullptr, eg2d_tensor_parameter_grid(c.ni, c.nj, u.data(), v.data(), s.data(), t.data()), c.cluster_i.where);
        check(g, eg2d_set_parameter_grid(g, s.data(), t.data()), c.cluster_i.where);
    }
}

// The quality summary: the library's metrics (EG2D_QUALITY_*), orthogonality at each side.
void print_quality(eg2d_grid *g, int topology) {
    auto q = [g](int metric) {
        double v = 0;
        eg2d_get_quality(g, metric, &v);
        return v;
    };
    std::printf("quality: %.0f folded cells, cell area %.4g to %.4g, skewness max %.2f deg, aspect ratio max %.3g,\n"
                "         smoothness max %.3g (i) %.3g (j)\n",
                q(EG2D_QUALITY_FOLDED_CELLS), q(EG2D_QUALITY_MIN_AREA), q(EG2D_QUALITY_MAX_AREA),
                q(EG2D_QUALITY_SKEWNESS), q(EG2D_QUALITY_ASPECT_RATIO), q(EG2D_QUALITY_SMOOTHNESS_I),
                q(EG2D_QUALITY_SMOOTHNESS_J));
    // orthogonality at the sides the topology has, named as in the case file
    static const int max_metric[] = {EG2D_QUALITY_ORTHO_MAX_JMIN, EG2D_QUALITY_ORTHO_MAX_IMAX,
                                     EG2D_QUALITY_ORTHO_MAX_JMAX, EG2D_QUALITY_ORTHO_MAX_IMIN};
    static const int mean_metric[] = {EG2D_QUALITY_ORTHO_MEAN_JMIN, EG2D_QUALITY_ORTHO_MEAN_IMAX,
                                      EG2D_QUALITY_ORTHO_MEAN_JMAX, EG2D_QUALITY_ORTHO_MEAN_IMIN};
    std::printf("orthogonality at the sides (deviation from 90 deg, max/mean):");
    for (const auto &s : side_names(topology))
        std::printf(" %s %.2f/%.2f", s.first.c_str(), q(max_metric[s.second]), q(mean_metric[s.second]));
    std::printf("\n");
}

// The monitor of a run: the progress line (and Ctrl-C), and the history of
// (iteration, residual) when a history file is asked for.
struct RunMonitor {
    Progress *progress;
    bool keep;
    std::vector<HistoryRow> rows;

    static int call(void *user, int iteration, double residual) {
        RunMonitor &m = *static_cast<RunMonitor *>(user);
        if (m.keep && std::isfinite(residual)) m.rows.push_back({iteration, residual});  // not the set-up's calls
        return Progress::monitor(m.progress, iteration, residual);
    }
};

// The text of each file the command writes itself (out.tool), in the order of
// c.outputs ("" for the library's formats): made before any file is written.
std::vector<std::string> tool_texts(const eg2d_grid *g, const Case &c, const std::vector<HistoryRow> &history,
                                    double tolerance) {
    std::vector<std::string> texts;
    for (const auto &out : c.outputs) {
        std::string text;
        if (out.tool == kHistoryCsv) text = history_csv(history);
        else if (out.tool == kHistorySvg) text = history_svg(history, tolerance, c.title);
        else if (out.tool == kControlsCsv || out.tool == kGridPng) {
            try {
                if (out.tool == kControlsCsv) text = controls_csv(g);
                else {
                    const GridLines lines = grid_lines(g);
                    const View v = domain_view(lines);
                    text = view_png(v, view_lines(lines, v));
                }
            } catch (const Failure &f) {
                throw Failure(f.exit_code(), out.where.str() + ": " + f.what());
            }
        }
        texts.push_back(std::move(text));
    }
    return texts;
}

// The output set is written as one unit (output_set.hpp). The command's own
// files (out.tool: the history, the control functions) are made as text
// before anything is written.
void write_outputs(eg2d_grid *g, const Case &c, const RunOptions &o, const std::vector<std::string> &texts) {
    if (c.svg_quality >= 0) check(g, eg2d_set_parameter(g, EG2D_PARAM_SVG_QUALITY, c.svg_quality), c.svg_quality_at);
    OutputSet set(o.out_dir);
    for (std::size_t k = 0; k < c.outputs.size(); ++k) {
        const auto &out = c.outputs[k];
        if (out.tool) set.add_text(out.name, texts[k]);
        else
            set.add(out.name, out.directory,
                    [g, &out](const std::string &path, bool) { check(g, eg2d_write(g, path.c_str(), out.format), out.where); });
    }
    for (const std::string &path : set.commit()) std::printf("wrote %s\n", path.c_str());
}

}  // namespace

// The solver that ran, its levels, and every change of strategy on the way
// (eg2d_get_run_event): a fallback is never silent.
static void print_what_ran(const eg2d_grid *g) {
    int solver = -1, levels = 1, built = 1, events = 0;
    eg2d_get_run_info(g, EG2D_RUN_SOLVER, &solver);
    eg2d_get_run_info(g, EG2D_RUN_LEVELS, &levels);
    eg2d_get_run_info(g, EG2D_RUN_LEVELS_BUILT, &built);
    eg2d_get_run_info(g, EG2D_RUN_EVENTS, &events);
    const char *name = eg2d_solver_name(solver);
    if (!name) return;
    if (built > 1)
        std::printf("solver %s, %d grid level%s (%d at the end)\n", name, built, built == 1 ? "" : "s", levels);
    else
        std::printf("solver %s\n", name);
    for (int k = 0; k < events; ++k) {
        char message[512];
        int iteration = 0;
        if (eg2d_get_run_event(g, k, &iteration, message, static_cast<int>(sizeof message)) == EG2D_OK)
            std::printf("  note, iteration %d: %s\n", iteration, message);
    }
}

// solve = false: the start grid is the result, so an initializer (TFI,
// Hermite TFI) can be seen, and drawn in the gallery, as it is. It is
// checked for folds like a solved grid (fold_check), since nothing after it
// would untangle them.
static int write_start_grid(eg2d_grid *g, const Case &c, const RunOptions &o) {
    std::printf("%s: %d x %d %s grid, %s start grid, not solved (solve = false)\n", c.title.c_str(), c.ni, c.nj,
                c.topology == EG2D_TOPO_O ? "O" : c.topology == EG2D_TOPO_C ? "C" : "single-block",
                name_of(initializers(), c.initial));
    preflight(c, o);
    print_quality(g, c.topology);
    double folded = 0, fold_check = 1;
    eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &folded);
    eg2d_get_parameter(g, EG2D_PARAM_FOLD_CHECK, &fold_check);
    if (folded > 0 && fold_check != 0)
        throw Failure(EXIT_FOLDED, c.file + ": the start grid has " + fmt(folded) +
                                       " folded cells (solve = false; no files written)");
    double tolerance = 0;  // the history picture's dashed line (the history itself is empty)
    eg2d_get_parameter(g, EG2D_PARAM_TOLERANCE, &tolerance);
    Progress signals(false, true);  // SIGINT and SIGTERM stop the set, which removes its stage
    write_outputs(g, c, o, tool_texts(g, c, {}, tolerance));
    return EXIT_OK;
}

namespace {

struct BlocksDeleter {
    void operator()(eg2d_blocks *b) const { eg2d_blocks_destroy(b); }
};
using BlocksPtr = std::unique_ptr<eg2d_blocks, BlocksDeleter>;

// A failed call on the set: the location in the case file and the set's message.
// `blocks`: the blocks' names in order, added to a message that numbers them.
void check_set(eg2d_blocks *set, int status, const Location &at, const std::string &blocks = "") {
    if (status == EG2D_ERR_MEMORY)
        throw Failure(EXIT_MEMORY, std::string("out of memory: the set is too large for this machine (") +
                                       eg2d_blocks_last_error(set) + ")");
    const std::string message = eg2d_blocks_last_error(set);
    const bool numbered = !blocks.empty() && message.find("block ") != std::string::npos;
    if (status != EG2D_OK)
        throw Failure(exit_code_for_status(status),
                      at.str() + ": " + message + (numbered ? " (blocks 0, 1, ...: " + blocks + ")" : ""));
}

// The set's files: the formats the library writes a set in (its list
// EG2D_LIST_SET_FORMATS: one mesh, a zone a block, or a VTK multiblock; eg2d_blocks_write,
// NAME.su2, NAME_foam, NAME.cgns, ...), every other library format one file
// per block (eg2d_write, NAME-BLOCK.vts, ...), the pictures one picture of
// the set. In the order of [output] formats, blocks in order.
struct SetFile {
    std::string name;
    int format;
    bool directory;
    int block;  // -1: the whole set
    Location where;
};

std::vector<SetFile> set_files(const Case &c) {
    std::vector<SetFile> files;
    for (const auto &out : c.outputs) {
        const bool whole = std::any_of(set_formats().begin(), set_formats().end(),
                                       [&](const Feature &f) { return f.id == out.format && !out.tool; });
        if (whole || out.tool == kGridPng || out.format == EG2D_FORMAT_SVG) {  // the set in one file; one picture
            files.push_back({out.name, out.tool == kGridPng ? -1 : out.format, out.directory, -1, out.where});
            continue;
        }
        std::string ext;
        for (const auto &f : formats())
            if (f.id == out.format && !f.tool) ext = f.extension;
        const std::string stem = out.name.substr(0, out.name.size() - ext.size());
        for (std::size_t b = 0; b < c.blocks.size(); ++b)
            files.push_back({stem + "-" + c.blocks[b].name + ext, out.format, out.directory, static_cast<int>(b), out.where});
    }
    return files;
}

// The set as one picture (svg, png): every block's lines in one view of the
// whole set, the joined stretches drawn as grid lines (each block's sides
// are drawn by patch, and a joined side keeps its default wall patch).
std::string set_picture(const Case &c, const std::vector<GridPtr> &grids, bool png) {
    std::vector<GridLines> blocks;
    GridLines all;
    for (const auto &g : grids) {
        blocks.push_back(grid_lines(g.get()));
        all.x.insert(all.x.end(), blocks.back().x.begin(), blocks.back().x.end());
        all.y.insert(all.y.end(), blocks.back().y.begin(), blocks.back().y.end());
    }
    for (const JoinSpec &j : c.joins)
        for (const JoinEnd &e : {j.a, j.b}) {
            GridLines &b = blocks[static_cast<std::size_t>(e.block)];
            const std::size_t ni = static_cast<std::size_t>(b.ni), top = ni * static_cast<std::size_t>(b.nj - 1);
            const int lo = std::min(e.first, e.last), hi = std::max(e.first, e.last);
            for (LineRef &l : b.lines) {
                if (l.kind == kGridLine) continue;
                int side = -1;
                std::size_t f = 0;
                if (l.stride == 1 && l.first < ni) side = EG2D_SIDE_JMIN, f = l.first;
                else if (l.stride == 1 && l.first >= top) side = EG2D_SIDE_JMAX, f = l.first - top;
                else if (l.stride == ni && l.first % ni == 0) side = EG2D_SIDE_IMIN, f = l.first / ni;
                else if (l.stride == ni && l.first % ni == ni - 1) side = EG2D_SIDE_IMAX, f = l.first / ni;
                if (side == e.side && static_cast<int>(f) >= lo && static_cast<int>(f) + l.count - 1 <= hi) l.kind = kGridLine;
            }
        }
    const View v = domain_view(all);
    std::vector<Polyline> shown;
    for (const GridLines &b : blocks) {
        std::vector<Polyline> p = view_lines(b, v);
        shown.insert(shown.end(), p.begin(), p.end());
    }
    // grid lines first, then boundaries, walls last (on top), as for one grid
    std::stable_sort(shown.begin(), shown.end(), [](const Polyline &a, const Polyline &b) { return a.kind < b.kind; });
    return png ? view_png(v, shown) : view_svg(v, shown, "eg2d " + c.title + ": the set of blocks");
}

// A case of [[blocks]]: each block a single-block grid with the case's
// system, solver and parameters, its own sides and patches; the set joins
// and solves them (eg2d_blocks_*), block 0's settings driving it.
// A set's wall layer may not be made (its run notes say why): a median
// first cell this many times off the asked height exits EXIT_GEOMETRY too.
constexpr double kSetFirstOff = 2.0;

int run_block_set(const Case &c, const RunOptions &o) {
    std::vector<GridPtr> grids;
    for (const BlockSpec &b : c.blocks) {
        eg2d_grid *raw = nullptr;
        check(nullptr, eg2d_create(b.ni, b.nj, &raw), b.size_at);
        grids.emplace_back(raw);
        eg2d_grid *g = raw;
        check(g, eg2d_set_system(g, c.system), c.system_at);
        check(g, eg2d_set_solver(g, c.solver), c.solver_at);
        std::vector<ParameterSetting> params = c.parameters;
        std::stable_partition(params.begin(), params.end(), [](const ParameterSetting &p) { return p.value != 0.0; });
        for (const auto &p : params) check(g, eg2d_set_parameter(g, p.id, p.value), p.where);
        for (const auto &s : b.sides) {
            const bool along_i = s.side == EG2D_SIDE_JMIN || s.side == EG2D_SIDE_JMAX;
            std::vector<double> x, y;
            side_nodes(s, along_i ? b.ni : b.nj, false, b.constants, x, y);
            check(g, eg2d_set_side(g, s.side, x.data(), y.data()), s.where);
        }
        for (const auto &p : b.patches)
            check(g, eg2d_set_patch(g, p.side, p.first, p.last, p.type, p.name.c_str()), p.where);
        apply_wall_spacings(g, b.wall_spacings);
    }
    eg2d_blocks *raw_set = nullptr;
    check_set(nullptr, eg2d_blocks_create(&raw_set), c.blocks_at);
    BlocksPtr owner(raw_set);
    eg2d_blocks *set = owner.get();
    std::string names;
    for (const BlockSpec &b : c.blocks) names += (names.empty() ? "" : ", ") + b.name;
    for (std::size_t k = 0; k < grids.size(); ++k) {
        int index = 0;
        check_set(set, eg2d_blocks_add(set, grids[k].get(), &index), c.blocks[k].where);
        // A name the library refuses is the case file's error, as another key's is.
        const int named = eg2d_blocks_set_name(set, index, c.blocks[k].name.c_str());
        if (named == EG2D_ERR_ARGUMENT)
            throw Failure(EXIT_CASE, c.blocks[k].name_at.str() + ": " + eg2d_blocks_last_error(set));
        check_set(set, named, c.blocks[k].name_at);
    }
    for (std::size_t k = 0; k < c.joins.size(); ++k) {
        const JoinSpec &j = c.joins[k];
        check_set(set, eg2d_blocks_join(set, j.a.block, j.a.side, j.a.first, j.a.last, j.b.block, j.b.side, j.b.first,
                                        j.b.last),
                  j.where, names);
        if (j.held) check_set(set, eg2d_blocks_hold_join(set, static_cast<int>(k), 1), j.where, names);
    }
    // The library names a join by its blocks' indices and sides: the case
    // file's message names the join's key where the message is about one.
    if (const int status = eg2d_blocks_check(set); status != EG2D_OK) {
        static const char *const library_side[] = {"JMIN", "IMAX", "JMAX", "IMIN"};
        const std::string message = eg2d_blocks_last_error(set);
        Location at = c.blocks_at;
        for (const JoinSpec &j : c.joins) {
            char text[256];
            std::snprintf(text, sizeof text, "join block %d side %s nodes %d..%d to block %d side %s nodes %d..%d",
                          j.a.block, library_side[j.a.side], j.a.first, j.a.last, j.b.block, library_side[j.b.side],
                          j.b.first, j.b.last);
            if (message.find(text) != std::string::npos) at = j.where;
        }
        int block = -1;
        if (message.find(" system ") != std::string::npos) at = c.system_at;  // the case's, every block's
        else if (at.key == c.blocks_at.key && std::sscanf(message.c_str(), "eg2d_blocks_check: block %d", &block) == 1 &&
                 block >= 0 && block < static_cast<int>(c.blocks.size()))
            at = c.blocks[static_cast<std::size_t>(block)].where;  // a block no join reaches, ...
        check_set(set, status, at, names);
    }

    double tolerance = 0;
    eg2d_get_parameter(grids.front().get(), EG2D_PARAM_TOLERANCE, &tolerance);
    long nodes = 0;
    for (const BlockSpec &b : c.blocks) nodes += static_cast<long>(b.ni) * b.nj;
    std::printf("%s: a set of %zu blocks, %zu join%s, %ld nodes, %s system, %s solver, tolerance %.3g\n", c.title.c_str(),
                c.blocks.size(), c.joins.size(), c.joins.size() == 1 ? "" : "s", nodes, name_of(systems(), c.system),
                eg2d_solver_name(c.solver), tolerance);
    for (const BlockSpec &b : c.blocks) std::printf("  block %s: %d x %d\n", b.name.c_str(), b.ni, b.nj);
    std::fflush(stdout);

    const std::vector<SetFile> files = set_files(c);
    std::vector<PlannedPath> paths;
    for (const auto &f : files) paths.push_back({f.name, f.format, f.directory, f.where.str()});
    check_before_solving(o.out_dir, paths);

    const auto start = std::chrono::steady_clock::now();
    const int status = eg2d_blocks_solve(set);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // (the solve's own message: eg2d_blocks_get_run on a set refused before
    // it ran sets the set's last error to its own)
    const std::string why = status == EG2D_OK ? "" : eg2d_blocks_last_error(set);
    int iterations = 0, unknowns = 0;
    double residual = 0;
    const bool ran = eg2d_blocks_get_run(set, &iterations, &residual, &unknowns) == EG2D_OK;
    if (status == EG2D_ERR_INTERRUPTED) {
        std::printf("interrupted at iteration %d, residual %.3e: no files written\n", iterations, residual);
        return EXIT_INTERRUPTED;
    }
    if (status == EG2D_OK)
        std::printf("converged in %d iterations, residual %.3e, %d nodes solved for, %.2f s\n", iterations, residual,
                    unknowns, seconds);
    print_what_ran(grids[0].get());  // every block describes the set's run
    if (status != EG2D_OK && status != EG2D_ERR_DIVERGED && ran)
        std::printf("stopped after %d iterations, residual %.3e\n", iterations, residual);
    if (status != EG2D_OK) throw Failure(exit_code_for_status(status), c.file + ": " + why + " (no files written)");
    double at_joins = 0, nearby = 0;
    check_set(set, eg2d_blocks_get_kinks(set, &at_joins, &nearby), c.blocks_at);
    const auto held = std::count_if(c.joins.begin(), c.joins.end(), [](const JoinSpec &j) { return j.held; });
    if (held < static_cast<long>(c.joins.size()))
        std::printf("grid lines across the joins: turns up to %.2f deg at the joined nodes, %.2f deg one line into "
                    "the blocks%s\n", at_joins, nearby,
                    held > 0 ? " (the free joins; held ones are boundaries the lines meet)" : "");
    else
        std::printf("grid lines across the joins: every join is held (lines placed by the case, met as boundaries: "
                    "their turns are not measured)\n");
    // the quality of the set: folded cells summed, then every block's
    double folded = 0, fold_check = 1;
    for (const auto &g : grids) {
        double f = 0;
        eg2d_get_quality(g.get(), EG2D_QUALITY_FOLDED_CELLS, &f);
        folded += f;
    }
    std::printf("quality: %.0f folded cells in the set\n", folded);
    for (std::size_t k = 0; k < grids.size(); ++k) {
        eg2d_grid *g = grids[k].get();
        double f = 0, lo = 0, hi = 0, skew = 0, aspect = 0;
        eg2d_get_quality(g, EG2D_QUALITY_FOLDED_CELLS, &f);
        eg2d_get_quality(g, EG2D_QUALITY_MIN_AREA, &lo);
        eg2d_get_quality(g, EG2D_QUALITY_MAX_AREA, &hi);
        eg2d_get_quality(g, EG2D_QUALITY_SKEWNESS, &skew);
        eg2d_get_quality(g, EG2D_QUALITY_ASPECT_RATIO, &aspect);
        std::printf("  block %s: %.0f folded cells, cell area %.4g to %.4g, skewness max %.2f deg, aspect ratio max %.3g\n",
                    c.blocks[k].name.c_str(), f, lo, hi, skew, aspect);
    }
    eg2d_get_parameter(grids.front().get(), EG2D_PARAM_FOLD_CHECK, &fold_check);
    if (folded > 0 && fold_check != 0)
        throw Failure(EXIT_FOLDED, c.file + ": the set has " + fmt(folded) + " folded cells (no files written)");
    // Each block's walls as a single grid's: a layer that grows too fast
    // exits EXIT_GEOMETRY, the files written.
    bool short_layer = false;
    for (std::size_t k = 0; k < grids.size(); ++k)
        short_layer = print_wall_layers(grids[k].get(), EG2D_TOPO_SINGLE, c.blocks[k].wall_spacings,
                                        c.wall_growth_limit, "block " + c.blocks[k].name + " ", kSetFirstOff) ||
                      short_layer;

    Progress signals(false, true);  // SIGINT and SIGTERM stop the set, which removes its stage
    if (c.svg_quality >= 0)
        for (auto &g : grids) check(g.get(), eg2d_set_parameter(g.get(), EG2D_PARAM_SVG_QUALITY, c.svg_quality), c.svg_quality_at);
    OutputSet out(o.out_dir);
    for (const SetFile &f : files) {
        if (f.block < 0 && (f.format == EG2D_FORMAT_SVG || f.format < 0)) {
            try {
                out.add_text(f.name, set_picture(c, grids, f.format < 0));
            } catch (const Failure &e) {
                throw Failure(e.exit_code(), f.where.str() + ": " + e.what());
            }
        } else if (f.block < 0)
            out.add(f.name, f.directory, [set, &f](const std::string &path, bool) {
                check_set(set, eg2d_blocks_write(set, path.c_str(), f.format), f.where);
            });
        else {
            eg2d_grid *g = grids[static_cast<std::size_t>(f.block)].get();
            out.add(f.name, f.directory,
                    [g, &f](const std::string &path, bool) { check(g, eg2d_write(g, path.c_str(), f.format), f.where); });
        }
    }
    for (const std::string &path : out.commit()) std::printf("wrote %s\n", path.c_str());
    return short_layer ? EXIT_GEOMETRY : EXIT_OK;
}

}  // namespace

int run_case(const Case &c, const RunOptions &o) {
    if (!c.blocks.empty()) return run_block_set(c, o);
    eg2d_grid *raw = nullptr;
    check(nullptr, eg2d_create(c.ni, c.nj, &raw), c.size_at);
    GridPtr grid(raw);
    eg2d_grid *g = grid.get();
    check(g, eg2d_set_topology(g, c.topology), c.topology_at);
    check(g, eg2d_set_system(g, c.system), c.system_at);
    check(g, eg2d_set_solver(g, c.solver), c.solver_at);
    // Zeros last: a setting that is 0 cannot be what makes another one valid,
    // and the library refuses a step that leaves every variational weight 0.
    std::vector<ParameterSetting> params = c.parameters;
    std::stable_partition(params.begin(), params.end(), [](const ParameterSetting &p) { return p.value != 0.0; });
    for (const auto &p : params) check(g, eg2d_set_parameter(g, p.id, p.value), p.where);
    std::vector<SlidingSide> sliding;  // alive for the whole run
    for (const auto &s : c.sides) {
        if (s.pieces.front().sliding) {
            sliding.emplace_back(g, s, c.constants);
            continue;
        }
        const bool along_i = s.side == EG2D_SIDE_JMIN || s.side == EG2D_SIDE_JMAX;
        std::vector<double> x, y;
        side_nodes(s, along_i ? c.ni : c.nj, c.topology == EG2D_TOPO_O, c.constants, x, y);
        check(g, eg2d_set_side(g, s.side, x.data(), y.data()), s.where);
    }
    for (const auto &p : c.patches)
        check(g, eg2d_set_patch(g, p.side, p.first, p.last, p.type, p.name.c_str()), p.where);
    for (const auto &l : c.interior_lines) {
        std::vector<double> x, y;
        side_nodes(l.curve, l.direction == EG2D_XI ? c.nj : c.ni,
                   c.topology == EG2D_TOPO_O && l.direction == EG2D_ETA, c.constants, x, y);
        check(g, eg2d_set_interior_line(g, l.direction, l.index, x.data(), y.data()), l.where);
    }
    apply_controls(g, c);
    check(g, eg2d_initialize(g, c.initial), c.initial_at);
    if (!c.solve) return write_start_grid(g, c, o);

    double tolerance = 0;
    eg2d_get_parameter(g, EG2D_PARAM_TOLERANCE, &tolerance);
    std::printf("%s: %d x %d %s grid, %s system, %s solver, tolerance %.3g\n", c.title.c_str(), c.ni, c.nj,
                c.topology == EG2D_TOPO_O ? "O" : c.topology == EG2D_TOPO_C ? "C" : "single-block", name_of(systems(), c.system),
                eg2d_solver_name(c.solver), tolerance);
    std::fflush(stdout);

    preflight(c, o);
    // Ctrl-C is caught from here to the last file written: during the run the
    // monitor stops it; while writing, the next file is not begun.
    Progress progress(o.live, o.quiet);
    RunMonitor monitor{&progress, false, {}};
    for (const auto &out : c.outputs) monitor.keep = monitor.keep || out.tool == kHistoryCsv || out.tool == kHistorySvg;
    const auto start = std::chrono::steady_clock::now();
    eg2d_set_monitor(g, &RunMonitor::call, &monitor);
    const int status = eg2d_solve(g);
    eg2d_set_monitor(g, nullptr, nullptr);
    progress.finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int iterations = 0;
    double residual = 0;
    eg2d_get_iterations(g, &iterations);
    eg2d_get_residual(g, &residual);
    if (status == EG2D_ERR_INTERRUPTED) {
        std::printf("interrupted by %s at iteration %d, residual %.3e: no files written\n", Progress::interrupt_name(),
                    iterations, residual);
        return Progress::interrupt_exit_code();
    }
    if (status == EG2D_OK)
        std::printf("converged in %d iterations, residual %.3e, %.2f s\n", iterations, residual, seconds);
    print_what_ran(g);
    print_quality(g, c.topology);
    if (status != EG2D_OK)
        throw Failure(exit_code_for_status(status), c.file + ": " + eg2d_last_error(g) + " (no files written)");
    const bool short_layer = print_wall_layers(g, c.topology, c.wall_spacings, c.wall_growth_limit);
    write_outputs(g, c, o, tool_texts(g, c, monitor.rows, tolerance));
    return short_layer ? EXIT_GEOMETRY : EXIT_OK;
}

}  // namespace eg2dtool
