#include "base/block_tridiagonal.hpp"

namespace eg2d {

namespace {
Mat2 mul(const Mat2 &p, const Mat2 &q) {
    return {p.a * q.a + p.b * q.c, p.a * q.b + p.b * q.d, p.c * q.a + p.d * q.c, p.c * q.b + p.d * q.d};
}
Vec2 mul(const Mat2 &p, const Vec2 &v) { return {p.a * v.x + p.b * v.y, p.c * v.x + p.d * v.y}; }
Mat2 mul(const Mat2 &p, double s) { return {p.a * s, p.b * s, p.c * s, p.d * s}; }
Vec2 mul(const Vec2 &v, double s) { return {v.x * s, v.y * s}; }
Mat2 sub(const Mat2 &p, const Mat2 &q) { return {p.a - q.a, p.b - q.b, p.c - q.c, p.d - q.d}; }
Mat2 add(const Mat2 &p, const Mat2 &q) { return {p.a + q.a, p.b + q.b, p.c + q.c, p.d + q.d}; }
Vec2 sub(const Vec2 &p, const Vec2 &q) { return {p.x - q.x, p.y - q.y}; }
Vec2 add(const Vec2 &p, const Vec2 &q) { return {p.x + q.x, p.y + q.y}; }
Mat2 adjugate(const Mat2 &m) { return {m.d, -m.b, -m.c, m.a}; }
double det(const Mat2 &m) { return m.a * m.d - m.b * m.c; }
Mat2 inv(const Mat2 &m) { return mul(adjugate(m), 1.0 / det(m)); }

// Block Thomas on rows 0..n-1 for a vector right-hand side r and, WithQ, a
// matrix one Q (two more columns). G is scratch. Each pivot's inverse is
// its adjugate over its determinant, the division last: the products with
// the adjugate run while it divides, as the recurrence waits on each row
// (the march's layer solves were a fifth of a large C-grid's run, NACA 0012
// 7169x2049, perf).
template <bool WithQ>
void thomas(std::size_t n, const Mat2 *A, const Mat2 *B, const Mat2 *C, Vec2 *r, Mat2 *Q, std::vector<Mat2> &G) {
    G.resize(n);
    Mat2 adj = adjugate(B[0]);
    double s = 1.0 / det(B[0]);
    G[0] = mul(mul(adj, C[0]), s);
    r[0] = mul(mul(adj, r[0]), s);
    if constexpr (WithQ) Q[0] = mul(mul(adj, Q[0]), s);
    for (std::size_t k = 1; k < n; ++k) {
        const Mat2 P = sub(B[k], mul(A[k], G[k - 1]));
        adj = adjugate(P);
        s = 1.0 / det(P);
        G[k] = mul(mul(adj, C[k]), s);
        r[k] = mul(mul(adj, sub(r[k], mul(A[k], r[k - 1]))), s);
        if constexpr (WithQ) Q[k] = mul(mul(adj, sub(Q[k], mul(A[k], Q[k - 1]))), s);
    }
    for (std::size_t k = n - 1; k-- > 0;) {
        r[k] = sub(r[k], mul(G[k], r[k + 1]));
        if constexpr (WithQ) Q[k] = sub(Q[k], mul(G[k], Q[k + 1]));
    }
}
}  // namespace

void solve_block_tridiagonal2(std::size_t n, const Mat2 *A, const Mat2 *B, const Mat2 *C, Vec2 *r,
                              std::vector<Mat2> &scratch) {
    thomas<false>(n, A, B, C, r, nullptr, scratch);
}

void solve_cyclic_block_tridiagonal2(std::size_t n, const Mat2 *A, const Mat2 *B, const Mat2 *C, Vec2 *r) {
    // Rows 0..n-2 in u[0..n-2], with u[n-1] moved to the right: u = p + Q u[n-1],
    // where Q solves the same rows for -A[0] in row 0 and -C[n-2] in row n-2.
    const std::size_t m = n - 1;
    std::vector<Mat2> Q(m), G;
    Q[0] = sub(Q[0], A[0]);
    Q[m - 1] = sub(Q[m - 1], C[m - 1]);
    thomas<true>(m, A, B, C, r, Q.data(), G);
    // Row n-1: A u[n-2] + B u[n-1] + C u[0] = r[n-1].
    const Mat2 S = add(B[m], add(mul(A[m], Q[m - 1]), mul(C[m], Q[0])));
    const Vec2 last = mul(inv(S), sub(r[m], add(mul(A[m], r[m - 1]), mul(C[m], r[0]))));
    r[m] = last;
    for (std::size_t k = 0; k < m; ++k) r[k] = add(r[k], mul(Q[k], last));
}

}  // namespace eg2d
