/* Whether the alignment snap's moves fit (physics.snapping, _Snapper.fits), compiled: a body
   meets a handful of neighbours and tries at most a few moves, and as Python floats (one item)
   or NumPy tables (a line) the calls cost more than the arithmetic, a tenth of the snap.  The
   same subtractions and comparisons of the same floats (tests/physics/test_snap_fits.py holds
   it to the plain definition). */

#include "snap_kernel_support.h"

/* ---- whether a move fits (physics.snapping._Snapper.fits) ---- */

enum { CLEARANCE, FARTHEST, TOLERANCE, FIT_LIMITS };

PyDoc_STRVAR(fitting_shifts_doc,
"fitting_shifts(members, axis, shifts, centres, halves, lowest, highest, tables, limits)\n"
"-> [shift, ...]\n\n"
"The ``shifts`` (in their order) by which the rigid body ``members`` may move along ``axis``\n"
"as far as the page and its neighbours go: every member inside its margins (``lowest``,\n"
"``highest``; or no further out than it is), and no pair closer than the clearance (or than\n"
"it is now).  ``tables`` are the snap's tables of both axes (their rows' edges and extents);\n"
"``limits`` the clearance, the longest move and the tolerance.\n\n"
"Only the items a move could bring within the clearance are tested: the neighbours within\n"
"the clearance across the axis and within it and the longest move along it, each with a\n"
"millimetre to spare (on a 600-item page the test against every item was two thirds of the\n"
"snapping's time); of those, a pair (neighbour, member) is tested if the neighbour is close\n"
"to any member, across within the clearance and along within it and the longest move, and\n"
"the pair is not already apart across (max(gap along, gap across) passes whatever the\n"
"shift).  The same subtractions and comparisons of the same floats as the Python loop and\n"
"the NumPy tables it replaces (one for a body of one item, one for a line).");

static PyObject *fitting_shifts(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 9 || !PyTuple_Check(args[2]) || !PyTuple_Check(args[7])
            || PyTuple_GET_SIZE(args[7]) != 2) {
        PyErr_SetString(PyExc_TypeError, "fitting_shifts(members, axis, shifts: tuple, centres, "
                        "halves, lowest, highest, tables: (x, y), limits)");
        return NULL;
    }
    int axis = PyLong_AsLong(args[1]);
    if (axis == -1 && PyErr_Occurred())
        return NULL;
    if (axis != 0 && axis != 1) {
        PyErr_SetString(PyExc_ValueError, "axis: 0 or 1");
        return NULL;
    }
    int across_axis = 1 - axis;
    Py_buffer views[8];
    int held = 0;
    PyObject *result = NULL;
    double *work = NULL;
    if (read_doubles(args[3], &views[0], 2, "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (views[0].shape[1] != 2) {
        PyErr_SetString(PyExc_ValueError, "centres: (rows, 2)");
        goto done;
    }
    if (read_rows(args[0], &views[1], count) < 0)
        goto done;
    held++;
    if (read_pairs_of(args[4], &views[2], count, "halves") < 0)
        goto done;
    held++;
    if (read_pairs_of(args[5], &views[3], count, "lowest") < 0)
        goto done;
    held++;
    if (read_pairs_of(args[6], &views[4], count, "highest") < 0)
        goto done;
    held++;
    for (int k = 0; k < 2; k++) {
        if (read_doubles(PyTuple_GET_ITEM(args[7], k), &views[5 + k], 2, "tables") < 0)
            goto done;
        held++;
        if (views[5 + k].shape[0] < count || views[5 + k].shape[1] != COLUMNS) {
            PyErr_SetString(PyExc_ValueError, "tables: the snap's, a row per item or more");
            goto done;
        }
    }
    if (read_doubles(args[8], &views[7], 1, "limits") < 0)
        goto done;
    held++;
    if (views[7].shape[0] != FIT_LIMITS || views[1].shape[0] == 0) {
        PyErr_SetString(PyExc_ValueError, "limits: clearance, farthest, tolerance; members: some");
        goto done;
    }
    const double *centres = views[0].buf, *halves = views[2].buf;
    const double *lowest = views[3].buf, *highest = views[4].buf, *limits = views[7].buf;
    const double *along_table = views[5 + axis].buf, *across_table = views[5 + across_axis].buf;
    const int64_t *members = views[1].buf;
    Py_ssize_t member_count = views[1].shape[0], shift_count = PyTuple_GET_SIZE(args[2]);
    double clearance = limits[CLEARANCE], farthest = limits[FARTHEST];
    double tolerance = limits[TOLERANCE];
    /* work: the shifts inside the margins, then per tested pair (neighbour, member) the
       neighbour's position, the member's, their reach, the gap across and the gap needed */
    work = PyMem_Malloc((shift_count + 5 * count * member_count + 1) * sizeof(double));
    if (work == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    double *inside = work, *tests = work + shift_count;
    Py_ssize_t inside_count = 0;
    for (Py_ssize_t k = 0; k < shift_count; k++) {
        double shift = PyFloat_AsDouble(PyTuple_GET_ITEM(args[2], k));
        if (shift == -1.0 && PyErr_Occurred())
            goto done;
        int within = 1;
        for (Py_ssize_t m = 0; m < member_count && within; m++) {
            Py_ssize_t row = members[m];
            double at = centres[2 * row + axis];
            double low = lowest[2 * row + axis], high = highest[2 * row + axis];
            low = at < low ? at : low;    /* min(lowest, at) */
            high = at > high ? at : high; /* max(highest, at) */
            double moved = at + shift;
            within = low - tolerance <= moved && moved <= high + tolerance;
        }
        if (within)
            inside[inside_count++] = shift;
    }
    Py_ssize_t tested = 0;
    if (inside_count) {
        /* the neighbours: the other active rows within the clearance (and a millimetre)
           across, and within it and the longest move along (an inactive row's extent is out
           of every range) */
        double spare = clearance + 1.0, reach = spare + farthest;
        const double *across_row = across_table + members[0] * COLUMNS;
        const double *along_row = along_table + members[0] * COLUMNS;
        double low_across = across_row[LOW_EDGE], high_across = across_row[HIGH_EDGE];
        double low = along_row[LOW_EDGE], high = along_row[HIGH_EDGE];
        for (Py_ssize_t m = 1; m < member_count; m++) {
            across_row = across_table + members[m] * COLUMNS;
            along_row = along_table + members[m] * COLUMNS;
            if (across_row[LOW_EDGE] < low_across) low_across = across_row[LOW_EDGE];
            if (across_row[HIGH_EDGE] > high_across) high_across = across_row[HIGH_EDGE];
            if (along_row[LOW_EDGE] < low) low = along_row[LOW_EDGE];
            if (along_row[HIGH_EDGE] > high) high = along_row[HIGH_EDGE];
        }
        double across_high = high_across + spare, across_low = low_across - spare;
        double along_high = high + reach, along_low = low - reach;
        if (make_room(0, count) < 0) {
            PyErr_NoMemory();
            goto done;
        }
        for (Py_ssize_t m = 0; m < member_count; m++)
            is_member[members[m]] = 1;
        for (Py_ssize_t other = 0; other < count; other++) {
            across_row = across_table + other * COLUMNS;
            along_row = along_table + other * COLUMNS;
            if (!(across_row[LOWS] < across_high && across_row[HIGHS] > across_low
                  && along_row[LOWS] < along_high && along_row[HIGHS] > along_low)
                    || is_member[other])
                continue;
            double there = centres[2 * other + axis];
            double there_across = centres[2 * other + across_axis];
            int close = 0;
            Py_ssize_t first = tested;
            for (Py_ssize_t m = 0; m < member_count; m++) {
                Py_ssize_t row = members[m];
                double at = centres[2 * row + axis];
                double across = fabs(there_across - centres[2 * row + across_axis])
                                - halves[2 * other + across_axis]
                                - halves[2 * row + across_axis];
                double pair_reach = halves[2 * other + axis] + halves[2 * row + axis];
                double now = fabs(there - at) - pair_reach;
                close |= across < clearance && now < clearance + farthest;
                double needed = across > now ? across : now;      /* max(now, across) */
                needed = clearance < needed ? clearance : needed; /* min(., clearance) */
                needed -= tolerance;
                if (!(across >= needed)) { /* else every shift passes: max(gap, across) */
                    double *test = tests + 5 * tested++;
                    test[0] = there;
                    test[1] = at;
                    test[2] = pair_reach;
                    test[3] = across;
                    test[4] = needed;
                }
            }
            if (!close)
                tested = first; /* a neighbour close to no member: none of its pairs tested */
        }
        for (Py_ssize_t m = 0; m < member_count; m++)
            is_member[members[m]] = 0;
    }
    result = PyList_New(0);
    for (Py_ssize_t k = 0; result != NULL && k < inside_count; k++) {
        double shift = inside[k];
        int fits = 1;
        for (Py_ssize_t t = 0; t < tested && fits; t++) {
            const double *test = tests + 5 * t;
            double gap = fabs(test[0] - (test[1] + shift)) - test[2];
            gap = test[3] > gap ? test[3] : gap; /* max(gap along, gap across) */
            fits = gap >= test[4];
        }
        if (fits) {
            PyObject *value = PyFloat_FromDouble(shift);
            if (value == NULL || PyList_Append(result, value) < 0)
                Py_CLEAR(result);
            Py_XDECREF(value);
        }
    }
done:
    PyMem_Free(work);
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

static PyMethodDef methods[] = {
    {"fitting_shifts", (PyCFunction)(void (*)(void))fitting_shifts, METH_FASTCALL,
     fitting_shifts_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "floatpage.physics.snap_fit_kernel",
    "Whether the alignment snap's moves fit, compiled (physics/snap_fit_kernel.c).",
    0,
    methods,
};

PyMODINIT_FUNC PyInit_snap_fit_kernel(void)
{
    return PyModule_Create(&module);
}
