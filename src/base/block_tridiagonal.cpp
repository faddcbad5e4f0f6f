#include "base/block_tridiagonal.hpp"

namespace eg2d {

namespace {
// One division, not four: the march's layer solves are a fifth of a large
// C-grid's run (NACA 0012 7169x2049, perf).
Mat2 inv(const Mat2 &m) {
    const double r = 1.0 / (m.a * m.d - m.b * m.c);
    return {m.d * r, -m.b * r, -m.c * r, m.a * r};
}
Mat2 mul(const Mat2 &p, const Mat2 &q) {
    return {p.a * q.a + p.b * q.c, p.a * q.b + p.b * q.d, p.c * q.a + p.d * q.c, p.c * q.b + p.d * q.d};
}
Vec2 mul(const Mat2 &p, const Vec2 &v) { return {p.a * v.x + p.b * v.y, p.c * v.x + p.d * v.y}; }
Mat2 sub(const Mat2 &p, const Mat2 &q) { return {p.a - q.a, p.b - q.b, p.c - q.c, p.d - q.d}; }
Mat2 add(const Mat2 &p, const Mat2 &q) { return {p.a + q.a, p.b + q.b, p.c + q.c, p.d + q.d}; }
Vec2 sub(const Vec2 &p, const Vec2 &q) { return {p.x - q.x, p.y - q.y}; }
Vec2 add(const Vec2 &p, const Vec2 &q) { return {p.x + q.x, p.y + q.y}; }

// Block Thomas on rows 0..n-1 for a vector right-hand side r and a matrix
// one Q (two more columns); either may be absent. G is scratch.
void thomas(std::size_t n, const Mat2 *A, const Mat2 *B, const Mat2 *C, Vec2 *r, Mat2 *Q, std::vector<Mat2> &G) {
    G.resize(n);
    Mat2 Minv = inv(B[0]);
    G[0] = mul(Minv, C[0]);
    if (r) r[0] = mul(Minv, r[0]);
    if (Q) Q[0] = mul(Minv, Q[0]);
    for (std::size_t k = 1; k < n; ++k) {
        Minv = inv(sub(B[k], mul(A[k], G[k - 1])));
        G[k] = mul(Minv, C[k]);
        if (r) r[k] = mul(Minv, sub(r[k], mul(A[k], r[k - 1])));
        if (Q) Q[k] = mul(Minv, sub(Q[k], mul(A[k], Q[k - 1])));
    }
    for (std::size_t k = n - 1; k-- > 0;) {
        if (r) r[k] = sub(r[k], mul(G[k], r[k + 1]));
        if (Q) Q[k] = sub(Q[k], mul(G[k], Q[k + 1]));
    }
}
}  // namespace

void solve_block_tridiagonal2(std::size_t n, const Mat2 *A, const Mat2 *B, const Mat2 *C, Vec2 *r) {
    std::vector<Mat2> G;
    thomas(n, A, B, C, r, nullptr, G);
}

void solve_block_tridiagonal2(std::size_t n, const Mat2 *A, const Mat2 *B, const Mat2 *C, Vec2 *r,
                              std::vector<Mat2> &scratch) {
    thomas(n, A, B, C, r, nullptr, scratch);
}

void solve_cyclic_block_tridiagonal2(std::size_t n, const Mat2 *A, const Mat2 *B, const Mat2 *C, Vec2 *r) {
    // Rows 0..n-2 in u[0..n-2], with u[n-1] moved to the right: u = p + Q u[n-1],
    // where Q solves the same rows for -A[0] in row 0 and -C[n-2] in row n-2.
    const std::size_t m = n - 1;
    std::vector<Mat2> Q(m), G;
    Q[0] = sub(Q[0], A[0]);
    Q[m - 1] = sub(Q[m - 1], C[m - 1]);
    thomas(m, A, B, C, r, Q.data(), G);
    // Row n-1: A u[n-2] + B u[n-1] + C u[0] = r[n-1].
    const Mat2 S = add(B[m], add(mul(A[m], Q[m - 1]), mul(C[m], Q[0])));
    const Vec2 last = mul(inv(S), sub(r[m], add(mul(A[m], r[m - 1]), mul(C[m], r[0]))));
    r[m] = last;
    for (std::size_t k = 0; k < m; ++k) r[k] = add(r[k], mul(Q[k], last));
}

}  // namespace eg2d
