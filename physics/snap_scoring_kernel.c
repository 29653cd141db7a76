/* The alignment snap's scoring (physics.snapping, _Snapper.options) and its finding of a
   group's line (_Snapper.line_of), compiled.

Why C: a scoring is a few dozen operations on arrays of tens to hundreds of floats, called
tens of thousands of times a page.  Written in NumPy each operation paid its own set-up, and
the snap cost a page of 50 items about twice its settle without guides; the pure-NumPy and
pure-Python variants were exhausted (docs/benchmarks.md, the fourteenth session's
snap_anatomy.py).  Here one call does it all, reading the snap's table through the buffer
protocol: no NumPy headers, no new dependency, only the C API.

Every float is the one the NumPy code computed: the same subtractions in float64, the same
bisections from the left ("d <= x" as "d < the next float after x"), the same ties.  The only
freedom taken is the order in which equal floats are sorted, which no result can see (both
sorts give the same sequence of values).  benchmarks/snap_identity.py checks every move of
its recorded snaps against the NumPy code's, bit for bit.

What the constants are comes from Python (snap_scoring.scoring_ranges): the twelve ends of the
distance ranges, the four window ends around a shift, the escape move, the window around a
body and the relevant distance, in one array of RANGES doubles. */

#include "snap_scoring_core.h" /* the scoring itself; snap_kernel_support.h */

/* ---- the entry points ---- */

PyDoc_STRVAR(score_moves_doc,
"score_moves(table, members, ranges, candidates, tries)\n"
"-> (shifts, gain, missing, lined_up, low, high)\n\n"
"The moves along one axis that would lower the near misses of the rigid body ``members``\n"
"(rows of ``table``, the snap's table of that axis with the page's lines below the rows),\n"
"best first, at most ``tries``; what the best gains; whether the body misses a line now and\n"
"whether it is on one; and the span [low, high] of the lines read (the memo keeps it).\n\n"
"Everything is read off the sorted distances from the body's features to the lines of the\n"
"same kind near them (the rows reaching into the body's extent widened by the window, the\n"
"body's own rows left out), by bisection: which moves to score, their scores, whether the\n"
"body misses a line now.  Distances past the relevant one only move every bisection's index\n"
"by the same count, which every range and score takes as a difference, so they are dropped\n"
"before the sort.  Of many candidates (a crowded page) only the ``candidates`` nearest 0\n"
"are scored.");

static PyObject *score_moves(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 5) {
        PyErr_SetString(PyExc_TypeError,
                        "score_moves(table, members, ranges, candidates, tries)");
        return NULL;
    }
    Py_ssize_t wanted = PyLong_AsSsize_t(args[3]);
    Py_ssize_t tries = PyLong_AsSsize_t(args[4]);
    if ((wanted == -1 || tries == -1) && PyErr_Occurred())
        return NULL;
    Py_buffer table_view, members_view, ranges_view;
    if (read_doubles(args[0], &table_view, 2, "table") < 0)
        return NULL;
    if (table_view.shape[1] != COLUMNS) {
        PyErr_SetString(PyExc_ValueError, "table: the snap's 15 columns");
        PyBuffer_Release(&table_view);
        return NULL;
    }
    Py_ssize_t rows = table_view.shape[0];
    if (read_rows(args[1], &members_view, rows) < 0) {
        PyBuffer_Release(&table_view);
        return NULL;
    }
    if (read_doubles(args[2], &ranges_view, 1, "ranges") < 0) {
        PyBuffer_Release(&table_view);
        PyBuffer_Release(&members_view);
        return NULL;
    }
    PyObject *result = NULL;
    const int64_t *members = members_view.buf;
    Py_ssize_t member_count = members_view.shape[0];
    if (ranges_view.shape[0] != RANGES || member_count == 0) {
        PyErr_SetString(PyExc_ValueError, "ranges: scoring_ranges' array; members: some rows");
        goto done;
    }
    Scored found;
    if (score_body(table_view.buf, rows, members, member_count, ranges_view.buf, wanted, tries,
                   &found) < 0)
        goto done;
    result = Py_BuildValue("(NdNNdd)", found.shifts, found.gain, PyBool_FromLong(found.missing),
                           PyBool_FromLong(found.lined_up), found.low, found.high);
done:
    PyBuffer_Release(&table_view);
    PyBuffer_Release(&members_view);
    PyBuffer_Release(&ranges_view);
    return result;
}

PyDoc_STRVAR(scored_candidates_doc,
"scored_candidates(ordered, ranges) -> (shifts, scores, missing, lined_up, now)\n\n"
"score_moves' candidates (sorted, each once) and their scores for the sorted distances\n"
"``ordered``, every one (no cut to the nearest, no choice): the units the kernel is made of,\n"
"for the tests that hold them to their plain definitions and for\n"
"benchmarks/near_miss_causes.py, which asks what each candidate would score.");

static PyObject *scored_candidates(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 2) {
        PyErr_SetString(PyExc_TypeError, "scored_candidates(ordered, ranges)");
        return NULL;
    }
    Py_buffer ordered_view, ranges_view;
    if (read_doubles(args[0], &ordered_view, 1, "ordered") < 0)
        return NULL;
    if (read_doubles(args[1], &ranges_view, 1, "ranges") < 0) {
        PyBuffer_Release(&ordered_view);
        return NULL;
    }
    PyObject *result = NULL, *shift_list = NULL, *score_list = NULL;
    const double *ordered = ordered_view.buf;
    Py_ssize_t count = ordered_view.shape[0];
    double *shifts = NULL;
    long *scores = NULL;
    if (ranges_view.shape[0] != RANGES) {
        PyErr_SetString(PyExc_ValueError, "ranges: scoring_ranges' array");
        goto done;
    }
    for (Py_ssize_t k = 1; k < count; k++)
        if (!(ordered[k - 1] <= ordered[k])) {
            PyErr_SetString(PyExc_ValueError, "ordered: sorted distances, no NaN");
            goto done;
        }
    /* room for the candidates and their spare, then the distances again with four +inf
       past them (misses_after steps four at a time) */
    shifts = PyMem_Malloc((7 * count + 6) * sizeof(double));
    scores = PyMem_Malloc((3 * count + 1) * sizeof(long));
    if (shifts == NULL || scores == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    Candidates made = candidate_shifts(ordered, count, ranges_view.buf, shifts,
                                       shifts + 3 * count + 1);
    double *padded = shifts + 6 * count + 2;
    memcpy(padded, ordered, count * sizeof(double));
    for (int pad = 0; pad < 4; pad++)
        padded[count + pad] = INFINITY;
    misses_after(padded, count, shifts, made.count, ranges_view.buf, scores);
    shift_list = PyList_New(made.count);
    score_list = PyList_New(made.count);
    if (shift_list == NULL || score_list == NULL)
        goto done;
    for (Py_ssize_t k = 0; k < made.count; k++) {
        PyObject *shift = PyFloat_FromDouble(shifts[k]), *score = PyLong_FromLong(scores[k]);
        if (shift == NULL || score == NULL) {
            Py_XDECREF(shift);
            Py_XDECREF(score);
            goto done;
        }
        PyList_SET_ITEM(shift_list, k, shift);
        PyList_SET_ITEM(score_list, k, score);
    }
    result = Py_BuildValue("(OONNl)", shift_list, score_list, PyBool_FromLong(made.missing),
                           PyBool_FromLong(made.lined_up), made.now);
done:
    Py_XDECREF(shift_list);
    Py_XDECREF(score_list);
    PyMem_Free(shifts);
    PyMem_Free(scores);
    PyBuffer_Release(&ordered_view);
    PyBuffer_Release(&ranges_view);
    return result;
}

PyDoc_STRVAR(line_of_doc,
"line_of(table, members, row, count, roots, movers, aligned) -> (line, low, high)\n\n"
"``row`` and the movers (groups whose root is marked in ``movers``) with a feature on one of\n"
"the lines of ``row``'s group (its rows ``members``) on the axis of ``table`` (an edge on an\n"
"edge, a centre on a centre: a pairing's distance within ``aligned``), in row order after\n"
"``row``; and the span [low, high] of the group's features widened by ``aligned`` (the memo\n"
"keeps it).  Read from the first ``count`` rows of the table (the items, not the page's\n"
"lines; an inactive row's lines are at +inf, on none).  Compiled for the reason the scoring\n"
"is: a third of a line's finding was NumPy's set-up.");

static PyObject *line_of(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 7) {
        PyErr_SetString(PyExc_TypeError,
                        "line_of(table, members, row, count, roots, movers, aligned)");
        return NULL;
    }
    Py_ssize_t row = PyLong_AsSsize_t(args[2]), count = PyLong_AsSsize_t(args[3]);
    double aligned = PyFloat_AsDouble(args[6]);
    if (PyErr_Occurred())
        return NULL;
    Py_buffer table_view, members_view, roots_view, movers_view;
    if (read_doubles(args[0], &table_view, 2, "table") < 0)
        return NULL;
    PyObject *result = NULL;
    int views = 1;
    if (table_view.shape[1] != COLUMNS || count < 0 || count > table_view.shape[0]
            || row < 0 || row >= count) {
        PyErr_SetString(PyExc_ValueError, "table: the snap's 15 columns, count rows or more");
        goto done;
    }
    if (read_rows(args[1], &members_view, count) < 0)
        goto done;
    views++;
    if (read_rows(args[4], &roots_view, count) < 0)
        goto done;
    views++;
    if (roots_view.shape[0] != count) {
        PyErr_SetString(PyExc_ValueError, "roots: one per row");
        goto done;
    }
    if (read_flags(args[5], &movers_view, count) < 0)
        goto done;
    views++;
    if (members_view.shape[0] == 0) {
        PyErr_SetString(PyExc_ValueError, "members: some rows");
        goto done;
    }
    double low = 0.0, high = 0.0;
    PyObject *line = line_body(table_view.buf, count, members_view.buf, members_view.shape[0],
                               row, roots_view.buf, movers_view.buf, aligned, &low, &high);
    if (line != NULL)
        result = Py_BuildValue("(Ndd)", line, low, high);
done:
    if (views > 3) PyBuffer_Release(&movers_view);
    if (views > 2) PyBuffer_Release(&roots_view);
    if (views > 1) PyBuffer_Release(&members_view);
    PyBuffer_Release(&table_view);
    return result;
}

static PyMethodDef methods[] = {
    {"score_moves", (PyCFunction)(void (*)(void))score_moves, METH_FASTCALL, score_moves_doc},
    {"scored_candidates", (PyCFunction)(void (*)(void))scored_candidates, METH_FASTCALL,
     scored_candidates_doc},
    {"line_of", (PyCFunction)(void (*)(void))line_of, METH_FASTCALL, line_of_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "floatpage.physics.snap_scoring_kernel",
    "The alignment snap's scoring and line finding, compiled (physics/snap_scoring_kernel.c).",
    0,
    methods,
};

PyMODINIT_FUNC PyInit_snap_scoring_kernel(void)
{
    return PyModule_Create(&module);
}
