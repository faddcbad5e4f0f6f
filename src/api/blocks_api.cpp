// Sets of blocks: create, join, check, solve, query.
#include <algorithm>
#include <functional>

#include "api/blocks_handle.hpp"
#include "blocks/join_kinks.hpp"
#include "io/formats.hpp"
#include "io/unstructured.hpp"

using namespace eg2d;
using namespace eg2d::api;

namespace eg2d {
namespace api {

void forget_in_sets(eg2d_grid *grid) noexcept {
    for (eg2d_blocks *s : grid->sets) {
        s->set.forget(&grid->gen);
        std::replace(s->grids.begin(), s->grids.end(), grid, static_cast<eg2d_grid *>(nullptr));
    }
}

}  // namespace api
}  // namespace eg2d

namespace {

Side side_of(int side, const char *name) {
    require(side >= EG2D_SIDE_JMIN && side <= EG2D_SIDE_IMIN,
            format("%s = %d: not EG2D_SIDE_JMIN (0), EG2D_SIDE_IMAX (1), EG2D_SIDE_JMAX (2) or EG2D_SIDE_IMIN (3)", name,
                   side));
    return static_cast<Side>(side);
}

}  // namespace

extern "C" {

EG2D_API int eg2d_blocks_create(eg2d_blocks **set) {
    if (set) *set = nullptr;
    return guard_without_grid("eg2d_blocks_create", [&] {
        require_ptr(set, "set");
        *set = new eg2d_blocks;
    });
}

EG2D_API void eg2d_blocks_destroy(eg2d_blocks *set) {
    if (!set) return;
    for (eg2d_grid *g : set->grids)
        if (g) g->sets.erase(std::remove(g->sets.begin(), g->sets.end(), set), g->sets.end());
    delete set;
}

EG2D_API const char *eg2d_blocks_last_error(const eg2d_blocks *set) {
    return set ? set->last_error.c_str() : eg2d_last_error(nullptr);
}

EG2D_API int eg2d_blocks_add(eg2d_blocks *set, eg2d_grid *grid, int *block) {
    return guard_set(set, "eg2d_blocks_add", [&] {
        require_ptr(grid, "grid");
        require_ptr(block, "block");
        // Room first, then the changes that cannot throw: strong guarantee.
        set->grids.reserve(set->grids.size() + 1);
        grid->sets.reserve(grid->sets.size() + 1);
        const int b = set->set.add(&grid->gen);
        set->grids.push_back(grid);
        grid->sets.push_back(set);
        *block = b;
    });
}

EG2D_API int eg2d_blocks_join(eg2d_blocks *set, int block_a, int side_a, int first_a, int last_a, int block_b,
                              int side_b, int first_b, int last_b) {
    return guard_set(set, "eg2d_blocks_join", [&] {
        const Join j{SideRange{block_a, side_of(side_a, "side_a"), first_a, last_a},
                     SideRange{block_b, side_of(side_b, "side_b"), first_b, last_b}};
        set->set.join(j);
    });
}

EG2D_API int eg2d_blocks_hold_join(eg2d_blocks *set, int join, int held) {
    return guard_set(set, "eg2d_blocks_hold_join", [&] {
        require(held == 0 || held == 1, format("held = %d: must be 0 or 1", held));
        set->set.hold(join, held == 1);
    });
}

EG2D_API int eg2d_blocks_set_name(eg2d_blocks *set, int block, const char *name) {
    return guard_set(set, "eg2d_blocks_set_name", [&] {
        require_ptr(name, "name");
        set->set.rename(block, name);
    });
}

EG2D_API const char *eg2d_blocks_name(const eg2d_blocks *set, int block) {
    return set && block >= 0 && block < set->set.size() ? set->set.name(block).c_str() : nullptr;
}

EG2D_API int eg2d_blocks_check(eg2d_blocks *set) {
    return guard_set(set, "eg2d_blocks_check", [&] { set->set.check(); });
}

EG2D_API int eg2d_blocks_solve(eg2d_blocks *set) {
    return guard_set(set, "eg2d_blocks_solve", [&] {
        set->ran = false;
        set->run = SetRun{};
        struct Ran {  // a run that failed after iterating still says how far it got
            eg2d_blocks *s;
            ~Ran() { s->ran = s->run.iterations > 0 || s->run.unknowns > 0; }
        } ran{set};
        set->set.check();  // (block 0 exists)
        const std::function<bool(int, double)> &monitor = set->set.block(0)->monitor;
        solve_set(set->set,
                  monitor ? std::function<bool(long, double)>([&](long it, double r) {
                      return monitor(static_cast<int>(std::min<long>(it, 2147483647L)), r);
                  })
                          : std::function<bool(long, double)>(),
                  set->run);
    });
}

EG2D_API int eg2d_blocks_get_run(const eg2d_blocks *set, int *iterations, double *residual, int *unknowns) {
    return guard_set(set, "eg2d_blocks_get_run", [&] {
        if (!set->ran) fail(Failure::State, "the set has not run (eg2d_blocks_solve)");
        if (iterations) *iterations = static_cast<int>(std::min<long>(set->run.iterations, 2147483647L));
        if (residual) *residual = set->run.residual;
        if (unknowns) *unknowns = static_cast<int>(std::min<long>(set->run.unknowns, 2147483647L));
    });
}

EG2D_API int eg2d_blocks_get_kinks(const eg2d_blocks *set, double *at_joins, double *nearby) {
    return guard_set(set, "eg2d_blocks_get_kinks", [&] {
        require_ptr(at_joins, "at_joins");
        require_ptr(nearby, "nearby");
        set->set.check();
        for (int b = 0; b < set->set.size(); ++b)
            if (!set->set.block(b)->grid().initialized())
                fail(Failure::State, format("block %d is not initialised (eg2d_initialize or eg2d_blocks_solve)", b));
        const JoinKinks k = join_kinks(set->set);
        *at_joins = k.at_joins;
        *nearby = k.nearby;
    });
}

EG2D_API int eg2d_blocks_write(const eg2d_blocks *set, const char *path, int file_format) {
    return guard_set(set, "eg2d_blocks_write", [&] {
        require_ptr(path, "path");
        const SetWriting how = set_writing(file_format);
        set->set.check();
        const BlockSet &bs = set->set;
        std::vector<MeshBlock> blocks;
        long nodes = 0;
        for (int b = 0; b < bs.size(); ++b) {
            const Grid &g = bs.block(b)->grid();
            if (!g.initialized())
                fail(Failure::State, format("block %d is not initialised (eg2d_initialize or eg2d_blocks_solve)", b));
            MeshBlock mb{&g, {}};
            for (int s = 0; s < 4; ++s) mb.joined[static_cast<std::size_t>(s)].assign(static_cast<std::size_t>(g.side_length(Side(s))), 0);
            blocks.push_back(std::move(mb));
            nodes += static_cast<long>(g.size());
        }
        if (how == SetWriting::Zones) {
            std::vector<const Grid *> grids;
            for (const MeshBlock &mb : blocks) grids.push_back(mb.grid);
            std::vector<ZoneJoin> joins;
            for (const Join &j : bs.joins())
                joins.push_back(ZoneJoin{j.a.block, j.a.side, j.a.first, j.a.last, j.b.block, j.b.side, j.b.first, j.b.last});
            std::vector<std::string> names;
            for (int b = 0; b < bs.size(); ++b) names.push_back(bs.name(b));
            write_blocks(grids, joins, names, bs.block(0)->settings, path, file_format);
            return;
        }
        std::vector<MeshTwin> twins;
        for (const Join &j : bs.joins()) {
            const Grid &ga = bs.block(j.a.block)->grid(), &gb = bs.block(j.b.block)->grid();
            for (int t = 0; t < j.a.count(); ++t) {
                twins.push_back(MeshTwin{j.a.block, side_node(ga, j.a.side, j.a.at(t)), j.b.block,
                                         side_node(gb, j.b.side, j.b.at(t))});
                if (t + 1 < j.a.count()) {  // the edge between nodes t and t+1 of either range
                    for (const SideRange *r : {&j.a, &j.b}) {
                        const int q = std::min(r->at(t), r->at(t + 1));
                        blocks[static_cast<std::size_t>(r->block)].joined[static_cast<std::size_t>(r->side)][static_cast<std::size_t>(q)] = 1;
                    }
                }
            }
        }
        UnstructuredMesh mesh = unstructured_mesh(blocks, twins);
        std::size_t first = 0;  // its cells are the blocks', block by block
        for (int b = 0; b < bs.size(); ++b) {
            const Grid &g = bs.block(b)->grid();
            const std::size_t count = static_cast<std::size_t>(g.ni() - 1) * static_cast<std::size_t>(g.nj() - 1);
            mesh.zones.push_back(CellZone{bs.name(b), first, count});
            first += count;
        }
        write_mesh(mesh, bs.block(0)->settings, format("a set of %d blocks, %ld nodes", bs.size(), nodes), path, file_format);
    });
}

}  // extern "C"
