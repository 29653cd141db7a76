/* The alignment snap's set-up, compiled: the snapper's tables (snapping.feature_table) and the
   rest check's pairs and tables (rest_check.RestCheck: fast_forces.candidate_pairs,
   blocked_axes, each pair's reach and shares, the pairs of each row; the masses, the rest
   boxes of fast_forces.wall_rest_box, the anchor springs).

   A snap runs twice a settle, and on a page of 5-30 items its set-up was made of some two
   hundred NumPy calls of a microsecond each on arrays of a few dozen rows: half of the snap,
   and the most of what the guides cost on the small pages of issue #16.  Here the same
   operations on the same floats in the same order, one call each; the NumPy definitions stay
   (snapping.feature_table, fast_forces.candidate_pairs, blocked_axes) and
   tests/physics/test_snap_setup.py holds these to them bit for bit. */

#include "snap_kernel_support.h"

/* ---- the snapper's table of one axis (snapping.feature_table) ---- */

PyDoc_STRVAR(fill_feature_table_doc,
"fill_feature_table(table, centres, halves, active, axis, edges, middles) -> None\n\n"
"Fill ``table`` (rows + edges + middles, 15) as snapping.feature_table makes it: per row its\n"
"low edge, centre and high edge on ``axis`` (centre less, centre, centre plus its half), them\n"
"paired as theirs and as mine, its low and high edge (an inactive row's theirs and lows at\n"
"+inf, its highs at -inf); per page line NaN but for theirs (an edge paired with a low and a\n"
"high edge, a middle with a centre, +inf elsewhere) and its low -inf, its high +inf.");

static PyObject *fill_feature_table(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 7) {
        PyErr_SetString(PyExc_TypeError, "fill_feature_table(table, centres, halves, active, "
                        "axis, edges, middles)");
        return NULL;
    }
    int axis = PyLong_AsLong(args[4]);
    if (axis == -1 && PyErr_Occurred())
        return NULL;
    if (axis != 0 && axis != 1) {
        PyErr_SetString(PyExc_ValueError, "axis: 0 or 1");
        return NULL;
    }
    Py_buffer views[6];
    int held = 0;
    PyObject *result = NULL;
    if (PyObject_GetBuffer(args[0], &views[0],
                           PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | PyBUF_WRITABLE) < 0)
        goto done;
    held++;
    if (views[0].ndim != 2 || views[0].itemsize != 8 || views[0].format == NULL
            || strcmp(views[0].format, "d") != 0 || views[0].shape[1] != COLUMNS) {
        PyErr_SetString(PyExc_TypeError, "table: a writable C-contiguous float64 (rows, 15)");
        goto done;
    }
    if (read_row_pairs(args[1], &views[1], "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[1].shape[0];
    if (read_pairs_of(args[2], &views[2], count, "halves") < 0)
        goto done;
    held++;
    if (read_flags(args[3], &views[3], count) < 0)
        goto done;
    held++;
    if (read_doubles(args[5], &views[4], 1, "edges") < 0)
        goto done;
    held++;
    if (read_doubles(args[6], &views[5], 1, "middles") < 0)
        goto done;
    held++;
    Py_ssize_t edges = views[4].shape[0], middles = views[5].shape[0];
    if (views[0].shape[0] != count + edges + middles) {
        PyErr_SetString(PyExc_ValueError, "table: a row per row, edge line and middle line");
        goto done;
    }
    double *table = views[0].buf;
    const double *centres = views[1].buf, *halves = views[2].buf;
    const char *active = views[3].buf;
    for (Py_ssize_t row = 0; row < count; row++) {
        double c = centres[2 * row + axis], h = halves[2 * row + axis];
        double low = c - h, high = c + h;
        double *cells = table + row * COLUMNS;
        cells[0] = low, cells[1] = c, cells[2] = high;
        if (active[row]) { /* THEIRS: LOW, HIGH, LOW, HIGH, CENTRE */
            cells[THEIRS] = low, cells[THEIRS + 1] = high, cells[THEIRS + 2] = low;
            cells[THEIRS + 3] = high, cells[THEIRS + 4] = c;
            cells[LOWS] = low, cells[HIGHS] = high;
        } else {
            for (int k = 0; k < PAIRINGS; k++)
                cells[THEIRS + k] = INFINITY;
            cells[LOWS] = INFINITY, cells[HIGHS] = -INFINITY;
        }
        /* MINE: LOW, LOW, HIGH, HIGH, CENTRE */
        cells[MINE] = low, cells[MINE + 1] = low, cells[MINE + 2] = high;
        cells[MINE + 3] = high, cells[MINE + 4] = c;
    }
    const double *edge = views[4].buf, *middle = views[5].buf;
    for (Py_ssize_t line = 0; line < edges + middles; line++) {
        double *cells = table + (count + line) * COLUMNS;
        for (int k = 0; k < COLUMNS; k++)
            cells[k] = NAN;
        for (int k = 0; k < PAIRINGS; k++)
            cells[THEIRS + k] = INFINITY;
        if (line < edges) /* their low edge: paired with my low and my high edge */
            cells[THEIRS] = cells[THEIRS + 2] = edge[line];
        else
            cells[THEIRS + 4] = middle[line - edges];
        cells[LOWS] = -INFINITY, cells[HIGHS] = INFINITY;
    }
    result = Py_NewRef(Py_None);
done:
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

/* ---- the rest check's pairs (fast_forces.candidate_pairs, by sweep) ---- */

typedef struct {
    double left;
    Py_ssize_t index;
} Entry;

/* np.argsort(kind="stable") of the left edges: by value, NaN last, ties in row order */
static int by_left(const void *a, const void *b)
{
    const Entry *x = a, *y = b;
    int x_nan = isnan(x->left), y_nan = isnan(y->left);
    if (x_nan != y_nan)
        return x_nan - y_nan;
    if (!x_nan && x->left != y->left)
        return x->left < y->left ? -1 : 1;
    return (x->index > y->index) - (x->index < y->index);
}

PyDoc_STRVAR(sweep_pairs_doc,
"sweep_pairs(centres, halves, active, roots, reach) -> bytes\n\n"
"fast_forces.candidate_pairs(centres, halves, np.flatnonzero(active), roots, reach) by its\n"
"sweep (fewer rows than GRID_FROM_ITEMS), as int64 (i, j) pairs, i < j, in its order: the\n"
"active rows sorted by left edge (stably), each meeting the rows after it whose left edge\n"
"lies before its right edge plus ``reach`` (searchsorted, side left) and whose gap across\n"
"(|y_b - y_a| - half_a - half_b) is below ``reach``, rows of one group left out.");

static PyObject *sweep_pairs(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 5) {
        PyErr_SetString(PyExc_TypeError, "sweep_pairs(centres, halves, active, roots, reach)");
        return NULL;
    }
    double reach = PyFloat_AsDouble(args[4]);
    if (reach == -1.0 && PyErr_Occurred())
        return NULL;
    Py_buffer views[4];
    int held = 0;
    PyObject *result = NULL;
    Entry *order = NULL;
    int64_t *pairs = NULL;
    if (read_row_pairs(args[0], &views[0], "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (read_pairs_of(args[1], &views[1], count, "halves") < 0)
        goto done;
    held++;
    if (read_flags(args[2], &views[2], count) < 0)
        goto done;
    held++;
    if (read_rows(args[3], &views[3], count) < 0)
        goto done;
    held++;
    if (views[3].shape[0] != count) {
        PyErr_SetString(PyExc_ValueError, "roots: one per row");
        goto done;
    }
    const double *centres = views[0].buf, *halves = views[1].buf;
    const char *active = views[2].buf;
    const int64_t *roots = views[3].buf;
    order = PyMem_Malloc((count + 1) * sizeof(Entry));
    if (order == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    Py_ssize_t n = 0;
    for (Py_ssize_t row = 0; row < count; row++)
        if (active[row]) {
            order[n].left = centres[2 * row] - halves[2 * row];
            order[n].index = row;
            n++;
        }
    if (n < 2) {
        result = PyBytes_FromStringAndSize(NULL, 0);
        goto done;
    }
    qsort(order, n, sizeof(Entry), by_left);
    Py_ssize_t room = 4 * n, made = 0;
    pairs = PyMem_Malloc(2 * room * sizeof(int64_t));
    if (pairs == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    Py_ssize_t stop = 0;
    for (Py_ssize_t a = 0; a < n; a++) {
        Py_ssize_t row_a = order[a].index;
        double right = centres[2 * row_a] + halves[2 * row_a];
        double until = right + reach;
        /* np.searchsorted(left_sorted, until, side="left"): the first left not below it
           (NaN lefts sort last and count as above everything) */
        Py_ssize_t lo = 0, hi = n;
        while (lo < hi) {
            Py_ssize_t mid = lo + (hi - lo) / 2;
            double left = order[mid].left;
            int below = isnan(until) ? !isnan(left) : (!isnan(left) && left < until);
            if (below)
                lo = mid + 1;
            else
                hi = mid;
        }
        stop = lo;
        double y_a = centres[2 * row_a + 1], half_a = halves[2 * row_a + 1];
        for (Py_ssize_t b = a + 1; b < stop; b++) {
            Py_ssize_t row_b = order[b].index;
            double clear = fabs(centres[2 * row_b + 1] - y_a) - half_a - halves[2 * row_b + 1];
            if (!(clear < reach))
                continue;
            int64_t i = row_a < row_b ? row_a : row_b, j = row_a < row_b ? row_b : row_a;
            if (roots[i] == roots[j])
                continue;
            if (made == room) {
                room *= 2;
                int64_t *grown = PyMem_Realloc(pairs, 2 * room * sizeof(int64_t));
                if (grown == NULL) {
                    PyErr_NoMemory();
                    goto done;
                }
                pairs = grown;
            }
            pairs[2 * made] = i;
            pairs[2 * made + 1] = j;
            made++;
        }
    }
    result = PyBytes_FromStringAndSize((const char *)pairs, 2 * made * sizeof(int64_t));
done:
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    PyMem_Free(order);
    PyMem_Free(pairs);
    return result;
}

/* ---- the rest check's table per pair and pairs per row ---- */

/* np.minimum of two floats: a NaN on either side is the answer */
static inline double smaller(double a, double b)
{
    return isnan(a) || isnan(b) ? NAN : (b < a ? b : a);
}

PyDoc_STRVAR(pair_tables_doc,
"pair_tables(pair_ends, sizes, halves, inverse, near, far, page_w, page_h, gap)\n"
"    -> (table bytes, pairs per row)\n\n"
"RestCheck's pair_table, (pairs, 6) float64 as bytes: each pair's reach (half sizes summed\n"
"plus ``gap``), its blocked axes as fast_forces.blocked_axes finds them with no gutter and\n"
"the walls ``near`` and ``far`` (1.0 where blocked), and its ends' shares of a push\n"
"(``inverse`` mass over the two summed, 1 where that is not above 0); and per row the pairs\n"
"it is an end of, as a list, first those where it is i, then j, each in pair order (a stable\n"
"sort of the ends).");

static PyObject *pair_tables(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 9) {
        PyErr_SetString(PyExc_TypeError, "pair_tables(pair_ends, sizes, halves, inverse, near, "
                        "far, page_w, page_h, gap)");
        return NULL;
    }
    double extent[2] = {PyFloat_AsDouble(args[6]), PyFloat_AsDouble(args[7])};
    double gap = PyFloat_AsDouble(args[8]);
    if (PyErr_Occurred())
        return NULL;
    Py_buffer views[6];
    int held = 0;
    PyObject *result = NULL, *table = NULL, *lists = NULL;
    Py_ssize_t *counts = NULL;
    if (read_row_pairs(args[1], &views[0], "sizes") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (PyObject_GetBuffer(args[0], &views[1], PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        goto done;
    held++;
    const char *format = views[1].format ? views[1].format : "B";
    if (views[1].ndim != 2 || views[1].itemsize != 8 || strchr("lqn", format[0]) == NULL
            || format[1] != '\0' || views[1].shape[1] != 2) {
        PyErr_SetString(PyExc_TypeError, "pair_ends: a C-contiguous int64 (pairs, 2)");
        goto done;
    }
    Py_ssize_t pair_count = views[1].shape[0];
    const int64_t *ends = views[1].buf;
    for (Py_ssize_t k = 0; k < 2 * pair_count; k++)
        if (ends[k] < 0 || ends[k] >= count) {
            PyErr_SetString(PyExc_IndexError, "pair_ends: a row outside the page");
            goto done;
        }
    if (read_pairs_of(args[2], &views[2], count, "halves") < 0)
        goto done;
    held++;
    if (read_doubles(args[3], &views[3], 1, "inverse") < 0)
        goto done;
    held++;
    if (views[3].shape[0] != count) {
        PyErr_SetString(PyExc_ValueError, "inverse: one per row");
        goto done;
    }
    if (read_pairs_of(args[4], &views[4], count, "near") < 0)
        goto done;
    held++;
    if (read_pairs_of(args[5], &views[5], count, "far") < 0)
        goto done;
    held++;
    const double *sizes = views[0].buf, *halves = views[2].buf, *inverse = views[3].buf;
    const double *near = views[4].buf, *far = views[5].buf;
    /* blocked_axes: one room for every pair where every row's walls stand as the first's */
    int uniform = 1;
    for (Py_ssize_t row = 0; row < count && uniform; row++)
        for (int axis = 0; axis < 2; axis++)
            if (!(near[2 * row + axis] == near[axis]) || !(far[2 * row + axis] == far[axis]))
                uniform = 0;
    double room_all[2] = {0.0, 0.0};
    if (count > 0)
        for (int axis = 0; axis < 2; axis++)
            room_all[axis] = extent[axis] - near[axis] - far[axis];
    table = PyBytes_FromStringAndSize(NULL, 6 * pair_count * sizeof(double));
    if (table == NULL)
        goto done;
    double *cells = (double *)PyBytes_AS_STRING(table);
    for (Py_ssize_t p = 0; p < pair_count; p++) {
        int64_t i = ends[2 * p], j = ends[2 * p + 1];
        double *pair = cells + 6 * p;
        int blocked[2];
        for (int axis = 0; axis < 2; axis++) {
            pair[axis] = halves[2 * i + axis] + halves[2 * j + axis] + gap;
            double room = uniform ? room_all[axis]
                : extent[axis] - smaller(near[2 * i + axis] + far[2 * j + axis],
                                         near[2 * j + axis] + far[2 * i + axis]);
            double need = sizes[2 * i + axis] + sizes[2 * j + axis] + 0.0;
            blocked[axis] = need > room;
        }
        if (blocked[0] && blocked[1]) /* hopeless either way: the cheaper axis decides */
            blocked[0] = blocked[1] = 0;
        pair[2] = blocked[0] ? 1.0 : 0.0;
        pair[3] = blocked[1] ? 1.0 : 0.0;
        double total = inverse[i] + inverse[j];
        total = total > 0 ? total : 1.0;
        pair[4] = inverse[i] / total;
        pair[5] = inverse[j] / total;
    }
    /* each row's pairs: as i, then as j, each in pair order */
    counts = PyMem_Calloc(count + 1, sizeof(Py_ssize_t));
    lists = PyList_New(count);
    if (counts == NULL || lists == NULL) {
        if (counts == NULL)
            PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t k = 0; k < 2 * pair_count; k++)
        counts[ends[k]]++;
    for (Py_ssize_t row = 0; row < count; row++) {
        PyObject *list = PyList_New(counts[row]);
        if (list == NULL)
            goto done;
        PyList_SET_ITEM(lists, row, list);
        counts[row] = 0; /* from here: how many are filled */
    }
    for (int side = 0; side < 2; side++)
        for (Py_ssize_t p = 0; p < pair_count; p++) {
            int64_t row = ends[2 * p + side];
            PyObject *number = PyLong_FromSsize_t(p);
            if (number == NULL)
                goto done;
            PyList_SET_ITEM(PyList_GET_ITEM(lists, row), counts[row]++, number);
        }
    result = PyTuple_Pack(2, table, lists);
done:
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    PyMem_Free(counts);
    Py_XDECREF(table);
    Py_XDECREF(lists);
    return result;
}

/* ---- the rest check's rows: masses, rest boxes, anchor springs ---- */

PyDoc_STRVAR(inverse_masses_doc,
"inverse_masses(sizes, roots, active, free, held) -> bytes\n\n"
"Per row, as float64: one over its group's mass (the charges w h of its active rows summed\n"
"row by row, as np.bincount adds them; at least 1e-12) where the integrator moves it (its\n"
"root free, itself not held, active), 0 elsewhere: RestCheck's inverse masses.");

static PyObject *inverse_masses(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 5) {
        PyErr_SetString(PyExc_TypeError, "inverse_masses(sizes, roots, active, free, held)");
        return NULL;
    }
    Py_buffer views[5];
    int held = 0;
    PyObject *result = NULL;
    double *mass = NULL;
    if (read_row_pairs(args[0], &views[0], "sizes") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (read_rows(args[1], &views[1], count) < 0)
        goto done;
    held++;
    if (views[1].shape[0] != count) {
        PyErr_SetString(PyExc_ValueError, "roots: one per row");
        goto done;
    }
    for (int k = 2; k < 5; k++) {
        if (read_flags(args[k], &views[k], count) < 0)
            goto done;
        held++;
    }
    const double *sizes = views[0].buf;
    const int64_t *roots = views[1].buf;
    const char *active = views[2].buf, *free_rows = views[3].buf, *held_rows = views[4].buf;
    mass = PyMem_Calloc(count + 1, sizeof(double));
    result = PyBytes_FromStringAndSize(NULL, count * sizeof(double));
    if (mass == NULL || result == NULL) {
        if (mass == NULL)
            PyErr_NoMemory();
        Py_CLEAR(result);
        goto done;
    }
    for (Py_ssize_t row = 0; row < count; row++) /* np.where(active, w * h, 0.0), bincount */
        mass[roots[row]] += active[row] ? sizes[2 * row] * sizes[2 * row + 1] : 0.0;
    double *inverse = (double *)PyBytes_AS_STRING(result);
    for (Py_ssize_t row = 0; row < count; row++) {
        double group = mass[roots[row]];
        group = isnan(group) ? NAN : (group > 1e-12 ? group : 1e-12); /* np.maximum */
        double one_over = 1.0 / group;
        inverse[row] = free_rows[roots[row]] && !held_rows[row] && active[row] ? one_over : 0.0;
    }
done:
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    PyMem_Free(mass);
    return result;
}

PyDoc_STRVAR(row_table_doc,
"row_table(halves, near, far, page_w, page_h, gap, anchors, hard, gammas, anchor_scale)\n"
"    -> bytes\n\n"
"RestCheck's row_table, (rows, 7) float64 as bytes: each row's rest box (fast_forces.\n"
"wall_rest_box with its walls at gap / 2 + near and gap / 2 + far: its lowest and highest\n"
"centre, the middle between its walls where it is too large for the page or for them), its\n"
"anchor spring's stiffness (anchor_scale times its gamma where it has a soft anchor, 0\n"
"elsewhere) and its anchor (0 where none).");

static PyObject *row_table(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 10) {
        PyErr_SetString(PyExc_TypeError, "row_table(halves, near, far, page_w, page_h, gap, "
                        "anchors, hard, gammas, anchor_scale)");
        return NULL;
    }
    double extent[2] = {PyFloat_AsDouble(args[3]), PyFloat_AsDouble(args[4])};
    double gap = PyFloat_AsDouble(args[5]), scale = PyFloat_AsDouble(args[9]);
    if (PyErr_Occurred())
        return NULL;
    Py_buffer views[6];
    int held = 0;
    PyObject *result = NULL;
    if (read_row_pairs(args[0], &views[0], "halves") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (read_pairs_of(args[1], &views[1], count, "near") < 0)
        goto done;
    held++;
    if (read_pairs_of(args[2], &views[2], count, "far") < 0)
        goto done;
    held++;
    if (read_pairs_of(args[6], &views[3], count, "anchors") < 0)
        goto done;
    held++;
    if (read_flags(args[7], &views[4], count) < 0)
        goto done;
    held++;
    if (read_doubles(args[8], &views[5], 1, "gammas") < 0)
        goto done;
    held++;
    if (views[5].shape[0] != count) {
        PyErr_SetString(PyExc_ValueError, "gammas: one per row");
        goto done;
    }
    const double *halves = views[0].buf, *near = views[1].buf, *far = views[2].buf;
    const double *anchors = views[3].buf, *gammas = views[5].buf;
    const char *hard = views[4].buf;
    result = PyBytes_FromStringAndSize(NULL, 7 * count * sizeof(double));
    if (result == NULL)
        goto done;
    double *cells = (double *)PyBytes_AS_STRING(result);
    for (Py_ssize_t row = 0; row < count; row++) {
        double *out = cells + 7 * row;
        for (int axis = 0; axis < 2; axis++) {
            double half = halves[2 * row + axis];
            double low_wall = gap / 2 + near[2 * row + axis];
            double high_wall = gap / 2 + far[2 * row + axis];
            double lowest = half + low_wall, highest = extent[axis] - half - high_wall;
            if (2 * half >= extent[axis] || lowest > highest) /* squeezed: the middle */
                lowest = highest = extent[axis] / 2 + (low_wall - high_wall) / 2;
            out[axis] = lowest;
            out[2 + axis] = highest;
        }
        int anchored = !isnan(anchors[2 * row]) && !hard[row];
        out[4] = anchored ? scale * gammas[row] : 0.0;
        out[5] = anchored ? anchors[2 * row] : 0.0;
        out[6] = anchored ? anchors[2 * row + 1] : 0.0;
    }
done:
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

/* ---- the snap's putting its movers on the save's grid (physics.snapping._Snapper.onto_grid) ---- */

/* save_grid.on_save_grid of one centre, the same operations in the same order */
static double save_grid_centre(double centre, double half, double page, double steps)
{
    double step = 1.0 / steps;
    double nearest = floor(centre * steps + 0.5) / steps;
    int inside = centre - half >= -1e-9 && centre + half <= page + 1e-9 && 2 * half <= page;
    if (inside && nearest - half < 0)
        nearest = ceil(rint(half / step * 1e6) / 1e6) / steps;
    if (inside && nearest + half > page)
        nearest = floor(rint((page - half) / step * 1e6) / 1e6) / steps;
    return nearest + 0.0;
}

/* save_grid.fitting_grid_shifts on raw arrays: ``kept`` (per row, this axis's shifts) less
   those of the groups they do not fit for, all at once, until none fails.  ``dropped`` (per
   root) marks the groups that lost theirs.  Returns 0, or -1 out of memory. */
static int fitting_grid(const double *centres, const double *halves, const char *active,
                        const int64_t *roots, Py_ssize_t count, int axis, const double *lowest,
                        const double *highest, double clearance, double tolerance,
                        double steps, double *kept, char *dropped)
{
    int across = 1 - axis;
    double margin = clearance + 3.0 / steps;
    Py_ssize_t room = 16, found = 0;
    Py_ssize_t *pairs = PyMem_Malloc(2 * room * sizeof(Py_ssize_t));
    double *tests = PyMem_Malloc(4 * room * sizeof(double));
    if (pairs == NULL || tests == NULL) {
        PyMem_Free(pairs);
        PyMem_Free(tests);
        return -1;
    }
    for (Py_ssize_t i = 0; i < count; i++) {
        if (!active[i])
            continue;
        for (Py_ssize_t j = i + 1; j < count; j++) {
            if (!active[j] || roots[i] == roots[j])
                continue;
            double gap_x = fabs(centres[2 * i] - centres[2 * j]) - halves[2 * i] - halves[2 * j];
            double gap_y = fabs(centres[2 * i + 1] - centres[2 * j + 1]) - halves[2 * i + 1]
                           - halves[2 * j + 1];
            if (!(gap_x < margin && gap_y < margin))
                continue;
            double gap_across = fabs(centres[2 * i + across] - centres[2 * j + across])
                                - halves[2 * i + across] - halves[2 * j + across];
            double reach = halves[2 * i + axis] + halves[2 * j + axis];
            double along = centres[2 * i + axis] - centres[2 * j + axis];
            double now = fabs(along) - reach;
            double needed = now > gap_across ? now : gap_across;
            needed = clearance < needed ? clearance : needed;
            needed -= tolerance;
            if (gap_across >= needed)
                continue; /* no shift along this axis brings them closer than needed */
            if (found == room) {
                room *= 2;
                Py_ssize_t *more_pairs = PyMem_Realloc(pairs, 2 * room * sizeof(Py_ssize_t));
                double *more_tests = more_pairs ? PyMem_Realloc(tests, 4 * room * sizeof(double))
                                                : NULL;
                if (more_pairs) pairs = more_pairs;
                if (more_tests) tests = more_tests;
                if (more_pairs == NULL || more_tests == NULL) {
                    PyMem_Free(pairs);
                    PyMem_Free(tests);
                    return -1;
                }
            }
            pairs[2 * found] = i;
            pairs[2 * found + 1] = j;
            tests[4 * found] = along;
            tests[4 * found + 1] = reach;
            tests[4 * found + 2] = gap_across;
            tests[4 * found + 3] = needed;
            found++;
        }
    }
    for (;;) {
        int any = 0;
        for (Py_ssize_t row = 0; row < count; row++) {
            if (!active[row] || kept[row] == 0.0)
                continue;
            double at = centres[2 * row + axis], after = at + kept[row];
            double low = lowest[2 * row + axis], high = highest[2 * row + axis];
            low = (at < low ? at : low) - tolerance;
            high = (at > high ? at : high) + tolerance;
            if (after < low || after > high) {
                dropped[roots[row]] = 2; /* failing now */
                any = 1;
            }
        }
        for (Py_ssize_t p = 0; p < found; p++) {
            Py_ssize_t i = pairs[2 * p], j = pairs[2 * p + 1];
            const double *test = tests + 4 * p;
            double gap = fabs(test[0] + kept[i] - kept[j]) - test[1];
            gap = gap > test[2] ? gap : test[2];
            if (gap < test[3]) {
                if (kept[i] != 0.0) { dropped[roots[i]] = 2; any = 1; }
                if (kept[j] != 0.0) { dropped[roots[j]] = 2; any = 1; }
            }
        }
        if (!any)
            break;
        for (Py_ssize_t row = 0; row < count; row++)
            if (dropped[roots[row]] == 2)
                kept[row] = 0.0;
        for (Py_ssize_t row = 0; row < count; row++)
            if (dropped[row] == 2)
                dropped[row] = 1;
    }
    PyMem_Free(pairs);
    PyMem_Free(tests);
    return 0;
}

PyDoc_STRVAR(grid_shifts_doc,
"grid_shifts(centres, halves, active, roots, movers, lowest, highest, page, clearance,\n"
"            tolerance, steps) -> bytes\n\n"
"_Snapper.onto_grid_numpy's shifts, compiled: per axis (x, then y with x's made), the movers'\n"
"shifts onto the save's grid (save_grid.on_save_grid; ``movers``: per row, whether it is a\n"
"mover's root; a group's rows take its root's), those that fit (fitting_grid_shifts), then\n"
"for the groups that did not, the step on their other side, those that fit: as float64\n"
"(rows, 2 axes, 2 passes), to be added pass by pass.  ``centres`` is not changed.");

static PyObject *grid_shifts(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 11) {
        PyErr_SetString(PyExc_TypeError, "grid_shifts(centres, halves, active, roots, movers, "
                        "lowest, highest, page, clearance, tolerance, steps)");
        return NULL;
    }
    double page[2];
    double clearance = PyFloat_AsDouble(args[8]), tolerance = PyFloat_AsDouble(args[9]);
    double steps = PyFloat_AsDouble(args[10]);
    if (!PyArg_ParseTuple(args[7], "dd", &page[0], &page[1]) || PyErr_Occurred())
        return NULL;
    Py_buffer views[7];
    int held = 0;
    PyObject *result = NULL;
    double *at = NULL, *kept = NULL, *wanted = NULL;
    char *dropped = NULL;
    if (read_row_pairs(args[0], &views[0], "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (read_pairs_of(args[1], &views[1], count, "halves") < 0)
        goto done;
    held++;
    if (read_flags(args[2], &views[2], count) < 0)
        goto done;
    held++;
    if (read_rows(args[3], &views[3], count) < 0)
        goto done;
    held++;
    if (read_flags(args[4], &views[4], count) < 0)
        goto done;
    held++;
    if (read_pairs_of(args[5], &views[5], count, "lowest") < 0)
        goto done;
    held++;
    if (read_pairs_of(args[6], &views[6], count, "highest") < 0)
        goto done;
    held++;
    if (views[3].shape[0] != count) {
        PyErr_SetString(PyExc_ValueError, "roots: one per row");
        goto done;
    }
    const double *halves = views[1].buf, *lowest = views[5].buf, *highest = views[6].buf;
    const char *active = views[2].buf, *movers = views[4].buf;
    const int64_t *roots = views[3].buf;
    result = PyBytes_FromStringAndSize(NULL, 4 * count * sizeof(double));
    at = PyMem_Malloc((2 * count + 1) * sizeof(double));
    kept = PyMem_Malloc((count + 1) * sizeof(double));
    wanted = PyMem_Malloc((count + 1) * sizeof(double));
    dropped = PyMem_Malloc(count + 1);
    if (result == NULL || at == NULL || kept == NULL || wanted == NULL || dropped == NULL) {
        Py_CLEAR(result);
        if (!PyErr_Occurred())
            PyErr_NoMemory();
        goto done;
    }
    double *out = (double *)PyBytes_AS_STRING(result); /* [row][axis][pass] */
    memset(out, 0, 4 * count * sizeof(double));
    memcpy(at, views[0].buf, 2 * count * sizeof(double));
    for (int axis = 0; axis < 2; axis++) {
        int any = 0;
        for (Py_ssize_t row = 0; row < count; row++) {
            wanted[row] = 0.0;
            if (movers[row]) {
                double here = at[2 * row + axis];
                double shift = save_grid_centre(here, halves[2 * row + axis], page[axis],
                                                steps) - here;
                wanted[row] = fabs(shift) <= tolerance ? 0.0 : shift;
            }
        }
        for (Py_ssize_t row = 0; row < count; row++) {
            Py_ssize_t root = roots[row];
            kept[row] = active[row] && movers[root] ? wanted[root] : 0.0;
            any |= kept[row] != 0.0;
        }
        for (int pass = 0; pass < 2 && any; pass++) {
            memset(dropped, 0, count + 1);
            if (fitting_grid(at, halves, active, roots, count, axis, lowest, highest,
                             clearance, tolerance, steps, kept, dropped) < 0) {
                Py_CLEAR(result);
                PyErr_NoMemory();
                goto done;
            }
            for (Py_ssize_t row = 0; row < count; row++) {
                if (kept[row] != 0.0) {
                    out[4 * row + 2 * axis + pass] = kept[row];
                    at[2 * row + axis] += kept[row];
                }
            }
            /* the other step for the groups that kept nothing: their shift less its sign's step */
            any = 0;
            for (Py_ssize_t row = 0; row < count; row++) {
                Py_ssize_t root = roots[row];
                double shift = active[row] && movers[root] ? wanted[root] : 0.0;
                double other = 0.0;
                if (kept[row] == 0.0 && shift != 0.0) {
                    other = shift - (shift > 0 ? 1.0 : -1.0) / steps;
                    if (fabs(other) <= tolerance)
                        other = 0.0;
                }
                kept[row] = other;
                any |= other != 0.0;
            }
            for (Py_ssize_t root = 0; root < count; root++)
                wanted[root] = 0.0; /* a second pass tries each once */
        }
    }
done:
    PyMem_Free(at);
    PyMem_Free(kept);
    PyMem_Free(wanted);
    PyMem_Free(dropped);
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

static PyMethodDef methods[] = {
    {"fill_feature_table", (PyCFunction)(void (*)(void))fill_feature_table, METH_FASTCALL,
     fill_feature_table_doc},
    {"sweep_pairs", (PyCFunction)(void (*)(void))sweep_pairs, METH_FASTCALL, sweep_pairs_doc},
    {"pair_tables", (PyCFunction)(void (*)(void))pair_tables, METH_FASTCALL, pair_tables_doc},
    {"inverse_masses", (PyCFunction)(void (*)(void))inverse_masses, METH_FASTCALL,
     inverse_masses_doc},
    {"row_table", (PyCFunction)(void (*)(void))row_table, METH_FASTCALL, row_table_doc},
    {"grid_shifts", (PyCFunction)(void (*)(void))grid_shifts, METH_FASTCALL, grid_shifts_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "floatpage.physics.snap_setup_kernel",
    "The alignment snap's set-up, compiled (physics/snap_setup_kernel.c).",
    0,
    methods,
};

PyMODINIT_FUNC PyInit_snap_setup_kernel(void)
{
    return PyModuleDef_Init(&module);
}
