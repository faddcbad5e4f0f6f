/*
 * eg2d.hpp -- header-only C++ wrapper of eg2d.h (C++17).
 *
 *     eg2d::grid g(65, 65);                      // eg2d_create; freed by ~grid
 *     g.set_side(EG2D_SIDE_JMIN, xb, yb);        // ... the four sides (std::vector<double>)
 *     g.set_tolerance(1e-10);
 *     g.solve();                                 // throws eg2d::error on failure
 *     std::vector<double> x, y;
 *     g.get_coordinates(x, y);                   // ni*nj, Fortran order
 *
 * Every failed call throws eg2d::error, whose status() is the EG2D_ERR_* code
 * and what() the message of eg2d_last_error (or of the size check that this
 * header does before handing a vector to the library). Methods are the C
 * functions without the eg2d_ prefix; get() gives the raw handle for C calls.
 */
#ifndef EG2D_HPP
#define EG2D_HPP

#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "eg2d.h"

namespace eg2d {

class error : public std::runtime_error {
public:
    error(int status, const std::string &message) : std::runtime_error(message), status_(status) {}
    int status() const noexcept { return status_; }

private:
    int status_;
};

namespace detail {
inline void check(int status, const eg2d_grid *g) {
    if (status != EG2D_OK) throw error(status, ::eg2d_last_error(g));
}
inline std::string text(const char *s) { return s ? s : ""; }
}  // namespace detail

/* The calls that need no grid. */
inline std::string status_string(int status) { return ::eg2d_status_string(status); }
inline std::string last_error() { return ::eg2d_last_error(nullptr); }
struct version_info {
    int major, minor, patch;
};
inline version_info version() {
    version_info v{0, 0, 0};
    ::eg2d_version(&v.major, &v.minor, &v.patch);
    return v;
}
/* A solver's short name, "" if the library has no such solver. */
inline std::string solver_name(int solver) { return detail::text(::eg2d_solver_name(solver)); }
struct parameter_info {
    double lower, upper, default_value;
};
inline parameter_info parameter_bounds(int param) {
    parameter_info p{0, 0, 0};
    detail::check(::eg2d_parameter_bounds(param, &p.lower, &p.upper, &p.default_value), nullptr);
    return p;
}

/* The library's lists (EG2D_LIST_*), in id order. */
struct list_entry {
    int id;
    std::string name;
};
inline std::vector<list_entry> list_entries(int list) {
    int n = 0;
    detail::check(::eg2d_list_count(list, &n), nullptr);
    std::vector<list_entry> v;
    for (int k = 0; k < n; ++k) {
        int id = 0;
        const char *name = nullptr;
        detail::check(::eg2d_list_entry(list, k, &id, &name), nullptr);
        v.push_back({id, detail::text(name)});
    }
    return v;
}
/* "" when the list has no such id. */
inline std::string list_name(int list, int id) { return detail::text(::eg2d_list_name(list, id)); }
inline int list_find(int list, const std::string &name) {
    int id = 0;
    detail::check(::eg2d_list_find(list, name.c_str(), &id), nullptr);
    return id;
}
struct parameter_description {
    int kind;  // EG2D_VALUE_* bits
    std::string unit, summary;
};
inline parameter_description describe_parameter(int param) {
    parameter_description d{0, "", ""};
    const char *unit = nullptr, *summary = nullptr;
    detail::check(::eg2d_parameter_info(param, &d.kind, &unit, &summary), nullptr);
    d.unit = detail::text(unit);
    d.summary = detail::text(summary);
    return d;
}
struct format_description {
    int kind;  // EG2D_WRITES_*
    std::string suffix;
};
inline format_description describe_format(int format) {
    format_description d{0, ""};
    const char *suffix = nullptr;
    detail::check(::eg2d_format_info(format, &d.kind, &suffix), nullptr);
    d.suffix = detail::text(suffix);
    return d;
}
/* "" for a summary-only metric. */
inline std::string quality_cell_field(int metric) { return detail::text(::eg2d_quality_cell_field(metric)); }

/* A Plot3D grid read by read_plot3d: x, y of ni*nj nodes (Fortran order). */
struct plot3d_grid {
    int ni = 0, nj = 0, format = 0, nblocks = 0;
    std::vector<double> x, y;
};
/* Grid `block` of a Plot3D file of any variant eg2d_read_plot3d detects. */
inline plot3d_grid read_plot3d(const std::string &path, int block = 0) {
    plot3d_grid g;
    detail::check(::eg2d_read_plot3d(path.c_str(), block, &g.format, &g.nblocks, &g.ni, &g.nj, nullptr, nullptr),
                  nullptr);
    g.x.resize(static_cast<std::size_t>(g.ni) * static_cast<std::size_t>(g.nj));
    g.y.resize(g.x.size());
    detail::check(::eg2d_read_plot3d_into(path.c_str(), block, static_cast<int>(g.x.size()), nullptr, nullptr, nullptr,
                                          nullptr, g.x.data(), g.y.data()),
                  nullptr);
    return g;
}
/* The points of a point file ("x y" per line) into x, y. */
inline void read_points(const std::string &path, std::vector<double> &x, std::vector<double> &y) {
    int n = 0;
    detail::check(::eg2d_read_points(path.c_str(), 0, &n, nullptr, nullptr), nullptr);
    std::vector<double> xs(static_cast<std::size_t>(n)), ys(xs.size());
    detail::check(::eg2d_read_points(path.c_str(), n, nullptr, xs.data(), ys.data()), nullptr);
    x.swap(xs);
    y.swap(ys);
}

/* n points of an EG2D_DIST_* distribution on [0, 1]. */
inline std::vector<double> distribution(int dist, int n, double p1 = 0, double p2 = 0) {
    std::vector<double> s(n > 0 ? static_cast<std::size_t>(n) : 0u);
    detail::check(::eg2d_distribution(dist, n, p1, p2, s.data()), nullptr);
    return s;
}
/* The p1 of an EG2D_DIST_* distribution whose first spacing (a fraction of 1) is first_spacing. */
inline double distribution_parameter(int dist, int n, double first_spacing, double p2 = 0) {
    double p1 = 0;
    detail::check(::eg2d_distribution_parameter(dist, n, first_spacing, p2, &p1), nullptr);
    return p1;
}
/* The wall spacing for a target y+ at a chord Reynolds number. */
inline double first_cell_height(double yplus, double reynolds, double chord = 1) {
    double h = 0;
    detail::check(::eg2d_first_cell_height(yplus, reynolds, chord, &h), nullptr);
    return h;
}

/* Khattri's (2006) clustering map EG2D_CLUSTER_* sampled at n points. */
inline std::vector<double> clustering_map(int kind, double a, double b, double strength, int n) {
    std::vector<double> u(n > 0 ? static_cast<std::size_t>(n) : 0u);
    detail::check(::eg2d_clustering_map(kind, a, b, strength, n, u.data()), nullptr);
    return u;
}
/* s(i, j) = u[i], t(i, j) = v[j] into u.size()*v.size() arrays (Fortran order). */
inline void tensor_parameter_grid(const std::vector<double> &u, const std::vector<double> &v, std::vector<double> &s,
                                  std::vector<double> &t) {
    std::vector<double> ss(u.size() * v.size()), ts(ss.size());
    detail::check(::eg2d_tensor_parameter_grid(static_cast<int>(u.size()), static_cast<int>(v.size()), u.data(),
                                               v.data(), ss.data(), ts.data()),
                  nullptr);
    s.swap(ss);
    t.swap(ts);
}

/* A curve handle: move-only, freed by the destructor. Made by the static
 * functions; a function curve keeps its std::function alive with it. */
class curve {
public:
    using function_type = std::function<std::pair<double, double>(double t)>;

    static curve polyline(const std::vector<double> &x, const std::vector<double> &y) {
        same_size(x, y);
        return curve([&](eg2d_curve **c) { return ::eg2d_curve_polyline(size_of(x), x.data(), y.data(), c); });
    }
    static curve spline(const std::vector<double> &x, const std::vector<double> &y) {
        same_size(x, y);
        return curve([&](eg2d_curve **c) { return ::eg2d_curve_spline(size_of(x), x.data(), y.data(), c); });
    }
    /* fn(t) -> (x, y) for t in [0, 1]; an exception in fn fails the call and is rethrown. */
    static curve function(function_type fn) {
        auto state = std::make_unique<function_state>();
        state->fn = std::move(fn);
        function_state *raw = state.get();
        curve c;
        c.state_ = std::move(state);
        const int status = ::eg2d_curve_function(&curve::call, raw, &c.c_);
        if (raw->thrown) std::rethrow_exception(std::exchange(raw->thrown, nullptr));
        detail::check(status, nullptr);
        return c;
    }
    static curve naca4(const std::string &digits, int flags = 0) {
        return curve([&](eg2d_curve **c) { return ::eg2d_curve_naca4(digits.c_str(), flags, c); });
    }
    static curve read_airfoil(const std::string &path) {
        return curve([&](eg2d_curve **c) { return ::eg2d_curve_read_airfoil(path.c_str(), c); });
    }

    ~curve() { ::eg2d_curve_destroy(c_); }
    curve(const curve &) = delete;
    curve &operator=(const curve &) = delete;
    curve(curve &&o) noexcept : c_(std::exchange(o.c_, nullptr)), state_(std::move(o.state_)) {}
    curve &operator=(curve &&o) noexcept {
        if (this != &o) {
            ::eg2d_curve_destroy(c_);
            c_ = std::exchange(o.c_, nullptr);
            state_ = std::move(o.state_);
        }
        return *this;
    }
    const eg2d_curve *get() const noexcept { return c_; }

    double length() const {
        double v = 0;
        run(::eg2d_curve_length(c_, &v));
        return v;
    }
    /* The point at normalized arc length s in [0, 1]. */
    std::pair<double, double> evaluate(double s) const {
        double x = 0, y = 0;
        run(::eg2d_curve_evaluate(c_, s, &x, &y));
        return {x, y};
    }
    /* n points at the normalized arc lengths of a distribution into x, y. */
    void points(int n, int dist, double p1, double p2, std::vector<double> &x, std::vector<double> &y) const {
        std::vector<double> xs(n > 0 ? static_cast<std::size_t>(n) : 0u), ys(xs.size());
        run(::eg2d_curve_points(c_, n, dist, p1, p2, xs.data(), ys.data()));
        x.swap(xs);
        y.swap(ys);
    }

private:
    struct function_state {
        function_type fn;
        std::exception_ptr thrown;
    };
    curve() = default;
    template <class Make>
    explicit curve(Make make) {
        detail::check(make(&c_), nullptr);
    }
    static void call(void *user, double t, double *x, double *y) noexcept {
        auto *state = static_cast<function_state *>(user);
        try {
            std::tie(*x, *y) = state->fn(t);
        } catch (...) {
            state->thrown = std::current_exception();
            *x = *y = std::numeric_limits<double>::quiet_NaN();
        }
    }
    void run(int status) const {
        if (state_ && state_->thrown) std::rethrow_exception(std::exchange(state_->thrown, nullptr));
        detail::check(status, nullptr);
    }
    static void same_size(const std::vector<double> &x, const std::vector<double> &y) {
        if (x.size() != y.size())
            throw error(EG2D_ERR_ARGUMENT, "curve: x has " + std::to_string(x.size()) + " points, y " +
                                               std::to_string(y.size()));
    }
    static int size_of(const std::vector<double> &x) { return static_cast<int>(x.size()); }

    eg2d_curve *c_ = nullptr;
    std::unique_ptr<function_state> state_;
};

/* One grid handle: move-only, freed by the destructor. */
class grid {
public:
    /* Called after every iteration; returning true stops the run. */
    using monitor = std::function<bool(int iteration, double residual)>;

    grid(int ni, int nj) {
        eg2d_grid *g = nullptr;
        const int status = ::eg2d_create(ni, nj, &g);
        if (status != EG2D_OK) throw error(status, ::eg2d_last_error(nullptr));
        g_ = g;
    }
    ~grid() { ::eg2d_destroy(g_); }
    grid(const grid &) = delete;
    grid &operator=(const grid &) = delete;
    grid(grid &&other) noexcept : g_(std::exchange(other.g_, nullptr)), monitor_(std::move(other.monitor_)) {}
    grid &operator=(grid &&other) noexcept {
        if (this != &other) {
            ::eg2d_destroy(g_);
            g_ = std::exchange(other.g_, nullptr);
            monitor_ = std::move(other.monitor_);
        }
        return *this;
    }

    eg2d_grid *get() const noexcept { return g_; }
    std::string last_error() const { return ::eg2d_last_error(g_); }

    void set_topology(int topology) { check(::eg2d_set_topology(g_, topology)); }
    int get_topology() const {
        int t = 0;
        check(::eg2d_get_topology(g_, &t));
        return t;
    }
    /* C-grid: the trailing edge's index on JMIN (eg2d_get_cut). */
    int get_cut() const {
        int w = 0;
        check(::eg2d_get_cut(g_, &w));
        return w;
    }

    /* One side: ni points for JMIN/JMAX, nj for IMIN/IMAX. */
    void set_side(int side, const std::vector<double> &x, const std::vector<double> &y) {
        const auto n = side_points(side);
        if (n && (x.size() != n || y.size() != n))
            throw error(EG2D_ERR_ARGUMENT, "set_side: side " + std::to_string(side) + ": x has " +
                                               std::to_string(x.size()) + " and y " + std::to_string(y.size()) +
                                               " points; the side has " + std::to_string(n));
        check(::eg2d_set_side(g_, side, x.data(), y.data()));
    }
    /* An interior line: the column i = index (EG2D_XI, nj points) or the row
     * j = index (EG2D_ETA, ni points), held by TFI and every solver. */
    void set_interior_line(int direction, int index, const std::vector<double> &x, const std::vector<double> &y) {
        const std::size_t n = direction == EG2D_XI ? side_points(EG2D_SIDE_IMIN)
                              : direction == EG2D_ETA ? side_points(EG2D_SIDE_JMIN) : 0;
        if (n && (x.size() != n || y.size() != n))
            throw error(EG2D_ERR_ARGUMENT, "set_interior_line: x has " + std::to_string(x.size()) + " and y " +
                                               std::to_string(y.size()) + " points; the line has " + std::to_string(n));
        check(::eg2d_set_interior_line(g_, direction, index, x.data(), y.data()));
    }
    void clear_interior_lines() { check(::eg2d_clear_interior_lines(g_)); }
    /* Whole ni*nj arrays (Fortran order); only the boundary is read. */
    void set_boundary(const std::vector<double> &x, const std::vector<double> &y) {
        check_nodes("set_boundary", x, y);
        check(::eg2d_set_boundary(g_, x.data(), y.data()));
    }
    void initialize(int method = EG2D_INIT_TFI) { check(::eg2d_initialize(g_, method)); }
    void set_coordinates(const std::vector<double> &x, const std::vector<double> &y) {
        check_nodes("set_coordinates", x, y);
        check(::eg2d_set_coordinates(g_, x.data(), y.data()));
    }

    void set_system(int system) { check(::eg2d_set_system(g_, system)); }
    void set_solver(int solver) { check(::eg2d_set_solver(g_, solver)); }
    int get_solver() const {
        int s = 0;
        check(::eg2d_get_solver(g_, &s));
        return s;
    }
    void set_relaxation(double omega) { check(::eg2d_set_relaxation(g_, omega)); }
    void set_tolerance(double tolerance) { check(::eg2d_set_tolerance(g_, tolerance)); }
    void set_max_iterations(int max_iterations) { check(::eg2d_set_max_iterations(g_, max_iterations)); }
    void set_parameter(int param, double value) { check(::eg2d_set_parameter(g_, param, value)); }
    double get_parameter(int param) const {
        double v = 0;
        check(::eg2d_get_parameter(g_, param, &v));
        return v;
    }

    void set_af_cycle(double dtau_min, double dtau_max, int steps) {
        check(::eg2d_set_af_cycle(g_, dtau_min, dtau_max, steps));
    }
    void set_af_time_rule(double a, double b) { check(::eg2d_set_af_time_rule(g_, a, b)); }

    /* Grid control (see eg2d.h). Arrays are ni*nj; an empty vector is NULL. */
    void add_line_source(int direction, double line, double amplitude, double decay) {
        check(::eg2d_add_line_source(g_, direction, line, amplitude, decay));
    }
    void add_point_source(double xi, double eta, double amplitude, double decay) {
        check(::eg2d_add_point_source(g_, xi, eta, amplitude, decay));
    }
    void clear_sources() { check(::eg2d_clear_sources(g_)); }
    void set_source_arrays(const std::vector<double> &P, const std::vector<double> &Q) {
        check(::eg2d_set_source_arrays(g_, optional_nodes("set_source_arrays", P), optional_nodes("set_source_arrays", Q)));
    }
    void set_orthogonality(int method) { check(::eg2d_set_orthogonality(g_, method)); }
    void set_wall_spacing(int side, double height) { check(::eg2d_set_wall_spacing(g_, side, height)); }
    // One first-cell height per node of the side; empty: the side is no wall.
    void set_wall_spacing_nodes(int side, const std::vector<double> &heights) {
        check(::eg2d_set_wall_spacing_nodes(g_, side, static_cast<int>(heights.size()),
                                            heights.empty() ? nullptr : heights.data()));
    }
    void set_parameter_grid(const std::vector<double> &s, const std::vector<double> &t) {
        check(::eg2d_set_parameter_grid(g_, optional_nodes("set_parameter_grid", s),
                                        optional_nodes("set_parameter_grid", t)));
    }
    void set_weight(const std::vector<double> &w) { check(::eg2d_set_weight(g_, optional_nodes("set_weight", w))); }

    /* An exception thrown by fn stops the run and is rethrown by iterate/solve.
     * An empty fn removes the monitor. */
    void set_monitor(monitor fn) {
        if (!fn) {
            check(::eg2d_set_monitor(g_, nullptr, nullptr));
            monitor_.reset();
            return;
        }
        auto state = std::make_unique<monitor_state>();
        state->fn = std::move(fn);
        check(::eg2d_set_monitor(g_, &grid::call_monitor, state.get()));
        monitor_ = std::move(state);
    }
    /* Exactly `iterations` iterations; the residual after them. */
    double iterate(int iterations) {
        double r = 0;
        run(::eg2d_iterate(g_, iterations, &r));
        return r;
    }
    void solve() { run(::eg2d_solve(g_)); }

    std::pair<int, int> get_size() const {
        int ni = 0, nj = 0;
        check(::eg2d_get_size(g_, &ni, &nj));
        return {ni, nj};
    }
    /* x, y resized to ni*nj, node (i, j) at i + ni*j. */
    void get_coordinates(std::vector<double> &x, std::vector<double> &y) const {
        node_arrays(x, y, [this](double *a, double *b) { return ::eg2d_get_coordinates(g_, a, b); });
    }
    double get_residual() const {
        double r = 0;
        check(::eg2d_get_residual(g_, &r));
        return r;
    }
    int get_iterations() const {
        int n = 0;
        check(::eg2d_get_iterations(g_, &n));
        return n;
    }
    // What the last iterate/solve ran (EG2D_RUN_*), and its changes of strategy.
    int get_run_info(int what) const {
        int v = 0;
        check(::eg2d_get_run_info(g_, what, &v));
        return v;
    }
    std::vector<std::pair<int, std::string>> get_run_events() const {
        std::vector<std::pair<int, std::string>> out;
        char buf[512];
        for (int k = 0, n = get_run_info(EG2D_RUN_EVENTS); k < n; ++k) {
            int it = 0;
            check(::eg2d_get_run_event(g_, k, &it, buf, static_cast<int>(sizeof buf)));
            out.emplace_back(it, buf);
        }
        return out;
    }
    // Boundary patches (EG2D_PATCH_*): set a stretch, back to the defaults,
    // and the whole boundary as the writers see it.
    struct patch {
        int side, first, last, type;
        std::string name;
    };
    void set_patch(int side, int first, int last, int type, const std::string &name) {
        check(::eg2d_set_patch(g_, side, first, last, type, name.c_str()));
    }
    void clear_patches() { check(::eg2d_clear_patches(g_)); }
    std::vector<patch> get_patches() const {
        int n = 0;
        check(::eg2d_get_patch_count(g_, &n));
        std::vector<patch> out;
        char buf[64];
        for (int k = 0; k < n; ++k) {
            patch p{0, 0, 0, 0, ""};
            check(::eg2d_get_patch(g_, k, &p.side, &p.first, &p.last, &p.type, buf, static_cast<int>(sizeof buf)));
            p.name = buf;
            out.push_back(p);
        }
        return out;
    }
    double get_quality(int metric) const {
        double v = 0;
        check(::eg2d_get_quality(g_, metric, &v));
        return v;
    }
    /* A figure of the wall layer at a side (EG2D_WALL_*). */
    double get_wall_layer(int side, int what) const {
        double v = 0;
        check(::eg2d_get_wall_layer(g_, side, what, &v));
        return v;
    }

    /* Per-cell values, (ni-1)*(nj-1), cell (i, j) at i + (ni-1)*j. */
    std::vector<double> get_cell_quality(int metric) const {
        const auto [ni, nj] = get_size();
        std::vector<double> v(static_cast<std::size_t>(ni - 1) * static_cast<std::size_t>(nj - 1));
        check(::eg2d_get_cell_quality(g_, metric, v.data()));
        return v;
    }

    /* The control terms as Thompson's P, Q per node (ni*nj each, Fortran order). */
    void get_controls(std::vector<double> &P, std::vector<double> &Q) const {
        node_arrays(P, Q, [this](double *a, double *b) { return ::eg2d_get_controls(g_, a, b); });
    }

    void set_side_curve(int side, const curve &c, int dist = EG2D_DIST_UNIFORM, double p1 = 0, double p2 = 0,
                        int flags = 0) {
        check(::eg2d_set_side_curve(g_, side, c.get(), dist, p1, p2, flags));
    }

    void set_airfoil(const curve &section, int topology = EG2D_TOPO_C) {
        check(::eg2d_set_airfoil(g_, section.get(), topology));
    }

    void write(const std::string &path, int format) const { check(::eg2d_write(g_, path.c_str(), format)); }
    void set_side_from_file(int side, const std::string &path) {
        check(::eg2d_set_side_from_file(g_, side, path.c_str()));
    }

private:
    struct monitor_state {
        monitor fn;
        std::exception_ptr thrown;
    };
    static int call_monitor(void *user, int iteration, double residual) noexcept {
        auto *state = static_cast<monitor_state *>(user);
        try {
            return state->fn(iteration, residual) ? 1 : 0;
        } catch (...) {
            state->thrown = std::current_exception();
            return 1;
        }
    }
    void run(int status) {
        if (monitor_ && monitor_->thrown) std::rethrow_exception(std::exchange(monitor_->thrown, nullptr));
        check(status);
    }
    void check(int status) const { detail::check(status, g_); }
    /* Two per-node arrays (ni*nj each) from one query; a and b keep their contents on failure. */
    template <class Query>
    void node_arrays(std::vector<double> &a, std::vector<double> &b, Query query) const {
        const auto [ni, nj] = get_size();
        std::vector<double> u(static_cast<std::size_t>(ni) * static_cast<std::size_t>(nj)), v(u.size());
        check(query(u.data(), v.data()));
        a.swap(u);
        b.swap(v);
    }
    std::size_t side_points(int side) const {
        const auto [ni, nj] = get_size();
        if (side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX) return static_cast<std::size_t>(ni);
        if (side == EG2D_SIDE_IMIN || side == EG2D_SIDE_IMAX) return static_cast<std::size_t>(nj);
        return 0; /* unknown side: the library reports it */
    }
    /* NULL for an empty vector, else its data after the ni*nj size check. */
    const double *optional_nodes(const char *what, const std::vector<double> &a) const {
        if (a.empty()) return nullptr;
        check_nodes(what, a, a);
        return a.data();
    }
    void check_nodes(const char *what, const std::vector<double> &x, const std::vector<double> &y) const {
        const auto [ni, nj] = get_size();
        const auto n = static_cast<std::size_t>(ni) * static_cast<std::size_t>(nj);
        if (x.size() != n || y.size() != n)
            throw error(EG2D_ERR_ARGUMENT, std::string(what) + ": x has " + std::to_string(x.size()) + " and y " +
                                               std::to_string(y.size()) + " values; ni*nj = " + std::to_string(n));
    }

    eg2d_grid *g_ = nullptr;
    std::unique_ptr<monitor_state> monitor_;
};

/* A set of blocks (eg2d.h, "Sets of blocks"): it refers to the grids added
 * (it owns none): keep them alive while the set is used. */
class blocks {
public:
    blocks() {
        eg2d_blocks *s = nullptr;
        const int status = ::eg2d_blocks_create(&s);
        if (status != EG2D_OK) throw error(status, ::eg2d_last_error(nullptr));
        s_ = s;
    }
    ~blocks() { ::eg2d_blocks_destroy(s_); }
    blocks(const blocks &) = delete;
    blocks &operator=(const blocks &) = delete;
    blocks(blocks &&other) noexcept : s_(std::exchange(other.s_, nullptr)) {}
    blocks &operator=(blocks &&other) noexcept {
        if (this != &other) {
            ::eg2d_blocks_destroy(s_);
            s_ = std::exchange(other.s_, nullptr);
        }
        return *this;
    }

    eg2d_blocks *get() const noexcept { return s_; }
    std::string last_error() const { return ::eg2d_blocks_last_error(s_); }

    /* The block's index. */
    int add(grid &g) {
        int b = -1;
        check(::eg2d_blocks_add(s_, g.get(), &b));
        return b;
    }
    /* The block's name in the files that hold a zone a block ("block0", ... until named). */
    void set_name(int block, const std::string &name) { check(::eg2d_blocks_set_name(s_, block, name.c_str())); }
    std::string name(int block) const {
        const char *n = ::eg2d_blocks_name(s_, block);
        if (!n) throw error(EG2D_ERR_ARGUMENT, "eg2d_blocks_name: the set has no block " + std::to_string(block));
        return n;
    }
    void join(int block_a, int side_a, int first_a, int last_a, int block_b, int side_b, int first_b, int last_b) {
        check(::eg2d_blocks_join(s_, block_a, side_a, first_a, last_a, block_b, side_b, first_b, last_b));
    }
    // Join `join` (0 for the first) held where the blocks' sides put it, or free again.
    void hold_join(int join, bool held = true) { check(::eg2d_blocks_hold_join(s_, join, held ? 1 : 0)); }
    void check_set() const { check(::eg2d_blocks_check(s_)); }
    void solve() { check(::eg2d_blocks_solve(s_)); }
    struct run_info {
        int iterations;
        double residual;
        int unknowns;
    };
    run_info get_run() const {
        run_info r{0, 0.0, 0};
        check(::eg2d_blocks_get_run(s_, &r.iterations, &r.residual, &r.unknowns));
        return r;
    }
    /* The largest turn of a grid line at the joins, and one node into each block (degrees). */
    std::pair<double, double> get_kinks() const {
        double at = 0.0, near = 0.0;
        check(::eg2d_blocks_get_kinks(s_, &at, &near));
        return {at, near};
    }
    void write(const std::string &path, int format) const { check(::eg2d_blocks_write(s_, path.c_str(), format)); }

private:
    void check(int status) const {
        if (status != EG2D_OK) throw error(status, ::eg2d_blocks_last_error(s_));
    }
    eg2d_blocks *s_ = nullptr;
};

}  // namespace eg2d
#endif /* EG2D_HPP */
