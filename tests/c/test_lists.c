/* The library's lists (eg2d_list_*, eg2d_parameter_info, eg2d_format_info,
 * eg2d_quality_cell_field): every id a program can pass is listed once by
 * name, in id order, found again by that name, and described; the errors
 * name what was wrong. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "eg2d.h"

static const int kLists[] = {EG2D_LIST_SOLVERS,      EG2D_LIST_PARAMETERS,   EG2D_LIST_FORMATS,
                             EG2D_LIST_QUALITY,      EG2D_LIST_SYSTEMS,      EG2D_LIST_INITIALIZERS,
                             EG2D_LIST_ORTHOGONALITY, EG2D_LIST_TOPOLOGIES,  EG2D_LIST_DISTRIBUTIONS,
                             EG2D_LIST_SET_FORMATS};
#define NLISTS (sizeof kLists / sizeof kLists[0])

/* Each list: entries in increasing id order, names unique, each found by
 * its name and named by its id. */
static void lists_are_consistent(void **state) {
    size_t l;
    (void)state;
    for (l = 0; l < NLISTS; ++l) {
        int n = -1, k, previous = -1000000;
        assert_int_equal(eg2d_list_count(kLists[l], &n), EG2D_OK);
        assert_true(n >= 2);
        for (k = 0; k < n; ++k) {
            int id = -1, found = -1, j;
            const char *name = NULL;
            assert_int_equal(eg2d_list_entry(kLists[l], k, &id, &name), EG2D_OK);
            assert_non_null(name);
            assert_true(id > previous);
            previous = id;
            assert_string_equal(eg2d_list_name(kLists[l], id), name);
            assert_int_equal(eg2d_list_find(kLists[l], name, &found), EG2D_OK);
            assert_int_equal(found, id);
            for (j = 0; j < k; ++j) {
                const char *other = NULL;
                assert_int_equal(eg2d_list_entry(kLists[l], j, NULL, &other), EG2D_OK);
                assert_string_not_equal(other, name);
            }
        }
    }
}

/* The names programs and case files use, each the id of eg2d.h. */
static void names_are_the_ids(void **state) {
    static const struct {
        int list;
        const char *name;
        int id;
    } known[] = {
        {EG2D_LIST_SOLVERS, "multigrid", EG2D_SOLVER_MULTIGRID},
        {EG2D_LIST_SOLVERS, "psor", EG2D_SOLVER_PSOR},
        {EG2D_LIST_PARAMETERS, "wall_growth", EG2D_PARAM_WALL_GROWTH},
        {EG2D_LIST_PARAMETERS, "march_growth", EG2D_PARAM_MARCH_GROWTH},
        {EG2D_LIST_PARAMETERS, "airfoil_wake_nodes", EG2D_PARAM_AIRFOIL_WAKE_NODES},
        {EG2D_LIST_FORMATS, "plot3d-ascii", EG2D_FORMAT_PLOT3D_ASCII},
        {EG2D_LIST_FORMATS, "openfoam", EG2D_FORMAT_OPENFOAM},
        {EG2D_LIST_QUALITY, "max_area", EG2D_QUALITY_MAX_AREA},
        {EG2D_LIST_QUALITY, "ortho_mean_imin", EG2D_QUALITY_ORTHO_MEAN_IMIN},
        {EG2D_LIST_SYSTEMS, "variational", EG2D_SYSTEM_VARIATIONAL},
        {EG2D_LIST_INITIALIZERS, "hyperbolic", EG2D_INIT_HYPERBOLIC},
        {EG2D_LIST_ORTHOGONALITY, "middlecoff-thomas", EG2D_ORTHO_MIDDLECOFF_THOMAS},
        {EG2D_LIST_TOPOLOGIES, "c", EG2D_TOPO_C},
        {EG2D_LIST_DISTRIBUTIONS, "tanh2", EG2D_DIST_TANH_TWO},
        {EG2D_LIST_SET_FORMATS, "cgns", EG2D_FORMAT_CGNS},
        {EG2D_LIST_SET_FORMATS, "openfoam", EG2D_FORMAT_OPENFOAM},
        {EG2D_LIST_SET_FORMATS, "vtm", EG2D_FORMAT_VTM},
    };
    size_t k;
    (void)state;
    for (k = 0; k < sizeof known / sizeof known[0]; ++k) {
        int id = -1;
        assert_int_equal(eg2d_list_find(known[k].list, known[k].name, &id), EG2D_OK);
        assert_int_equal(id, known[k].id);
    }
    /* eg2d_solver_name is the solvers' list */
    assert_string_equal(eg2d_solver_name(EG2D_SOLVER_NESTED), eg2d_list_name(EG2D_LIST_SOLVERS, EG2D_SOLVER_NESTED));
}

/* Every parameter of the list has bounds, a default within them (or 0 as
 * automatic), a kind, a unit and a summary; every id from 0 to 999 that
 * has bounds is listed (no parameter outside the table). */
static void parameters_are_described(void **state) {
    int n, k, id, listed = 0;
    (void)state;
    assert_int_equal(eg2d_list_count(EG2D_LIST_PARAMETERS, &n), EG2D_OK);
    for (k = 0; k < n; ++k) {
        double lo, hi, def;
        int kind = -1;
        const char *unit = NULL, *summary = NULL;
        assert_int_equal(eg2d_list_entry(EG2D_LIST_PARAMETERS, k, &id, NULL), EG2D_OK);
        assert_int_equal(eg2d_parameter_bounds(id, &lo, &hi, &def), EG2D_OK);
        assert_int_equal(eg2d_parameter_info(id, &kind, &unit, &summary), EG2D_OK);
        assert_true(lo < hi);
        assert_true((def >= lo && def <= hi) || (def == 0 && (kind & EG2D_VALUE_AUTOMATIC)));
        assert_true(kind >= 0 && kind <= 31);
        if (kind & EG2D_VALUE_FLAG) {
            assert_true(kind & EG2D_VALUE_INTEGER);
            assert_true(lo == 0 && hi == 1);
        }
        assert_true(unit && *unit && summary && strlen(summary) > 8);
    }
    for (id = 0; id < 1000; ++id) listed += eg2d_parameter_bounds(id, NULL, NULL, NULL) == EG2D_OK;
    assert_int_equal(listed, n);
    {
        int kind;
        assert_int_equal(eg2d_parameter_info(EG2D_PARAM_MG_FMG, &kind, NULL, NULL), EG2D_OK);
        assert_int_equal(kind, EG2D_VALUE_FLAG | EG2D_VALUE_INTEGER);
        assert_int_equal(eg2d_parameter_info(EG2D_PARAM_RELAXATION, &kind, NULL, NULL), EG2D_OK);
        assert_int_equal(kind, EG2D_VALUE_AUTOMATIC | EG2D_VALUE_OPEN_LOWER | EG2D_VALUE_OPEN_UPPER);
        assert_int_equal(eg2d_parameter_info(EG2D_PARAM_WALL_RELAXATION, &kind, NULL, NULL), EG2D_OK);
        assert_int_equal(kind, EG2D_VALUE_REAL | EG2D_VALUE_OPEN_LOWER);
    }
}

static void formats_and_metrics_are_described(void **state) {
    int kind = -1;
    const char *suffix = NULL;
    (void)state;
    assert_int_equal(eg2d_format_info(EG2D_FORMAT_VTS, &kind, &suffix), EG2D_OK);
    assert_int_equal(kind, EG2D_WRITES_FILE);
    assert_string_equal(suffix, ".vts");
    assert_int_equal(eg2d_format_info(EG2D_FORMAT_OPENFOAM, &kind, &suffix), EG2D_OK);
    assert_int_equal(kind, EG2D_WRITES_DIRECTORY);
    assert_string_equal(suffix, "_foam");
    assert_int_equal(eg2d_format_info(EG2D_FORMAT_VTM, &kind, &suffix), EG2D_OK);  /* names its blocks' directory */
    assert_int_equal(kind, EG2D_WRITES_FILE);
    assert_string_equal(suffix, ".vtm");
    assert_int_equal(eg2d_format_info(77, &kind, &suffix), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "format = 77"));
    assert_string_equal(eg2d_quality_cell_field(EG2D_QUALITY_MIN_AREA), "area");
    assert_string_equal(eg2d_quality_cell_field(EG2D_QUALITY_MAX_AREA), "area");
    assert_string_equal(eg2d_quality_cell_field(EG2D_QUALITY_SKEWNESS), "skewness");
    assert_null(eg2d_quality_cell_field(EG2D_QUALITY_ORTHO_MAX_JMIN));
    assert_null(eg2d_quality_cell_field(-3));
}

static void errors_name_the_thing(void **state) {
    int n, id = 12345;
    const char *name = "untouched";
    (void)state;
    assert_int_equal(eg2d_list_count(99, &n), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "list = 99"));
    assert_int_equal(eg2d_list_count(EG2D_LIST_SOLVERS, NULL), EG2D_ERR_ARGUMENT);
    assert_int_equal(eg2d_list_count(EG2D_LIST_SOLVERS, &n), EG2D_OK);
    assert_int_equal(eg2d_list_entry(EG2D_LIST_SOLVERS, n, &id, &name), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "EG2D_LIST_SOLVERS has"));
    assert_int_equal(eg2d_list_entry(EG2D_LIST_SOLVERS, -1, &id, &name), EG2D_ERR_ARGUMENT);
    assert_int_equal(id, 12345); /* nothing written on failure */
    assert_string_equal(name, "untouched");
    assert_int_equal(eg2d_list_find(EG2D_LIST_SYSTEMS, "Winslow", &id), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "one of: laplace, winslow, variational"));
    assert_int_equal(eg2d_list_find(EG2D_LIST_SYSTEMS, NULL, &id), EG2D_ERR_ARGUMENT);
    assert_null(eg2d_list_name(EG2D_LIST_SOLVERS, 98));
    assert_null(eg2d_list_name(-1, 0));
    assert_int_equal(eg2d_parameter_info(9999, NULL, NULL, NULL), EG2D_ERR_ARGUMENT);
    assert_non_null(strstr(eg2d_last_error(NULL), "parameter 9999"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lists_are_consistent),
        cmocka_unit_test(names_are_the_ids),
        cmocka_unit_test(parameters_are_described),
        cmocka_unit_test(formats_and_metrics_are_described),
        cmocka_unit_test(errors_name_the_thing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
