// How grid lines cross a set's joins: the turn of each line that crosses a
// join at the joined node, against its turns one line into either block.
// Blocks interpolated on their own (blockMesh's algebraic blocks, TFI) kink
// at the joins; a set solved as one grid does not.
#pragma once
#include "blocks/block_set.hpp"

namespace eg2d {

struct JoinKinks {
    double at_joins = 0.0;  // degrees: the largest turn at a joined node (vertices left out)
    double nearby = 0.0;    // degrees: the largest turn of the same lines one node into either block
};

// From the blocks' current coordinates (each at least 3 nodes each way).
JoinKinks join_kinks(const BlockSet &set);

}  // namespace eg2d
