// The graded wall layer on a set of blocks: the single block's
// (grid/graded_layer.hpp) on the set's grid lines, which run on from block
// to block across the joins. Each stretch of a line between two nodes the
// solve does not move (the domain's boundary, a held vertex; in the second
// pass the free vertices too) is one line to grade: from the first-cell
// height of a wall it leaves at either end (each block's
// eg2d_set_wall_spacing, over its sides' wall patches), its cells graded
// (graded_line_cells) within kGradedRows cells of the wall, blended in the
// log into its present spacing beyond (wall_shares, fit_length). A line
// leaves a wall when its first segment is the wall's block's grid line off
// that side: at a step's corner the row that continues the floor leaves
// the step's face. The set is then solved twice (set_solve.cpp): on the
// one-dimensional controls of its re-spaced lines (Thomas & Middlecoff
// 1980), which smooth it without losing the spacing, then, its lines
// re-spaced again where that solve made the first cells drift, on the
// controls that make it an exact solution (Composite::hold_spacing), as
// the single block's second step does (reshape_graded_layer).
#pragma once
#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "blocks/block_set.hpp"
#include "blocks/composite.hpp"

namespace eg2d {

struct SetLayerFigures {
    int lines = 0;           // lines graded from a wall
    double growth = 1.0;     // the largest ratio of consecutive cells within kGradedRows of a wall
    double first_off = 0.0;  // the largest |first cell / height - 1| along the lines
};

class SetWallLayer {
public:
    // The set's lines and the walls at their ends; empty when no block asks
    // a wall a height.
    SetWallLayer(const BlockSet &set, const Composite &c);
    bool empty() const { return walls_ == 0; }
    // Whether some block of the set asks a wall a first-cell height.
    static bool asks_walls(const BlockSet &set);
    // Every line with a wall end re-spaced along itself, every copy of a
    // node moved with it, c synced. `vertices`: whether the free vertices
    // move (the first pass: its cells scaled to the heights) or end lines
    // (the second: the first cells' errors moved out, corrected()).
    void respace(Composite &c, bool vertices) const;
    // Each line leaving a wall turned to the wall's normal near it: all the
    // way at the wall, less over the rows the height's scale fades over, each
    // node at its distance along the line (the single block's
    // turn_to_normals). Free vertices stay.
    void turn_to_normals(Composite &c) const;
    SetLayerFigures measure(const Composite &c) const;
    // The boundary's lines that leave a wall with a first cell more than
    // kSidesOff times off its height: the solve holds their points, and the
    // lines beside them follow them, not the wall ("" when none).
    std::string kept_sides(const Composite &c) const;

private:
    struct NodeRef {
        int b, i, j;
    };
    // A stretch of a line between two nodes the solve holds, by node id.
    // Where a line leaves a wall: node p of block b's side.
    struct WallAt {
        int b = 0;
        Side side = Side::JMin;
        int p = 0;
        Vec2 normal;  // the wall's unit normal into the domain
    };
    struct Stretch {
        std::vector<int> ids;
        double first = 0.0, last = 0.0;  // heights at its ends (0: no wall)
        WallAt first_wall, last_wall;
    };
    std::vector<Stretch> stretches(const Composite &c, bool vertices) const;
    // The lines graded from a wall, by their first two nodes.
    using Graded = std::set<std::pair<int, int>>;
    static Graded graded_starts(const std::vector<Stretch> &all);
    double taper(const Composite &c, const WallAt &w, const Graded &graded, bool turning = false) const;
    double height_on(int b, Side side, int i, int j) const;
    double height_leaving(const Composite &c, int id, int next, WallAt &wall) const;
    // The second pass's arc lengths of s's nodes: its first cells moved to
    // their heights, no node further than a first cell's error.
    std::vector<double> corrected(const Stretch &s, const std::vector<double> &arc, const Graded &graded,
                                  const Composite &c) const;
    void move_along(Composite &c, const Stretch &s, const std::vector<Vec2> &points, const std::vector<double> &arc,
                    const std::vector<double> &want) const;
    int id(int b, int i, int j) const {
        return ids_[static_cast<std::size_t>(b)][static_cast<std::size_t>(i) +
                                                  static_cast<std::size_t>(ni_[static_cast<std::size_t>(b)]) *
                                                      static_cast<std::size_t>(j)];
    }

    std::vector<int> ni_, nj_;
    std::vector<std::vector<int>> ids_;               // per block node (Fortran order): the set's node
    std::vector<std::vector<NodeRef>> copies_;        // per set node: every block's copy
    std::vector<std::array<std::vector<double>, 4>> heights_;  // per block and side: each node's first cell
    std::vector<std::vector<int>> lines_;             // the set's grid lines, end to end, by node id
    int walls_ = 0;
};

}  // namespace eg2d
