/* Whether the alignment snap's moves fit (physics.snapping, _Snapper.fits), compiled: a body
   meets a handful of neighbours and tries at most a few moves, and as Python floats (one item)
   or NumPy tables (a line) the calls cost more than the arithmetic, a tenth of the snap.  The
   same subtractions and comparisons of the same floats (tests/physics/test_snap_fits.py holds
   it to the plain definition). */

#include "snap_fit_core.h" /* fit_body, the test itself; snap_kernel_support.h */

/* ---- whether a move fits (physics.snapping._Snapper.fits) ---- */

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
    Py_buffer views[8];
    int held = 0;
    PyObject *result = NULL;
    if (read_row_pairs(args[3], &views[0], "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
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
    const double *along_table = views[5 + axis].buf, *across_table = views[5 + 1 - axis].buf;
    result = fit_body(centres, count, views[1].buf, views[1].shape[0], axis, args[2], halves,
                      lowest, highest, along_table, across_table, limits);
done:
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
