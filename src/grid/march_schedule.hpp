// The marching schedule of the hyperbolic march: the height of each layer.
// Heights grow geometrically, h_k = h_1 r^(k-1), k = 1..N, with the ratio r
// found so that they add up to the marching distance D (docs/hyperbolic.md).
#pragma once
#include <vector>

namespace eg2d {

// N >= 1 layers, D > 0, growth limit G >= 1. first_height h_1 > 0, or 0 for
// automatic: the h_1 whose constant ratio is r = 1 + (G-1)/2, half the
// allowed growth. Throws Failure::Argument when h_1 cannot reach D with
// 1/G <= r <= G.
std::vector<double> march_schedule(int layers, double distance, double first_height, double growth);

// The ratio r >= 1 of n geometric cells from `first` that add up to
// `distance` (1 when n cells of `first` already reach it).
double covering_ratio(int n, double first, double distance);

}  // namespace eg2d
