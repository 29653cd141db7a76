/* What the snap's compiled modules share (snap_scoring_kernel.c, snap_fit_kernel.c,
   rest_check_kernel.c): the layout of the snap's table, the reading of NumPy arrays through
   the buffer protocol (no NumPy headers: a float64 or int64 array is a buffer of format "d"
   or "l"/"q"), and room kept between calls.  Each module gets its own copy of these (they are
   static): a module's calls never overlap, each holds the GIL throughout. */

#ifndef SNAP_KERNEL_SUPPORT_H
#define SNAP_KERNEL_SUPPORT_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* the columns of the snap's table per axis (snapping.feature_table) */
#define COLUMNS 15
#define LOW_EDGE 0
#define HIGH_EDGE 2
#define THEIRS 3 /* 3..7: a row's features as the lines others pair with */
#define MINE 8   /* 8..12: the same row's features paired as its own */
#define PAIRINGS 5
#define LOWS 13
#define HIGHS 14

/* Room kept between calls: a scoring's arrays are a few kilobytes, a line's a hundred, and
   an allocation each call cost more than the arithmetic.  Safe as plain statics: a call holds
   the GIL throughout and runs no Python code while it uses them. */
static double *scratch = NULL;
static Py_ssize_t scratch_size = 0;
static Py_ssize_t *near_rows = NULL;
static char *is_member = NULL; /* all 0 between calls */
static Py_ssize_t row_room = 0;
static long *score_room = NULL;
static Py_ssize_t score_size = 0;

static inline long *scores_for(Py_ssize_t count)
{
    if (count > score_size) {
        long *grown = PyMem_Realloc(score_room, count * sizeof(long));
        if (grown == NULL)
            return NULL;
        score_room = grown;
        score_size = count;
    }
    return score_room;
}

static inline int make_room(Py_ssize_t doubles, Py_ssize_t rows)
{
    if (doubles > scratch_size) {
        double *grown = PyMem_Realloc(scratch, doubles * sizeof(double));
        if (grown == NULL)
            return -1;
        scratch = grown;
        scratch_size = doubles;
    }
    if (rows > row_room) {
        Py_ssize_t *grown_rows = PyMem_Realloc(near_rows, rows * sizeof(Py_ssize_t));
        if (grown_rows == NULL)
            return -1;
        near_rows = grown_rows;
        char *grown_marks = PyMem_Realloc(is_member, rows);
        if (grown_marks == NULL)
            return -1;
        memset(grown_marks, 0, rows);
        is_member = grown_marks;
        row_room = rows;
    }
    return 0;
}

/* ---- reading the arguments ---- */

static inline int read_doubles(PyObject *object, Py_buffer *view, int ndim, const char *name)
{
    if (PyObject_GetBuffer(object, view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
    if (view->ndim != ndim || view->itemsize != sizeof(double) || view->format == NULL
            || strcmp(view->format, "d") != 0) {
        PyErr_Format(PyExc_TypeError, "%s: a C-contiguous float64 array of %d dimensions",
                     name, ndim);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

static inline int read_rows(PyObject *object, Py_buffer *view, Py_ssize_t limit)
{
    if (PyObject_GetBuffer(object, view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
    const char *format = view->format ? view->format : "B";
    if (view->ndim != 1 || view->itemsize != 8 || strchr("lqn", format[0]) == NULL
            || format[1] != '\0') {
        PyErr_SetString(PyExc_TypeError, "members: a contiguous int64 array of rows");
        PyBuffer_Release(view);
        return -1;
    }
    const int64_t *rows = view->buf;
    for (Py_ssize_t k = 0; k < view->shape[0]; k++)
        if (rows[k] < 0 || rows[k] >= limit) {
            PyErr_SetString(PyExc_IndexError, "members: a row outside the table");
            PyBuffer_Release(view);
            return -1;
        }
    return 0;
}

static inline int read_flags(PyObject *object, Py_buffer *view, Py_ssize_t count)
{
    if (PyObject_GetBuffer(object, view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
    if (view->ndim != 1 || view->itemsize != 1 || view->format == NULL
            || strcmp(view->format, "?") != 0 || view->shape[0] < count) {
        PyErr_SetString(PyExc_TypeError, "movers: a bool array, one per row");
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

/* A float64 (rows, 2) array: centres, sizes, halves; its rows are view->shape[0] */
static inline int read_row_pairs(PyObject *object, Py_buffer *view, const char *name)
{
    if (read_doubles(object, view, 2, name) < 0)
        return -1;
    if (view->shape[1] != 2) {
        PyErr_Format(PyExc_ValueError, "%s: (rows, 2)", name);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

static inline int read_pairs_of(PyObject *object, Py_buffer *view, Py_ssize_t rows,
                                const char *name)
{
    if (read_doubles(object, view, 2, name) < 0)
        return -1;
    if (view->shape[0] != rows || view->shape[1] != 2) {
        PyErr_Format(PyExc_ValueError, "%s: (rows, 2)", name);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

#endif
