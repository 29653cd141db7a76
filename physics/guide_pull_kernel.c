/* The guide force's refresh (physics.guides.GuidePulls.refresh), compiled: for every pulled
   item and axis, the feature to pull and the line to pull it to.  As NumPy it was some eighty
   calls a refresh (a sort, the gathers of the five looks, the choices between edges and
   centres), about 0.25 ms each and two to seven a settle with guides: most of what the pull
   costs besides the snap (benchmarks/guide_cost_parts.py).  Here it is one call, the same
   comparisons on the same floats: the lines sorted by value then by their place in the pool
   (np.argsort's stable order), a search from the left (np.searchsorted's), two looks below and
   two above, the first of the nearest (np.argmin's), ``<=`` everywhere the NumPy had it
   (tests/physics/test_guide_lookups.py holds it to guides.nearest_guides and the NumPy refresh). */

#include "snap_kernel_support.h"

#define PAGE_OWNER (-1)   /* guides.PAGE */
#define NOBODY_OWNER (-2) /* guides.NOBODY: the sentinels' owner */

/* one pool of lines, sorted: values, their owners, their index in the pool */
typedef struct {
    Py_ssize_t count;
    double *values;    /* the pool, in pool order */
    int64_t *owners;   /* per pool entry */
    Py_ssize_t *order; /* pool indices sorted by (value, index) */
} Pool;

static const double *sort_values; /* the pool qsort reads (one sort at a time: the GIL) */

static int by_value_then_index(const void *a, const void *b)
{
    Py_ssize_t i = *(const Py_ssize_t *)a, j = *(const Py_ssize_t *)b;
    double x = sort_values[i], y = sort_values[j];
    if (x < y)
        return -1;
    if (y < x)
        return 1;
    return (i > j) - (i < j); /* equal (or -0.0 and 0.0): the stable order, by place */
}

static void sort_pool(Pool *pool)
{
    for (Py_ssize_t k = 0; k < pool->count; k++)
        pool->order[k] = k;
    sort_values = pool->values;
    qsort(pool->order, pool->count, sizeof(Py_ssize_t), by_value_then_index);
}

/* guides.nearest_guides for one query: the pool index of the nearest value of another owner
   within reach (-1 if none) and the signed distance to it (inf if none).  The sorted values
   with two -inf sentinels below and three +inf above, owned by nobody; the looks are the
   sentinel-padded positions p - 2 .. p + 2 of the search from the left p. */
static void nearest(const Pool *pool, double query, int64_t owner, double reach,
                    Py_ssize_t *found, double *distance)
{
    Py_ssize_t count = pool->count;
    if (count == 0) {
        *found = -1;
        *distance = INFINITY;
        return;
    }
    /* np.searchsorted(ordered, query) over the padded array: the first place whose value is
       not below the query (the -inf sentinels are below every finite query) */
    Py_ssize_t low = 0, high = count + 5;
    while (low < high) {
        Py_ssize_t middle = low + (high - low) / 2;
        double value = middle < 2 ? -INFINITY : middle >= count + 2 ? INFINITY
            : pool->values[pool->order[middle - 2]];
        if (value < query)
            low = middle + 1;
        else
            high = middle;
    }
    double best = 0.0, best_size = 0.0;
    Py_ssize_t best_look = 0;
    for (int look = 0; look < 5; look++) {
        Py_ssize_t padded = low - 2 + look;
        double gap;
        if (padded < 2 || padded >= count + 2) /* a sentinel: owned by nobody */
            gap = (padded < 2 ? -INFINITY : INFINITY) - query;
        else {
            Py_ssize_t index = pool->order[padded - 2];
            gap = pool->owners[index] != owner ? pool->values[index] - query : INFINITY;
        }
        double size = fabs(gap);
        /* np.argmin: the first of the least (a NaN, as NumPy's, the first NaN) */
        if (look == 0 || size < best_size || (isnan(size) && !isnan(best_size))) {
            best = gap;
            best_size = size;
            best_look = padded;
        }
    }
    Py_ssize_t index = best_look < 2 || best_look >= count + 2 ? -1
        : pool->order[best_look - 2];
    if (best_size <= reach) {
        *found = index;
        *distance = best;
    } else {
        *found = -1;
        *distance = INFINITY;
    }
}

static int read_writable(PyObject *object, Py_buffer *view, int doubles, Py_ssize_t size,
                         const char *name)
{
    if (PyObject_GetBuffer(object, view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | PyBUF_WRITABLE) < 0)
        return -1;
    const char *format = view->format ? view->format : "B";
    int right = view->ndim == 1 && view->itemsize == 8 && view->shape[0] >= size
        && (doubles ? strcmp(format, "d") == 0
                    : strchr("lqn", format[0]) != NULL && format[1] == '\0');
    if (!right) {
        PyErr_Format(PyExc_TypeError, "%s: a writable %s array of at least %zd", name,
                     doubles ? "float64" : "int64", size);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

PyDoc_STRVAR(chosen_pulls_doc,
"chosen_pulls(centres, halves, rows, guides, edges_x, middles_x, edges_y, middles_y, reach,\n"
"             own, partner, factor, offset) -> kept\n\n"
"GuidePulls.refresh's choice, both axes (x first): for each of ``rows`` (the pulled rows) the\n"
"nearest line of another owner within ``reach`` to one of its features (an edge to the\n"
"``guides``' edges and the page's edge lines, its centre to their centres and the page's\n"
"middles), the edge before the centre and the low edge before the high on equal distances.\n"
"Writes, per pull kept, the flat slot pulled (row * 2 + axis), the partner's slot (the row's\n"
"own for a page line), the partner's factor (0 for a page line) and the offset, such that the\n"
"line less the feature is factor * partner + offset - own; into the four arrays (each at\n"
"least 2 * len(rows) long) from their start; returns how many it wrote.");

static PyObject *chosen_pulls(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 13) {
        PyErr_SetString(PyExc_TypeError, "chosen_pulls(centres, halves, rows, guides, edges_x, "
                        "middles_x, edges_y, middles_y, reach, own, partner, factor, offset)");
        return NULL;
    }
    double reach = PyFloat_AsDouble(args[8]);
    if (PyErr_Occurred())
        return NULL;
    Py_buffer views[12];
    int held = 0;
    PyObject *result = NULL;
    double *values = NULL;
    int64_t *owners = NULL;
    Py_ssize_t *order = NULL;
    if (read_doubles(args[0], &views[held], 2, "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (views[0].shape[1] != 2) {
        PyErr_SetString(PyExc_ValueError, "centres: (rows, 2)");
        goto done;
    }
    if (read_pairs_of(args[1], &views[held], count, "halves") < 0)
        goto done;
    held++;
    if (read_rows(args[2], &views[held], count) < 0)
        goto done;
    held++;
    if (read_rows(args[3], &views[held], count) < 0)
        goto done;
    held++;
    static const char *line_names[4] = {"edges_x", "middles_x", "edges_y", "middles_y"};
    for (int k = 0; k < 4; k++) {
        if (read_doubles(args[4 + k], &views[held], 1, line_names[k]) < 0)
            goto done;
        held++;
    }
    Py_ssize_t pulled = views[2].shape[0], guides = views[3].shape[0];
    static const char *out_names[4] = {"own", "partner", "factor", "offset"};
    for (int k = 0; k < 4; k++) {
        if (read_writable(args[9 + k], &views[held], k >= 2, 2 * pulled, out_names[k]) < 0)
            goto done;
        held++;
    }
    const double *centres = views[0].buf, *halves = views[1].buf;
    const int64_t *rows = views[2].buf, *guide_rows = views[3].buf;
    int64_t *own = views[8].buf, *partner = views[9].buf;
    double *factor = views[10].buf, *offset = views[11].buf;
    Py_ssize_t most_lines = 0;
    for (int axis = 0; axis < 2; axis++) {
        Py_ssize_t lines = 3 * guides + views[4 + 2 * axis].shape[0]
            + views[5 + 2 * axis].shape[0];
        if (lines > most_lines)
            most_lines = lines;
    }
    values = PyMem_Malloc((most_lines + 1) * sizeof(double));
    owners = PyMem_Malloc((most_lines + 1) * sizeof(int64_t));
    order = PyMem_Malloc((most_lines + 1) * sizeof(Py_ssize_t));
    if (values == NULL || owners == NULL || order == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    Py_ssize_t kept = 0;
    for (int axis = 0; axis < 2; axis++) {
        const double *page_edges = views[4 + 2 * axis].buf, *middles = views[5 + 2 * axis].buf;
        Py_ssize_t edge_count = views[4 + 2 * axis].shape[0];
        Py_ssize_t middle_count = views[5 + 2 * axis].shape[0];
        /* every line in one array as the refresh pools them: the guides' low edges, their
           high edges, the page's edge lines; then their centres and the page's middles */
        Py_ssize_t edge_lines = 2 * guides + edge_count;
        for (Py_ssize_t g = 0; g < guides; g++) {
            double theirs = centres[2 * guide_rows[g] + axis];
            double half = halves[2 * guide_rows[g] + axis];
            values[g] = theirs - half;
            values[guides + g] = theirs + half;
            values[edge_lines + g] = theirs;
            owners[g] = owners[guides + g] = owners[edge_lines + g] = guide_rows[g];
        }
        for (Py_ssize_t e = 0; e < edge_count; e++) {
            values[2 * guides + e] = page_edges[e];
            owners[2 * guides + e] = PAGE_OWNER;
        }
        for (Py_ssize_t m = 0; m < middle_count; m++) {
            values[edge_lines + guides + m] = middles[m];
            owners[edge_lines + guides + m] = PAGE_OWNER;
        }
        Pool edge_pool = {edge_lines, values, owners, order};
        Pool centre_pool = {guides + middle_count, values + edge_lines, owners + edge_lines,
                            order + edge_lines};
        sort_pool(&edge_pool);
        sort_pool(&centre_pool);
        for (Py_ssize_t k = 0; k < pulled; k++) {
            int64_t row = rows[k];
            double mine = centres[2 * row + axis], my_half = halves[2 * row + axis];
            Py_ssize_t found_low, found_high, found_centre;
            double gap_low, gap_high, gap_centre;
            nearest(&edge_pool, mine - my_half, row, reach, &found_low, &gap_low);
            nearest(&edge_pool, mine + my_half, row, reach, &found_high, &gap_high);
            int low_better = fabs(gap_low) <= fabs(gap_high);
            Py_ssize_t found_edge = low_better ? found_low : found_high;
            double gap_edge = low_better ? gap_low : gap_high;
            double own_side = low_better ? -my_half : my_half;
            nearest(&centre_pool, mine, row, reach, &found_centre, &gap_centre);
            int use_edge = fabs(gap_edge) <= fabs(gap_centre);
            Py_ssize_t found = use_edge ? found_edge : found_centre;
            if (found < 0)
                continue;
            Py_ssize_t chosen = use_edge ? found : found + edge_lines; /* into the lines */
            int64_t guide_row = owners[chosen];
            /* a guide's low edge sits at -half from its centre, its high edge at +half; a
               page line or a centre at 0 */
            double guide_side = chosen < guides ? -halves[2 * guide_row + axis]
                : chosen < 2 * guides ? halves[2 * guide_row + axis] : 0.0;
            int on_page = guide_row == PAGE_OWNER;
            own[kept] = row * 2 + axis;
            partner[kept] = (on_page ? row : guide_row) * 2 + axis;
            factor[kept] = on_page ? 0.0 : 1.0;
            offset[kept] = (on_page ? values[chosen] : guide_side) - (use_edge ? own_side : 0.0);
            kept++;
        }
    }
    result = PyLong_FromSsize_t(kept);
done:
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    PyMem_Free(values);
    PyMem_Free(owners);
    PyMem_Free(order);
    return result;
}

/* np.maximum of two floats: a NaN on either side is the answer */
static inline double larger(double a, double b)
{
    return isnan(a) || isnan(b) ? NAN : (b > a ? b : a);
}

static int read_flat(PyObject *object, Py_buffer *view, int writable, const char *name)
{
    int flags = PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0);
    if (PyObject_GetBuffer(object, view, flags) < 0)
        return -1;
    if (view->itemsize != 8 || view->format == NULL || strcmp(view->format, "d") != 0) {
        PyErr_Format(PyExc_TypeError, "%s: a C-contiguous float64 array", name);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

static int read_slots(PyObject *object, Py_buffer *view, Py_ssize_t limit, const char *name)
{
    if (PyObject_GetBuffer(object, view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
    const char *format = view->format ? view->format : "B";
    int right = view->ndim == 1 && view->itemsize == 8 && strchr("lqn", format[0]) != NULL
        && format[1] == '\0';
    for (Py_ssize_t k = 0; right && k < view->shape[0]; k++)
        right = ((const int64_t *)view->buf)[k] >= 0 && ((const int64_t *)view->buf)[k] < limit;
    if (!right) {
        PyErr_Format(PyExc_ValueError, "%s: an int64 array of slots within the page", name);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

PyDoc_STRVAR(pull_doc,
"pull(acc, centres, own, partner, factor, offset, reach, scale, apart) -> None\n\n"
"GuidePulls.pull's arithmetic, per chosen pull k (flat slots of ``acc`` and ``centres``):\n"
"distance = factor * centres[partner] + offset - centres[own], apart[k] = |distance|, and\n"
"acc[own] += scale * distance * max(1 - apart / reach, 0), ``scale`` the pull's PULL_EVERY *\n"
"k * share worked out by the caller; the same operations in the same order as the NumPy, on\n"
"the same floats (about ten NumPy calls every fourth step of a cooling page).");

static PyObject *pull(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 9) {
        PyErr_SetString(PyExc_TypeError, "pull(acc, centres, own, partner, factor, offset, "
                        "reach, scale, apart)");
        return NULL;
    }
    double reach = PyFloat_AsDouble(args[6]), scale = PyFloat_AsDouble(args[7]);
    if (PyErr_Occurred())
        return NULL;
    Py_buffer views[7];
    int held = 0;
    PyObject *result = NULL;
    if (read_flat(args[0], &views[held], 1, "acc") < 0)
        goto done;
    held++;
    if (read_flat(args[1], &views[held], 0, "centres") < 0)
        goto done;
    held++;
    Py_ssize_t slots = views[0].len / 8;
    if (views[1].len != views[0].len) {
        PyErr_SetString(PyExc_ValueError, "acc and centres: one shape");
        goto done;
    }
    if (read_slots(args[2], &views[held], slots, "own") < 0)
        goto done;
    held++;
    if (read_slots(args[3], &views[held], slots, "partner") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[2].shape[0];
    if (read_flat(args[4], &views[held], 0, "factor") < 0)
        goto done;
    held++;
    if (read_flat(args[5], &views[held], 0, "offset") < 0)
        goto done;
    held++;
    if (read_flat(args[8], &views[held], 1, "apart") < 0)
        goto done;
    held++;
    if (views[3].shape[0] != count || views[4].len / 8 != count || views[5].len / 8 != count
            || views[6].len / 8 != count) {
        PyErr_SetString(PyExc_ValueError, "own, partner, factor, offset, apart: one per pull");
        goto done;
    }
    double *acc = views[0].buf, *apart = views[6].buf;
    const double *flat = views[1].buf, *factor = views[4].buf, *offset = views[5].buf;
    const int64_t *own = views[2].buf, *partner = views[3].buf;
    for (Py_ssize_t k = 0; k < count; k++) {
        double distance = factor[k] * flat[partner[k]] + offset[k] - flat[own[k]];
        apart[k] = fabs(distance);
        double pulled = distance * larger(1.0 - apart[k] / reach, 0.0);
        acc[own[k]] += scale * pulled;
    }
    result = Py_NewRef(Py_None);
done:
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

PyDoc_STRVAR(hold_doc,
"hold(acc, holding, flat_roots, hold) -> None\n\n"
"GuidePulls.hold_on_lines' arithmetic: for each flat slot of ``holding``, the total push on\n"
"it (``acc`` at the slot, or with ``flat_roots`` the sum of every slot of its group, in\n"
"slot order from 0.0 as np.bincount sums), kept = sign(total) * max(|total| - hold, 0), and\n"
"acc[slot] += kept - total; every total worked out before any slot changes, as the NumPy's.\n"
"Asked every step of a cold page (the probes, the end of the cooling).");

static PyObject *hold(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 4) {
        PyErr_SetString(PyExc_TypeError, "hold(acc, holding, flat_roots, hold)");
        return NULL;
    }
    double strength = PyFloat_AsDouble(args[3]);
    if (PyErr_Occurred())
        return NULL;
    Py_buffer views[3];
    int held = 0;
    PyObject *result = NULL;
    double *totals = NULL;
    if (read_flat(args[0], &views[held], 1, "acc") < 0)
        goto done;
    held++;
    Py_ssize_t slots = views[0].len / 8;
    if (read_slots(args[1], &views[held], slots, "holding") < 0)
        goto done;
    held++;
    int grouped = args[2] != Py_None;
    if (grouped) {
        if (read_slots(args[2], &views[held], slots, "flat_roots") < 0)
            goto done;
        held++;
        if (views[2].shape[0] != slots) {
            PyErr_SetString(PyExc_ValueError, "flat_roots: one per slot");
            goto done;
        }
    }
    double *acc = views[0].buf;
    const int64_t *holding = views[1].buf;
    Py_ssize_t count = views[1].shape[0];
    totals = PyMem_Calloc((grouped ? slots : count) + 1, sizeof(double));
    if (totals == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    if (grouped) { /* np.bincount(flat_roots, acc, size): per slot, summed in slot order */
        const int64_t *roots = views[2].buf;
        for (Py_ssize_t k = 0; k < slots; k++)
            totals[roots[k]] += acc[k];
    }
    for (Py_ssize_t k = 0; k < count; k++) {
        double total = grouped ? totals[holding[k]] : acc[holding[k]];
        double sign = isnan(total) ? NAN : (total > 0) - (total < 0);
        double kept = sign * larger(fabs(total) - strength, 0.0);
        acc[holding[k]] += kept - total;
    }
    result = Py_NewRef(Py_None);
done:
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    PyMem_Free(totals);
    return result;
}

static PyMethodDef methods[] = {
    {"chosen_pulls", (PyCFunction)(void (*)(void))chosen_pulls, METH_FASTCALL,
     chosen_pulls_doc},
    {"pull", (PyCFunction)(void (*)(void))pull, METH_FASTCALL, pull_doc},
    {"hold", (PyCFunction)(void (*)(void))hold, METH_FASTCALL, hold_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT, "guide_pull_kernel",
    "The guide force's refresh, pull and hold, compiled (physics.guides.GuidePulls).", -1,
    methods,
};

PyMODINIT_FUNC PyInit_guide_pull_kernel(void)
{
    return PyModule_Create(&module_def);
}
