// include/eg2d.hpp: RAII, exceptions carrying the status and the message,
// size checks, the monitor (and exceptions thrown by it), and the swan grid
// equal to the one the C library writes (argv[1], from swan_write_c).
#include "eg2d.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

static int failures = 0, passes = 0;
#define CHECK(cond)                                                           \
    do {                                                                      \
        if (cond) ++passes;                                                   \
        else {                                                                \
            ++failures;                                                       \
            std::printf("FAIL line %d: %s\n", __LINE__, #cond);               \
        }                                                                     \
    } while (0)

// Runs f, which must throw eg2d::error with this status and message part.
template <class F>
static bool throws(F f, int status, const std::string &part) {
    try {
        f();
    } catch (const eg2d::error &e) {
        const bool ok = e.status() == status && std::string(e.what()).find(part) != std::string::npos;
        if (!ok) std::printf("  got status %d, message \"%s\"\n", e.status(), e.what());
        return ok;
    }
    std::printf("  no exception\n");
    return false;
}

static void set_swan(eg2d::grid &g, int ni, int nj) {
    std::vector<double> x(ni), y(ni), u(nj), v(nj);
    for (int i = 0; i < ni; ++i) {
        const double s = (double)i / (ni - 1);
        x[i] = s;
        y[i] = 0;
    }
    g.set_side(EG2D_SIDE_JMIN, x, y);
    for (int i = 0; i < ni; ++i) y[i] = 1 - 2 * x[i] + 2 * x[i] * x[i];
    g.set_side(EG2D_SIDE_JMAX, x, y);
    for (int j = 0; j < nj; ++j) {
        const double s = (double)j / (nj - 1);
        u[j] = 1 + 2 * s - 2 * s * s;
        v[j] = s;
    }
    g.set_side(EG2D_SIDE_IMAX, u, v);
    for (int j = 0; j < nj; ++j) u[j] = 0;
    g.set_side(EG2D_SIDE_IMIN, u, v);
}

int main(int argc, char **argv) {
    // grid-less calls
    CHECK(eg2d::version().major == EG2D_VERSION_MAJOR);
    CHECK(eg2d::status_string(EG2D_ERR_STATE).rfind("EG2D_ERR_STATE:", 0) == 0);
    CHECK(eg2d::solver_name(EG2D_SOLVER_PSOR) == "psor" && eg2d::solver_name(99).empty());
    CHECK(eg2d::parameter_bounds(EG2D_PARAM_TOLERANCE).default_value == 1e-8);
    CHECK(throws([] { eg2d::parameter_bounds(999); }, EG2D_ERR_ARGUMENT, "parameter 999"));
    CHECK(eg2d::last_error().find("parameter 999") != std::string::npos);

    // creation and size checks
    CHECK(throws([] { eg2d::grid g(2, 9); }, EG2D_ERR_ARGUMENT, "eg2d_create"));
    eg2d::grid g(17, 13);
    CHECK(g.get_size() == std::make_pair(17, 13));
    CHECK(throws([&] { g.set_side(EG2D_SIDE_JMIN, std::vector<double>(10), std::vector<double>(10)); },
                 EG2D_ERR_ARGUMENT, "x has 10 and y 10 points; the side has 17"));
    CHECK(throws([&] { g.set_side(9, std::vector<double>(17), std::vector<double>(17)); }, EG2D_ERR_ARGUMENT,
                 "eg2d_set_side"));
    CHECK(throws([&] { g.initialize(); }, EG2D_ERR_STATE, "eg2d_initialize"));
    CHECK(throws([&] { g.set_topology(7); }, EG2D_ERR_ARGUMENT, "topology = 7"));
    CHECK(g.get_topology() == EG2D_TOPO_SINGLE);
    set_swan(g, 17, 13);
    CHECK(throws([&] { g.set_side(EG2D_SIDE_JMIN, std::vector<double>(17, 5.0), std::vector<double>(17, 5.0)); },
                 EG2D_ERR_BOUNDARY, "eg2d_set_side"));
    CHECK(throws([&] { g.initialize(5); }, EG2D_ERR_ARGUMENT, "eg2d_initialize"));
    std::vector<double> x, y;
    CHECK(throws([&] { g.get_coordinates(x, y); }, EG2D_ERR_STATE, "eg2d_get_coordinates"));
    g.initialize();
    g.get_coordinates(x, y);
    CHECK(x.size() == 17u * 13u && x[16] == 1.0 && y[16] == 0.0 && y[17 * 12] == 1.0);
    CHECK(throws([&] { g.set_coordinates(std::vector<double>(5), y); }, EG2D_ERR_ARGUMENT,
                 "set_coordinates: x has 5 and y 221 values; ni*nj = 221"));
    CHECK(throws([&] { g.set_boundary(x, std::vector<double>(5)); }, EG2D_ERR_ARGUMENT, "set_boundary"));
    g.set_coordinates(x, y);
    g.set_boundary(x, y);

    // settings
    CHECK(throws([&] { g.set_system(9); }, EG2D_ERR_ARGUMENT, "eg2d_set_system"));
    g.set_system(EG2D_SYSTEM_WINSLOW);
    CHECK(throws([&] { g.set_solver(-1); }, EG2D_ERR_ARGUMENT, "no such solver"));
    g.set_solver(EG2D_SOLVER_PSOR);
    CHECK(g.get_solver() == EG2D_SOLVER_PSOR);
    CHECK(throws([&] { g.set_relaxation(2.5); }, EG2D_ERR_ARGUMENT, "eg2d_set_relaxation"));
    g.set_relaxation(0);
    CHECK(throws([&] { g.set_tolerance(0); }, EG2D_ERR_ARGUMENT, "tolerance = 0"));
    g.set_tolerance(1e-11);
    CHECK(throws([&] { g.set_max_iterations(0); }, EG2D_ERR_ARGUMENT, "eg2d_set_max_iterations"));
    g.set_max_iterations(5000);
    CHECK(throws([&] { g.set_parameter(999, 1); }, EG2D_ERR_ARGUMENT, "eg2d_set_parameter"));
    CHECK(throws([&] { g.get_parameter(999); }, EG2D_ERR_ARGUMENT, "eg2d_get_parameter"));
    CHECK(g.get_parameter(EG2D_PARAM_MAX_ITERATIONS) == 5000);

    // running: the monitor stops the run; its exception is rethrown
    int calls = 0;
    g.set_monitor([&](int it, double) { ++calls; return it >= 3; });
    CHECK(throws([&] { g.solve(); }, EG2D_ERR_INTERRUPTED, "monitor"));
    CHECK(calls == 3 && g.get_iterations() == 3);
    g.set_monitor([](int, double) -> bool { throw std::runtime_error("from the monitor"); });
    bool rethrown = false;
    try {
        g.iterate(5);
    } catch (const std::runtime_error &e) {
        rethrown = std::string(e.what()) == "from the monitor";
    }
    CHECK(rethrown && g.get_iterations() == 4);
    g.set_monitor(nullptr);
    CHECK(throws([&] { g.iterate(-1); }, EG2D_ERR_ARGUMENT, "eg2d_iterate"));
    const double r = g.iterate(2);
    CHECK(r == g.get_residual() && g.get_iterations() == 6);
    g.solve();
    CHECK(g.get_residual() <= 1e-11);
    CHECK(g.get_quality(EG2D_QUALITY_FOLDED_CELLS) == 0 && g.get_quality(EG2D_QUALITY_MIN_AREA) > 0);
    CHECK(throws([&] { g.get_quality(99); }, EG2D_ERR_ARGUMENT, "eg2d_get_quality"));
    // what ran
    CHECK(g.get_run_info(EG2D_RUN_SOLVER) == EG2D_SOLVER_PSOR && g.get_run_info(EG2D_RUN_LEVELS) == 1);
    CHECK(g.get_run_events().empty());
    CHECK(throws([&] { g.get_run_info(99); }, EG2D_ERR_ARGUMENT, "not an EG2D_RUN_* id"));
    {
        eg2d::grid tiny(4, 4);  // too small for a coarse level: multigrid says so
        set_swan(tiny, 4, 4);
        tiny.solve();
        const auto events = tiny.get_run_events();
        CHECK(events.size() == 1 && events[0].first == 1 &&
              events[0].second.rfind("multigrid: the 4x4 grid has no coarse level", 0) == 0);
    }

    // AF settings, per-cell quality, files
    CHECK(throws([&] { g.set_af_cycle(2, 1, 0); }, EG2D_ERR_ARGUMENT, "eg2d_set_af_cycle"));
    g.set_af_cycle(0.5, 0, 0);
    CHECK(throws([&] { g.set_af_time_rule(0, 0); }, EG2D_ERR_ARGUMENT, "eg2d_set_af_time_rule"));
    g.set_af_time_rule(0, 0.5);
    CHECK(g.get_parameter(EG2D_PARAM_AF_B) == 0.5);
    const std::vector<double> areas = g.get_cell_quality(EG2D_QUALITY_MIN_AREA);
    double total = 0;
    for (double a : areas) total += a;
    CHECK(areas.size() == 16u * 12u && std::fabs(total - 1) < 1e-2);  // the swan's area is 1
    CHECK(throws([&] { g.get_cell_quality(EG2D_QUALITY_ORTHO_MAX_JMIN); }, EG2D_ERR_ARGUMENT, "per-cell"));
    g.get_coordinates(x, y);
    g.write("cxx_header.x", EG2D_FORMAT_PLOT3D_ASCII);
    const eg2d::plot3d_grid back = eg2d::read_plot3d("cxx_header.x");
    CHECK(back.ni == 17 && back.nj == 13 && back.nblocks == 1 && back.format == EG2D_FORMAT_PLOT3D_ASCII);
    double worst = 0;
    for (std::size_t k = 0; k < x.size(); ++k) worst = std::fmax(worst, std::fabs(back.x[k] - x[k]) + std::fabs(back.y[k] - y[k]));
    CHECK(worst == 0);  // 17 significant digits round-trip exactly
    CHECK(throws([&] { g.write("no-such-dir/g.x", EG2D_FORMAT_PLOT3D); }, EG2D_ERR_IO, "no-such-dir/g.x"));
    CHECK(throws([] { eg2d::read_plot3d("no-such-file.x"); }, EG2D_ERR_IO, "no-such-file.x"));
    {
        std::ofstream pts("cxx_header_jmin.txt");
        pts.precision(17);
        for (int i = 0; i < 17; ++i) pts << i / 16.0 << " 0\n";
    }
    std::vector<double> px, py;
    eg2d::read_points("cxx_header_jmin.txt", px, py);
    CHECK(px.size() == 17u && px[16] == 1.0 && py[3] == 0.0);
    CHECK(throws([&] { eg2d::read_points("no-such-file.txt", px, py); }, EG2D_ERR_IO, "no-such-file.txt"));
    g.set_side_from_file(EG2D_SIDE_JMIN, "cxx_header_jmin.txt");
    CHECK(throws([&] { g.set_side_from_file(EG2D_SIDE_IMIN, "cxx_header_jmin.txt"); }, EG2D_ERR_BOUNDARY,
                 "holds 17 points"));
    g.solve();

    // RAII: moves transfer the handle; a moved-from grid reports a NULL handle
    eg2d::grid h = std::move(g);
    CHECK(h.get() != nullptr && g.get() == nullptr);
    CHECK(throws([&] { g.solve(); }, EG2D_ERR_ARGUMENT, "grid is NULL"));
    h.get_coordinates(x, y);
    CHECK(std::fabs(x[16 + 17 * 12] - 1.0) < 1e-15);

    // curves, distributions, y+
    {
        const auto c = eg2d::curve::polyline({0, 1, 1}, {0, 0, 1});
        CHECK(std::fabs(c.length() - 2) < 1e-14);
        const auto p = c.evaluate(0.75);
        CHECK(std::fabs(p.first - 1) < 1e-12 && std::fabs(p.second - 0.5) < 1e-12);
        CHECK(throws([&] { c.evaluate(1.5); }, EG2D_ERR_ARGUMENT, "s = 1.5"));
        std::vector<double> cx, cy;
        c.points(5, EG2D_DIST_UNIFORM, 0, 0, cx, cy);
        CHECK(cx.size() == 5u && std::fabs(cx[1] - 0.5) < 1e-12 && std::fabs(cy[3] - 0.5) < 1e-12);
        CHECK(throws([] { eg2d::curve::polyline({0}, {0}); }, EG2D_ERR_ARGUMENT, "eg2d_curve_polyline"));
        CHECK(throws([] { eg2d::curve::spline({0, 1}, {0}); }, EG2D_ERR_ARGUMENT, "x has 2 points, y 1"));
        const double pi = std::acos(-1.0);
        const auto arc = eg2d::curve::function(
            [pi](double t) { return std::make_pair(3 * std::cos(pi * t / 2), 3 * std::sin(pi * t / 2)); });
        CHECK(std::fabs(arc.length() - 1.5 * pi) < 1e-10);
        bool rethrown = false;
        try {
            eg2d::curve::function([](double) -> std::pair<double, double> { throw std::logic_error("from the curve"); });
        } catch (const std::logic_error &e) {
            rethrown = std::string(e.what()) == "from the curve";
        }
        CHECK(rethrown);
        const auto naca = eg2d::curve::naca4("0012", EG2D_NACA_CLOSED_TE);
        CHECK(std::fabs(naca.evaluate(0).first - 1) < 1e-12);
        CHECK(throws([] { eg2d::curve::naca4("12"); }, EG2D_ERR_ARGUMENT, "eg2d_curve_naca4"));
        CHECK(throws([] { eg2d::curve::read_airfoil("no-such-airfoil.dat"); }, EG2D_ERR_IO, "no-such-airfoil.dat"));
        const std::vector<double> s = eg2d::distribution(EG2D_DIST_UNIFORM, 5);
        CHECK(s.size() == 5u && s[2] == 0.5);
        CHECK(throws([] { eg2d::distribution(EG2D_DIST_EXPONENTIAL, 5, 0); }, EG2D_ERR_ARGUMENT, "eg2d_distribution"));
        const double cf = std::pow(2 * std::log10(1e6) - 0.65, -2.3);
        CHECK(std::fabs(eg2d::first_cell_height(1, 1e6) - 1 / (1e6 * std::sqrt(cf / 2))) < 1e-18);
        CHECK(throws([] { eg2d::first_cell_height(-1, 1e6); }, EG2D_ERR_ARGUMENT, "eg2d_first_cell_height"));
        eg2d::grid q(17, 13);
        const auto bottom = eg2d::curve::polyline({0, 1}, {0, 0});
        q.set_side_curve(EG2D_SIDE_JMIN, bottom);
        CHECK(throws([&] { q.set_side_curve(9, bottom); }, EG2D_ERR_ARGUMENT, "eg2d_set_side_curve"));
    }

    // grid control, on the swan (17 x 13)
    {
        eg2d::grid c(17, 13);
        set_swan(c, 17, 13);
        c.set_tolerance(1e-12);
        c.solve();
        std::vector<double> x0, y0;
        c.get_coordinates(x0, y0);
        CHECK(throws([&] { c.add_line_source(5, 0, 1, 0.5); }, EG2D_ERR_ARGUMENT, "eg2d_add_line_source"));
        c.add_line_source(EG2D_ETA, 0, 20, 0.5);
        c.solve();
        c.get_coordinates(x, y);
        CHECK(y[8 + 17] < y0[8 + 17] - 1e-3);  // eta-lines pulled toward eta = 0
        CHECK(throws([&] { c.add_point_source(4, 4, 1, -1); }, EG2D_ERR_ARGUMENT, "eg2d_add_point_source"));
        c.add_point_source(4, 4, 1, 0.5);
        c.clear_sources();
        CHECK(throws([&] { c.set_source_arrays({}, std::vector<double>(5)); }, EG2D_ERR_ARGUMENT,
                     "set_source_arrays: x has 5"));
        c.set_source_arrays({}, std::vector<double>(17 * 13, 0.5));
        c.set_source_arrays({}, {});
        CHECK(throws([&] { c.set_orthogonality(7); }, EG2D_ERR_ARGUMENT, "eg2d_set_orthogonality"));
        CHECK(throws([&] { c.set_wall_spacing(9, 0.1); }, EG2D_ERR_ARGUMENT, "eg2d_set_wall_spacing"));
        CHECK(throws([&] { c.set_wall_spacing_nodes(EG2D_SIDE_JMIN, std::vector<double>(5, 0.02)); },
                     EG2D_ERR_ARGUMENT, "eg2d_set_wall_spacing_nodes: n = 5: side JMIN has 17 nodes"));
        c.set_wall_spacing_nodes(EG2D_SIDE_JMIN, std::vector<double>(17, 0.03));
        c.set_wall_spacing(EG2D_SIDE_JMIN, 0.02);  // one height again
        c.set_orthogonality(EG2D_ORTHO_WALL);
        c.set_max_iterations(20000);
        c.solve();
        c.get_coordinates(x, y);
        CHECK(std::fabs(y[8 + 17] - 0.02) < 1e-6);  // the first cell height at the wall
        c.set_orthogonality(EG2D_ORTHO_NONE);
        CHECK(throws([] { eg2d::clustering_map(EG2D_CLUSTER_LINE, 1.5, 0, 0, 9); }, EG2D_ERR_ARGUMENT,
                     "eg2d_clustering_map"));
        const std::vector<double> u = eg2d::clustering_map(EG2D_CLUSTER_BOUNDARIES, 0.5, 0, 0, 17);
        const std::vector<double> v = eg2d::clustering_map(EG2D_CLUSTER_BOUNDARIES, 0.5, 0, 0, 13);
        CHECK(u.front() == 0 && u.back() == 1 && u[1] < 1.0 / 16);
        std::vector<double> s, t;
        eg2d::tensor_parameter_grid(u, v, s, t);
        CHECK(s.size() == 17u * 13u && s[3 + 17 * 5] == u[3] && t[3 + 17 * 5] == v[5]);
        c.set_parameter_grid(s, t);
        CHECK(throws([&] { c.set_parameter_grid(s, std::vector<double>(3)); }, EG2D_ERR_ARGUMENT, "set_parameter_grid"));
        c.set_parameter_grid({}, {});
        c.set_weight(std::vector<double>(17 * 13, 1.0));
        CHECK(throws([&] { c.set_weight(std::vector<double>(17 * 13, 0.0)); }, EG2D_ERR_ARGUMENT, "eg2d_set_weight"));
        c.set_weight({});
    }

    // boundary patches
    {
        eg2d::grid p(9, 7);
        CHECK(p.get_patches().size() == 4 && p.get_patches()[2].name == "jmax");
        p.set_patch(EG2D_SIDE_IMIN, 0, 6, EG2D_PATCH_INFLOW, "inlet");
        const auto all = p.get_patches();
        CHECK(all.back().side == EG2D_SIDE_IMIN && all.back().type == EG2D_PATCH_INFLOW && all.back().name == "inlet");
        CHECK(throws([&] { p.set_patch(EG2D_SIDE_IMIN, 2, 4, EG2D_PATCH_WALL, "x"); }, EG2D_ERR_ARGUMENT, "eg2d_set_patch"));
        p.clear_patches();
        CHECK(p.get_patches().back().name == "imin");
    }

    // a set of blocks: the unit square with a bulging top as one block and as
    // two blocks joined down its middle give the same grid
    {
        const int ni = 17, nj = 9, mid = 8;
        auto square = [&](int i0, int i1) {
            const int n = i1 - i0 + 1;
            eg2d::grid g(n, nj);
            std::vector<double> sx(n), sy(n), tx(nj), ty(nj);
            auto top = [](double u) { return 1 + u * (1 - u) / 4; };
            for (int side = 0; side < 4; ++side) {
                const bool along = side == EG2D_SIDE_JMIN || side == EG2D_SIDE_JMAX;
                std::vector<double> &px = along ? sx : tx, &py = along ? sy : ty;
                for (std::size_t k = 0; k < px.size(); ++k) {
                    const double u = along ? double(i0 + int(k)) / (ni - 1) : (side == EG2D_SIDE_IMAX ? double(i1) / (ni - 1) : double(i0) / (ni - 1));
                    const double v = along ? (side == EG2D_SIDE_JMAX ? 1.0 : 0.0) : double(k) / (nj - 1);
                    px[k] = u;
                    py[k] = v * top(u);
                }
                g.set_side(side, px, py);
            }
            return g;
        };
        eg2d::grid one = square(0, ni - 1), left = square(0, mid), right = square(mid, ni - 1);
        one.set_tolerance(1e-13);
        one.solve();
        std::vector<double> xo, yo, xl, yl, xr, yr;
        one.get_coordinates(xo, yo);
        eg2d::blocks set;
        CHECK(set.add(left) == 0 && set.add(right) == 1);
        CHECK(throws([&] { set.join(0, EG2D_SIDE_IMAX, 0, 1, 1, EG2D_SIDE_IMIN, 0, 2); }, EG2D_ERR_ARGUMENT,
                     "block 0 side IMAX nodes 0..1 has 2 nodes, block 1 side IMIN nodes 0..2 has 3"));
        set.join(0, EG2D_SIDE_IMAX, 0, nj - 1, 1, EG2D_SIDE_IMIN, 0, nj - 1);
        set.check_set();
        left.set_tolerance(1e-13);
        set.solve();
        const auto run = set.get_run();
        CHECK(run.unknowns == (ni - 2) * (nj - 2) && run.residual <= 1e-13);
        CHECK(set.get_kinks().first > 0);
        left.get_coordinates(xl, yl);
        right.get_coordinates(xr, yr);
        double diff = 0;
        for (int j = 0; j < nj; ++j)
            for (int i = 0; i < ni; ++i) {
                const double xs = i <= mid ? xl[i + (mid + 1) * j] : xr[i - mid + (ni - mid) * j];
                const double ys = i <= mid ? yl[i + (mid + 1) * j] : yr[i - mid + (ni - mid) * j];
                diff = std::fmax(diff, std::fmax(std::fabs(xs - xo[i + ni * j]), std::fabs(ys - yo[i + ni * j])));
            }
        std::printf("set of blocks: max |set - one block| = %.2e\n", diff);
        CHECK(diff < 1e-9);
        CHECK(throws([&] { set.write("/nonexistent-dir/x.vts", EG2D_FORMAT_VTS); }, EG2D_ERR_UNSUPPORTED,
                     "the vts format cannot hold a set of blocks"));
    }

    // the swan of the C library (tests/support/swan_write_c.c)
    if (argc > 1) {
        std::ifstream in(argv[1]);
        int ni = 0, nj = 0;
        in >> ni >> nj;
        std::vector<double> xc(ni * nj), yc(ni * nj);
        for (int k = 0; k < ni * nj; ++k) in >> xc[k] >> yc[k];
        CHECK(in.good() && ni == 33);
        eg2d::grid s(ni, nj);
        set_swan(s, ni, nj);
        s.set_system(EG2D_SYSTEM_WINSLOW);
        s.set_solver(EG2D_SOLVER_PSOR);
        s.set_tolerance(1e-12);
        s.solve();
        s.get_coordinates(x, y);
        double diff = 0;
        for (int k = 0; k < ni * nj; ++k) diff = std::fmax(diff, std::fmax(std::fabs(x[k] - xc[k]), std::fabs(y[k] - yc[k])));
        std::printf("swan %dx%d: max |C++ - C| = %.2e\n", ni, nj, diff);
        CHECK(diff <= 1e-14);
    }
    std::printf("test_hpp: %d passed, %d failed\n", passes, failures);
    return failures ? 1 : 0;
}
