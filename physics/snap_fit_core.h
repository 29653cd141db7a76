/* Whether the alignment snap's moves fit (physics.snapping, _Snapper.fits): the test itself,
   shared by the module that exposes it to Python (snap_fit_kernel.c, fitting_shifts) and the
   compiled sweeps (snap_sweep_kernel.c), which call it directly instead of through Python (a
   call, a tuple of nine and eight buffer requests per body that tries its moves).  Each module
   includes its own copy (all static), as with snap_kernel_support.h. */

#ifndef SNAP_FIT_CORE_H
#define SNAP_FIT_CORE_H

#include "snap_kernel_support.h"

enum { CLEARANCE, FARTHEST, TOLERANCE, FIT_LIMITS };

/* fitting_shifts on raw arrays: ``count`` rows of ``centres``, ``halves``, ``lowest`` and
   ``highest`` (two per row), the snap's tables along and across ``axis`` (a row per item or
   more), ``limits`` (FIT_LIMITS), the body's ``members`` (checked to be rows by the caller)
   and ``shifts`` (a tuple of floats).  A new list of the shifts that fit, or NULL with an
   exception set. */
static PyObject *fit_body(const double *centres, Py_ssize_t count, const int64_t *members,
                          Py_ssize_t member_count, int axis, PyObject *shifts,
                          const double *halves, const double *lowest, const double *highest,
                          const double *along_table, const double *across_table,
                          const double *limits)
{
    int across_axis = 1 - axis;
    PyObject *result = NULL;
    double *work = NULL;
    Py_ssize_t shift_count = PyTuple_GET_SIZE(shifts);
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
        double shift = PyFloat_AsDouble(PyTuple_GET_ITEM(shifts, k));
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
    return result;
}

#endif
