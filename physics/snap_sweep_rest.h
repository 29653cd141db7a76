/* The compiled sweeps' rest check (physics.rest_check.RestCheck.keeps_rest, as_it_is,
   group_sums, unheld, and LineHold.held's gather), included by snap_sweep_kernel.c: the same
   decisions on the same floats as the Python, its force sums and the lines' hold the compiled
   ones the Python called (rest_net, held_on_lines).  Asked before each move beyond NUDGE_MM;
   in Python its NumPy calls were a quarter to a half of a small page's snap. */

#ifndef SNAP_SWEEP_REST_H
#define SNAP_SWEEP_REST_H

#include "snap_sweep_state.h"

/* np.maximum of two floats: a NaN on either side is the answer */
static inline double larger(double a, double b)
{
    return isnan(a) || isnan(b) ? NAN : (b > a ? b : a);
}

/* rest_net(rows, pairs, centres, members, axis, shift, ...): per row (x, y), into ``net`` */
static int net_of(Sweep *self, PyObject *rows, PyObject *pairs, PyObject *members, int axis,
                  PyObject *shift, double *net)
{
    PyObject *args = self->net_args;
    PyObject *axis_object = PyLong_FromLong(axis);
    if (axis_object == NULL)
        return -1;
    PyObject *result = PyObject_CallFunctionObjArgs(
        self->rest_net, rows, pairs, PyTuple_GET_ITEM(args, 0), members, axis_object, shift,
        PyTuple_GET_ITEM(args, 1), PyTuple_GET_ITEM(args, 2), PyTuple_GET_ITEM(args, 3),
        PyTuple_GET_ITEM(args, 4), NULL);
    Py_DECREF(axis_object);
    if (result == NULL)
        return -1;
    Py_ssize_t n = PyList_GET_SIZE(rows);
    if (!PyList_Check(result) || PyList_GET_SIZE(result) != n) {
        Py_DECREF(result);
        PyErr_SetString(PyExc_TypeError, "rest_net: one (x, y) per row");
        return -1;
    }
    for (Py_ssize_t k = 0; k < n; k++) {
        PyObject *pair = PyList_GET_ITEM(result, k);
        net[2 * k] = PyFloat_AsDouble(PyTuple_GET_ITEM(pair, 0));
        net[2 * k + 1] = PyFloat_AsDouble(PyTuple_GET_ITEM(pair, 1));
    }
    Py_DECREF(result);
    return PyErr_Occurred() ? -1 : 0;
}

/* RestCheck.group_sums: each group's net, (len(groups), 2), from its rows' in ``rows`` order
   (np.add.at: summed from 0.0 row by row); every group one row: its own */
static int group_sums(Sweep *self, const double *per_row, PyObject *rows, const Py_ssize_t *groups,
                      Py_ssize_t group_count, double *sums)
{
    Py_ssize_t n = PyList_GET_SIZE(rows);
    if (!self->grouped) {
        memcpy(sums, per_row, 2 * n * sizeof(double));
        return 0;
    }
    double *summed = PyMem_Calloc(2 * self->count + 1, sizeof(double));
    if (summed == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    for (Py_ssize_t k = 0; k < n; k++) {
        Py_ssize_t row = PyLong_AsSsize_t(PyList_GET_ITEM(rows, k));
        Py_ssize_t root = PyLong_AsSsize_t(PyList_GET_ITEM(self->root_list, row));
        summed[2 * root] += per_row[2 * k];
        summed[2 * root + 1] += per_row[2 * k + 1];
    }
    for (Py_ssize_t g = 0; g < group_count; g++) {
        sums[2 * g] = summed[2 * groups[g]];
        sums[2 * g + 1] = summed[2 * groups[g] + 1];
    }
    PyMem_Free(summed);
    return PyErr_Occurred() ? -1 : 0;
}

/* RestCheck.unheld for one group: its largest push the lines' hold leaves */
static inline double unheld(Sweep *self, const double *acc, const char *held)
{
    double size[2];
    for (int axis = 0; axis < 2; axis++) {
        size[axis] = fabs(acc[axis]);
        if (held != NULL && held[axis])
            size[axis] = larger(size[axis] - self->hold, 0.0);
    }
    return sqrt(size[0] * size[0] + size[1] * size[1]); /* rest_check.speed_of */
}

/* LineHold.held(groups, axis, members, shift) into ``out`` (one flag per group): its rows and
   their owners (LineHold.others) written into kept int64 arrays, then held_on_lines called
   with the arguments LineHold.held gives it */
static int held_of(Sweep *self, const Py_ssize_t *groups, Py_ssize_t count, int axis,
                   PyObject *members, PyObject *shift, char *out)
{
    Py_buffer rows_view, owner_view;
    if (PyObject_GetBuffer(self->scratch_rows, &rows_view, PyBUF_C_CONTIGUOUS | PyBUF_WRITABLE) < 0)
        return -1;
    if (PyObject_GetBuffer(self->scratch_owner, &owner_view,
                           PyBUF_C_CONTIGUOUS | PyBUF_WRITABLE) < 0) {
        PyBuffer_Release(&rows_view);
        return -1;
    }
    int64_t *rows = rows_view.buf, *owner = owner_view.buf;
    Py_ssize_t room = rows_view.len / 8, n = 0;
    int status = -1;
    for (Py_ssize_t g = 0; g < count; g++) {
        PyObject *group_rows = PyList_GET_ITEM(self->group_rows, groups[g]);
        for (Py_ssize_t k = 0; k < PyList_GET_SIZE(group_rows) && n < room; k++) {
            rows[n] = PyLong_AsSsize_t(PyList_GET_ITEM(group_rows, k));
            owner[n++] = g;
        }
    }
    PyBuffer_Release(&rows_view);
    PyBuffer_Release(&owner_view);
    PyObject *rows_now = PySequence_GetSlice(self->scratch_rows, 0, n);
    PyObject *owner_now = PySequence_GetSlice(self->scratch_owner, 0, n);
    PyObject *groups_now = PyLong_FromSsize_t(count);
    PyObject *axis_now = PyLong_FromLong(axis);
    PyObject *result = NULL;
    if (rows_now != NULL && owner_now != NULL && groups_now != NULL && axis_now != NULL
            && !PyErr_Occurred()) {
        PyObject *parts = self->hold_args;
        PyObject *lines = PyTuple_GET_ITEM(parts, 4 + axis);
        PyObject *args[13] = {rows_now, owner_now, groups_now, PyTuple_GET_ITEM(parts, 0),
                              PyTuple_GET_ITEM(parts, 1), PyTuple_GET_ITEM(parts, 2),
                              PyTuple_GET_ITEM(parts, 3), PyTuple_GET_ITEM(lines, 0),
                              PyTuple_GET_ITEM(lines, 1), axis_now, members, shift,
                              PyTuple_GET_ITEM(parts, 6)};
        result = PyObject_Vectorcall(self->held_on_lines, args, 13, NULL);
    }
    if (result != NULL) {
        if (!PyList_Check(result) || PyList_GET_SIZE(result) != count)
            PyErr_SetString(PyExc_TypeError, "held_on_lines: one flag per group");
        else {
            status = 0;
            for (Py_ssize_t g = 0; g < count && status == 0; g++) {
                int flag = PyObject_IsTrue(PyList_GET_ITEM(result, g));
                if (flag < 0)
                    status = -1;
                out[g] = (char)flag;
            }
        }
    }
    Py_XDECREF(result);
    Py_XDECREF(rows_now);
    Py_XDECREF(owner_now);
    Py_XDECREF(groups_now);
    Py_XDECREF(axis_now);
    return status;
}

/* RestCheck.as_it_is for the groups not known since the last move: worked out together (one
   rest_net over their rows and pairs, as the Python did) and kept */
static int as_it_is(Sweep *self, const Py_ssize_t *groups, Py_ssize_t count)
{
    Py_ssize_t missing_count = 0;
    Py_ssize_t *missing = PyMem_Malloc((count + 1) * sizeof(Py_ssize_t));
    char *held = PyMem_Calloc(3 * count + 3, 1); /* per group and axis, then one axis's */
    double *net = NULL, *sums = NULL;
    PyObject *rows = NULL, *pair_set = NULL, *pairs = NULL;
    int status = -1;
    if (missing == NULL || held == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t g = 0; g < count; g++)
        if (!self->before_known[groups[g]])
            missing[missing_count++] = groups[g];
    if (missing_count == 0) {
        status = 0;
        goto done;
    }
    char *axis_held = held + 2 * count + 2; /* room for one axis at a time */
    if (self->hold > 0)
        for (int axis = 0; axis < 2; axis++) {
            if (held_of(self, missing, missing_count, axis, self->no_rows, self->zero,
                        axis_held) < 0)
                goto done;
            for (Py_ssize_t g = 0; g < missing_count; g++)
                held[2 * g + axis] = axis_held[g];
        }
    rows = PyList_New(0);
    pair_set = PySet_New(NULL);
    if (rows == NULL || pair_set == NULL)
        goto done;
    for (Py_ssize_t g = 0; g < missing_count; g++) {
        PyObject *group_rows = PyList_GET_ITEM(self->group_rows, missing[g]);
        for (Py_ssize_t k = 0; k < PyList_GET_SIZE(group_rows); k++) {
            PyObject *row = PyList_GET_ITEM(group_rows, k);
            if (PyList_Append(rows, row) < 0)
                goto done;
            Py_ssize_t index = PyLong_AsSsize_t(row);
            PyObject *its = PyList_GET_ITEM(self->pairs_of, index);
            for (Py_ssize_t p = 0; p < PyList_GET_SIZE(its); p++)
                if (PySet_Add(pair_set, PyList_GET_ITEM(its, p)) < 0)
                    goto done;
        }
    }
    pairs = PySequence_List(pair_set);
    if (pairs == NULL || PyList_Sort(pairs) < 0)
        goto done;
    Py_ssize_t n = PyList_GET_SIZE(rows);
    net = PyMem_Malloc((2 * n + 2) * sizeof(double));
    sums = PyMem_Malloc((2 * missing_count + 2) * sizeof(double));
    if (net == NULL || sums == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    PyObject *zero = PyFloat_FromDouble(0.0);
    if (zero == NULL)
        goto done;
    int failed = net_of(self, rows, pairs, self->no_rows, 0, zero, net) < 0;
    Py_DECREF(zero);
    if (failed || group_sums(self, net, rows, missing, missing_count, sums) < 0)
        goto done;
    for (Py_ssize_t g = 0; g < missing_count; g++) {
        Py_ssize_t group = missing[g];
        self->before_known[group] = 1;
        self->before_held[2 * group] = held[2 * g];
        self->before_held[2 * group + 1] = held[2 * g + 1];
        self->before_push[group] = unheld(self, sums + 2 * g,
                                          self->hold > 0 ? held + 2 * g : NULL);
        self->before_net[2 * group] = sums[2 * g];
        self->before_net[2 * group + 1] = sums[2 * g + 1];
    }
    status = 0;
done:
    PyMem_Free(missing);
    PyMem_Free(held);
    PyMem_Free(net);
    PyMem_Free(sums);
    Py_XDECREF(rows);
    Py_XDECREF(pair_set);
    Py_XDECREF(pairs);
    return status;
}

/* RestCheck.keeps_holds(members, axis, shift, reached): the groups held on the members' lines
   (line_mates), but those of ``reached``, each pushed within the limit or no harder than it
   was once the move has taken its line away; 1 if so, 0 if not, -1 on an error */
static int keeps_holds(Sweep *self, PyObject *members, int axis, PyObject *shift,
                       const Py_ssize_t *reached, Py_ssize_t reached_count)
{
    if (!(self->hold > 0))
        return 1;
    PyObject *axis_now = PyLong_FromLong(axis);
    if (axis_now == NULL)
        return -1;
    PyObject *parts = self->mate_args;
    PyObject *args[8] = {members, axis_now, PyTuple_GET_ITEM(parts, 0),
                         PyTuple_GET_ITEM(parts, 1), PyTuple_GET_ITEM(parts, 2),
                         PyTuple_GET_ITEM(parts, 3), PyTuple_GET_ITEM(parts, 4),
                         PyTuple_GET_ITEM(parts, 5)};
    PyObject *found = PyObject_Vectorcall(self->line_mates, args, 8, NULL);
    Py_DECREF(axis_now);
    if (found == NULL)
        return -1;
    if (!PyList_Check(found)) {
        Py_DECREF(found);
        PyErr_SetString(PyExc_TypeError, "line_mates: a list");
        return -1;
    }
    Py_ssize_t total = PyList_GET_SIZE(found), count = 0;
    Py_ssize_t *mates = PyMem_Malloc((total + 1) * sizeof(Py_ssize_t));
    char *after = PyMem_Calloc(total + 1, 1);
    int status = -1;
    if (mates == NULL || after == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t k = 0; k < total; k++) {
        Py_ssize_t group = PyLong_AsSsize_t(PyList_GET_ITEM(found, k));
        if (group < 0 || group >= self->count) {
            if (!PyErr_Occurred())
                PyErr_SetString(PyExc_IndexError, "line_mates: a group outside the page");
            goto done;
        }
        int known = 0;
        for (Py_ssize_t r = 0; r < reached_count && !known; r++)
            known = reached[r] == group;
        if (!known)
            mates[count++] = group;
    }
    status = 1;
    if (count == 0)
        goto done;
    status = -1;
    /* which still have a line after the move (held on the members' line, each was held) */
    if (held_of(self, mates, count, axis, members, shift, after) < 0)
        goto done;
    Py_ssize_t losing = 0;
    for (Py_ssize_t g = 0; g < count; g++)
        if (!after[g])
            mates[losing++] = mates[g];
    status = 1;
    if (losing == 0)
        goto done;
    status = -1;
    if (as_it_is(self, mates, losing) < 0)
        goto done;
    status = 1;
    for (Py_ssize_t g = 0; g < losing && status; g++) {
        Py_ssize_t group = mates[g];
        if (!self->before_held[2 * group + axis])
            continue; /* not losing a hold it had on this axis */
        char held[2];
        held[axis] = 0;
        held[1 - axis] = self->before_held[2 * group + 1 - axis];
        double push = unheld(self, self->before_net + 2 * group, held);
        status = push <= larger(self->before_push[group], self->limit) + 1e-9;
    }
done:
    Py_DECREF(found);
    PyMem_Free(mates);
    PyMem_Free(after);
    return status;
}


/* RestCheck.unlisted_near(members, axis, shift): 1 if the move would meet a row its pairs do
   not list, 0 if not, -1 on an error */
static int unlisted_near(Sweep *self, PyObject *members, int axis, PyObject *shift)
{
    PyObject *axis_now = PyLong_FromLong(axis);
    if (axis_now == NULL)
        return -1;
    PyObject *parts = self->unlisted_args;
    PyObject *args[12] = {members, axis_now, shift};
    for (Py_ssize_t k = 0; k < 9; k++)
        args[3 + k] = PyTuple_GET_ITEM(parts, k);
    PyObject *found = PyObject_Vectorcall(self->unlisted, args, 12, NULL);
    Py_DECREF(axis_now);
    if (found == NULL)
        return -1;
    int near = PyObject_IsTrue(found);
    Py_DECREF(found);
    return near;
}

/* RestCheck.keeps_rest(members, axis, shift) */
static int keeps_rest(Sweep *self, PyObject *members, int axis, PyObject *shift)
{
    if (!self->rest_taken) { /* the first move that asks: the check is built now */
        PyObject *parts = PyObject_CallNoArgs(self->keeps_rest);
        if (parts == NULL)
            return -1;
        int taken = take_rest(self, parts);
        Py_DECREF(parts);
        if (taken < 0)
            return -1;
    }
    int unlisted = unlisted_near(self, members, axis, shift);
    if (unlisted < 0)
        return -1;
    if (unlisted) { /* the pairs found again where the items are now: RestCheck.refind */
        PyObject *parts = PyObject_CallNoArgs(self->refind);
        if (parts == NULL)
            return -1;
        drop_rest(self);
        int taken = take_rest(self, parts);
        Py_DECREF(parts);
        if (taken < 0)
            return -1;
        memset(self->before_known, 0, self->count);
    }
    PyObject *found = PyObject_CallOneArg(self->reached_by, members);
    if (found == NULL)
        return -1;
    int status = -1;
    Py_ssize_t *groups = NULL, *failing = NULL;
    double *per_row = NULL, *after = NULL;
    char *held = NULL;
    Py_buffer view;
    if (!PyTuple_Check(found) || PyTuple_GET_SIZE(found) != 3
            || PyObject_GetBuffer(PyTuple_GET_ITEM(found, 0), &view,
                                  PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0) {
        if (!PyErr_Occurred())
            PyErr_SetString(PyExc_TypeError, "reached_by: (groups, rows, pairs)");
        Py_DECREF(found);
        return -1;
    }
    Py_ssize_t count = view.ndim == 1 ? view.shape[0] : 0;
    if (view.itemsize != 8) {
        PyErr_SetString(PyExc_TypeError, "reached_by: int64 groups");
        goto done;
    }
    if (count == 0) {
        status = keeps_holds(self, members, axis, shift, NULL, 0);
        goto done;
    }
    groups = PyMem_Malloc(count * sizeof(Py_ssize_t));
    failing = PyMem_Malloc(count * sizeof(Py_ssize_t));
    PyObject *rows = PyTuple_GET_ITEM(found, 1), *pairs = PyTuple_GET_ITEM(found, 2);
    Py_ssize_t n = PyList_GET_SIZE(rows);
    per_row = PyMem_Malloc((2 * n + 2) * sizeof(double));
    after = PyMem_Malloc((2 * count + 2) * sizeof(double));
    held = PyMem_Calloc(3 * count + 3, 1); /* per group and axis, then the moved axis's */
    if (groups == NULL || failing == NULL || per_row == NULL || after == NULL || held == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t g = 0; g < count; g++)
        groups[g] = (Py_ssize_t)((const int64_t *)view.buf)[g];
    if (net_of(self, rows, pairs, members, axis, shift, per_row) < 0)
        goto done;
    if (group_sums(self, per_row, rows, groups, count, after) < 0)
        goto done;
    double limit = self->limit + 1e-9;
    Py_ssize_t over = 0;
    for (Py_ssize_t g = 0; g < count; g++) {
        double x = after[2 * g], y = after[2 * g + 1];
        double size = sqrt(x * x + y * y); /* rest_check.speed_of */
        if (size > limit) {
            after[2 * over] = after[2 * g];
            after[2 * over + 1] = after[2 * g + 1];
            failing[over++] = groups[g];
        }
    }
    if (over == 0) { /* within the limit with no hold at all: which lines hold is moot */
        status = keeps_holds(self, members, axis, shift, groups, count);
        goto done;
    }
    /* only a group over the limit may fail: the hold only lowers a push */
    if (as_it_is(self, failing, over) < 0)
        goto done;
    if (self->hold > 0) {
        char *moved = held + 2 * count + 2;
        if (held_of(self, failing, over, axis, members, shift, moved) < 0)
            goto done;
        for (Py_ssize_t g = 0; g < over; g++) {
            held[2 * g] = self->before_held[2 * failing[g]];
            held[2 * g + 1] = self->before_held[2 * failing[g] + 1];
            held[2 * g + axis] = moved[g];
        }
    }
    status = 1;
    for (Py_ssize_t g = 0; g < over && status; g++) {
        double push = unheld(self, after + 2 * g, self->hold > 0 ? held + 2 * g : NULL);
        double before = larger(self->before_push[failing[g]], self->limit);
        status = push <= before + 1e-9;
    }
    if (status == 1)
        status = keeps_holds(self, members, axis, shift, groups, count);
done:
    PyBuffer_Release(&view);
    Py_DECREF(found);
    PyMem_Free(groups);
    PyMem_Free(failing);
    PyMem_Free(per_row);
    PyMem_Free(after);
    PyMem_Free(held);
    return status;
}

#endif
