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

// n >= 2 cells c_k = exp(ln first + k (ln last - ln first) / (n-1) + q k (k-(n-1))),
// k = 0..n-1, from `first` to `last`, with q found so that they add up to
// `distance`: the log of the cell a quadratic, so the ratio of consecutive
// cells changes linearly along the line (a geometric series when q = 0).
// guess, when given, is where the solve for q starts (and gets q): the
// previous column's, which makes the hybrid layer's respacing of thousands
// of similar columns 2-3 Newton steps each.
std::vector<double> graded_cells(int n, double first, double last, double distance, double *guess = nullptr);

// The largest first cell whose graded_cells do not shrink: their first
// ratio is 1 (cells first exp(q k^2)).
// guess as graded_cells' (the log of the first cell).
double largest_graded_first(int n, double last, double distance, double *guess = nullptr);

}  // namespace eg2d
