/* The alignment snap's sweeps (physics.snapping._Snapper: improve, try_lesser, options,
   line_of, attempt and the memo, physics.snap_memo.AxisMemo), compiled.

   With the scoring, the line, the fit test and the rest check's sums compiled (the other
   *_kernel.c), what was left of a snap on the crowded pages was Python around them: the memo's
   recalls, a body's options, the choice between its move and its line's, the tries: some two
   microseconds of interpreter a call, tens of thousands of calls a snap, two thirds of its time
   on the 50- and 60-item pages of benchmarks/guide_cost.py.  Here the same decisions in the
   same order: the scoring, the line finding and the fit test are the kernels' own C
   (snap_scoring_core.h, snap_fit_core.h, included here as in their modules) called directly
   with the arguments their Python entry points get, on arrays read once per snap (through
   Python, each call's tuple and buffer requests were a fifth of its cost), the memo keeps and recalls what AxisMemo did (a span is stale once a move along its
   axis sweeps an item across it, ends included), a line stuck since the last move is not tried
   again, the first fitting move that keeps the page at rest is made, as _Snapper.apply makes
   it.  The rest check (RestCheck.keeps_rest, as_it_is) is here too, its force sums and the
   lines' hold the compiled ones it called (rest_net, held_on_lines), the pairs a body reaches
   RestCheck's own (reached_by, kept there).  tests/physics/test_snap_sweep.py holds the whole
   to _Snapper's and RestCheck's Python methods (snap_to_guides(compiled=False)), move for
   move; benchmarks/snap_identity.py to main's snaps. */

#include "snap_sweep_state.h" /* the Sweep, Moves, Span; snap_kernel_support.h */
#include "snap_scoring_core.h" /* score_body: the scoring, called without Python */
#include "snap_fit_core.h"     /* fit_body: the fit test, the same */
/* the ranges' copy holds every double of scoring_ranges (RANGES, snap_scoring_core.h) */
_Static_assert(sizeof(((Sweep *)0)->range_values) == RANGES * sizeof(double),
               "Sweep.range_values: scoring_ranges' RANGES doubles");

static void moves_clear(Moves *moves)
{
    Py_CLEAR(moves->roots);
    Py_CLEAR(moves->members);
    Py_CLEAR(moves->shifts);
}

/* AxisMemo.recall's test: no move along the axis since the span was kept swept across it */
static int still_valid(Sweep *self, int axis, Span *span)
{
    if (span->since < 0)
        return 0;
    const double *lows = self->swept_low[axis], *highs = self->swept_high[axis];
    for (Py_ssize_t k = span->since; k < self->swept_count[axis]; k++)
        if (highs[k] >= span->low && lows[k] <= span->high) {
            span->since = -1;
            return 0;
        }
    span->since = self->swept_count[axis];
    return 1;
}

static int swept(Sweep *self, int axis, double low, double high)
{
    if (self->swept_count[axis] == self->swept_room[axis]) {
        Py_ssize_t room = self->swept_room[axis] ? 2 * self->swept_room[axis] : 64;
        double *lows = PyMem_Realloc(self->swept_low[axis], room * sizeof(double));
        if (lows == NULL)
            return -1;
        self->swept_low[axis] = lows;
        double *highs = PyMem_Realloc(self->swept_high[axis], room * sizeof(double));
        if (highs == NULL)
            return -1;
        self->swept_high[axis] = highs;
        self->swept_room[axis] = room;
    }
    self->swept_low[axis][self->swept_count[axis]] = low;
    self->swept_high[axis][self->swept_count[axis]] = high;
    self->swept_count[axis]++;
    return 0;
}

/* score_moves on the table of kind ``bleed`` along ``axis`` for the body of ``rows``: fills
   ``out``'s shifts, gain, flags; returns the span read.  The scoring of snap_scoring_core.h,
   called on the cells and rows this Sweep read once (sweep_new), with the arguments
   _Snapper.options hands score_moves. */
static int scored(Sweep *self, int bleed, int axis, const int64_t *rows, Py_ssize_t n,
                  Moves *out, Span *span)
{
    if (!self->table_held[bleed][axis]) {
        PyErr_SetString(PyExc_RuntimeError, "no table of this kind");
        return -1;
    }
    if (n == 0) {
        PyErr_SetString(PyExc_ValueError, "ranges: scoring_ranges' array; members: some rows");
        return -1;
    }
    Py_buffer *view = &self->table_views[bleed][axis];
    Scored found;
    if (score_body(view->buf, view->shape[0], rows, n, self->range_values, self->candidates,
                   self->tries, &found) < 0)
        return -1;
    out->shifts = found.shifts;
    out->gain = found.gain;
    out->missing = found.missing;
    out->lined_up = found.lined_up;
    span->low = found.low;
    span->high = found.high;
    return 0;
}

/* a line's rows, its groups' in its order (np.concatenate's), in room kept by the Sweep */
static const int64_t *line_rows(Sweep *self, PyObject *roots, Py_ssize_t *n)
{
    Py_ssize_t total = 0, count = PyList_GET_SIZE(roots);
    for (Py_ssize_t k = 0; k < count; k++)
        total += self->member_sizes[PyLong_AsSsize_t(PyList_GET_ITEM(roots, k))];
    if (total > self->line_room) {
        int64_t *grown = PyMem_Realloc(self->line_room_rows, (total + 1) * sizeof(int64_t));
        if (grown == NULL) {
            PyErr_NoMemory();
            return NULL;
        }
        self->line_room_rows = grown;
        self->line_room = total;
    }
    Py_ssize_t at = 0;
    for (Py_ssize_t k = 0; k < count; k++) {
        Py_ssize_t root = PyLong_AsSsize_t(PyList_GET_ITEM(roots, k));
        memcpy(self->line_room_rows + at, self->member_rows[root],
               self->member_sizes[root] * sizeof(int64_t));
        at += self->member_sizes[root];
    }
    *n = at;
    return self->line_room_rows;
}

/* _Snapper.options([root], axis) */
static int options_alone(Sweep *self, Py_ssize_t root, int axis, Moves *out)
{
    memset(out, 0, sizeof(Moves));
    out->roots = Py_NewRef(PyList_GET_ITEM(self->root_lists, root));
    out->members = Py_NewRef(PyList_GET_ITEM(self->members, root));
    if (self->too_large[root * 2 + axis]) {
        out->shifts = PyTuple_New(0);
        return out->shifts == NULL ? -1 : 0;
    }
    Span *span = &self->alone_span[axis][root];
    Moves *known = &self->alone_value[axis][root];
    if (self->memo_on && still_valid(self, axis, span)) {
        out->shifts = Py_NewRef(known->shifts);
        out->gain = known->gain;
        out->missing = known->missing;
        out->lined_up = known->lined_up;
        return 0;
    }
    Span read;
    if (scored(self, self->bleeds[root] ? 1 : 0, axis, self->member_rows[root],
               self->member_sizes[root], out, &read) < 0)
        return -1;
    if (self->memo_on) {
        Py_XSETREF(known->shifts, Py_NewRef(out->shifts));
        known->gain = out->gain;
        known->missing = out->missing;
        known->lined_up = out->lined_up;
        span->low = read.low;
        span->high = read.high;
        span->since = self->swept_count[axis];
    }
    return 0;
}

static PyObject *sorted_key(PyObject *roots)
{
    PyObject *copy = PyList_GetSlice(roots, 0, PyList_GET_SIZE(roots));
    if (copy == NULL)
        return NULL;
    if (PyList_Sort(copy) < 0) {
        Py_DECREF(copy);
        return NULL;
    }
    PyObject *key = PyList_AsTuple(copy);
    Py_DECREF(copy);
    return key;
}

static PyObject *members_of(Sweep *self, PyObject *roots)
{
    /* np.concatenate of the groups' rows, kept per line (the same lines come back from the
       memo again and again; nothing writes into a body's rows) */
    PyObject *key = PyList_AsTuple(roots);
    if (key == NULL)
        return NULL;
    PyObject *known = PyDict_GetItemWithError(self->line_members, key);
    if (known != NULL || PyErr_Occurred()) {
        Py_DECREF(key);
        return known != NULL ? Py_NewRef(known) : NULL;
    }
    Py_ssize_t n = PyList_GET_SIZE(roots);
    PyObject *parts = PyList_New(n);
    if (parts == NULL) {
        Py_DECREF(key);
        return NULL;
    }
    for (Py_ssize_t k = 0; k < n; k++) {
        Py_ssize_t root = PyLong_AsSsize_t(PyList_GET_ITEM(roots, k));
        if (root < 0 || root >= self->count) {
            Py_DECREF(key);
            Py_DECREF(parts);
            if (!PyErr_Occurred())
                PyErr_SetString(PyExc_IndexError, "a root outside the page");
            return NULL;
        }
        PyList_SET_ITEM(parts, k, Py_NewRef(PyList_GET_ITEM(self->members, root)));
    }
    PyObject *members = PyObject_CallOneArg(self->concatenate, parts);
    Py_DECREF(parts);
    if (members != NULL && PyDict_SetItem(self->line_members, key, members) < 0)
        Py_CLEAR(members);
    Py_DECREF(key);
    return members;
}

/* _Snapper.options(roots, axis) for a line of several groups (``key``: the roots sorted) */
static int options_line(Sweep *self, PyObject *roots, PyObject *key, int axis, Moves *out)
{
    memset(out, 0, sizeof(Moves));
    Py_ssize_t n = PyList_GET_SIZE(roots);
    int all_bleed = 1, any_large = 0;
    for (Py_ssize_t k = 0; k < n; k++) {
        Py_ssize_t root = PyLong_AsSsize_t(PyList_GET_ITEM(roots, k));
        if (root < 0 || root >= self->count) {
            if (!PyErr_Occurred())
                PyErr_SetString(PyExc_IndexError, "a root outside the page");
            return -1;
        }
        any_large |= self->too_large[root * 2 + axis];
        all_bleed &= self->bleeds[root] != 0;
    }
    out->roots = Py_NewRef(roots);
    if (any_large) { /* no move to make (its members are never read) */
        out->members = Py_NewRef(Py_None);
        out->shifts = PyTuple_New(0);
        return out->shifts == NULL ? -1 : 0;
    }
    PyObject *entry = NULL;
    if (self->memo_on) {
        entry = PyDict_GetItemWithError(self->lines_known[axis], key); /* borrowed */
        if (entry == NULL && PyErr_Occurred())
            return -1;
    }
    if (entry != NULL) {
        Span span = {PyLong_AsSsize_t(PyList_GET_ITEM(entry, 0)),
                     PyFloat_AS_DOUBLE(PyList_GET_ITEM(entry, 1)),
                     PyFloat_AS_DOUBLE(PyList_GET_ITEM(entry, 2))};
        if (still_valid(self, axis, &span)) {
            PyObject *since = PyLong_FromSsize_t(span.since);
            if (since == NULL)
                return -1;
            PyList_SetItem(entry, 0, since);
            out->shifts = Py_NewRef(PyList_GET_ITEM(entry, 5));
            out->gain = PyFloat_AS_DOUBLE(PyList_GET_ITEM(entry, 6));
            out->missing = PyList_GET_ITEM(entry, 7) == Py_True;
            out->lined_up = PyList_GET_ITEM(entry, 8) == Py_True;
            int same = PyObject_RichCompareBool(PyList_GET_ITEM(entry, 3), roots, Py_EQ);
            if (same < 0)
                return -1;
            if (same)
                Py_SETREF(out->roots, Py_NewRef(PyList_GET_ITEM(entry, 3)));
            /* the rows (members_of, in the order of the roots named) are made by attempt,
               if there is a move to try: most lines have none */
            return 0;
        }
        if (PyDict_DelItem(self->lines_known[axis], key) < 0)
            return -1;
    }
    Span read;
    Py_ssize_t row_count;
    const int64_t *rows = line_rows(self, roots, &row_count);
    if (rows == NULL || scored(self, all_bleed, axis, rows, row_count, out, &read) < 0)
        return -1;
    if (self->memo_on) {
        PyObject *kept = Py_BuildValue("[ndd OOO d OO]", self->swept_count[axis], read.low,
                                       read.high, out->roots, Py_None, out->shifts,
                                       out->gain, out->missing ? Py_True : Py_False,
                                       out->lined_up ? Py_True : Py_False);
        if (kept == NULL)
            return -1;
        int failed = PyDict_SetItem(self->lines_known[axis], key, kept);
        Py_DECREF(kept);
        if (failed < 0)
            return -1;
    }
    return 0;
}

/* _Snapper.line_of(row, axis): a new reference to the list of roots */
static PyObject *line_of(Sweep *self, Py_ssize_t row, int axis)
{
    Span *span = &self->line_span[axis][row];
    PyObject **known = &self->line_value[axis][row];
    if (self->memo_on && still_valid(self, axis, span))
        return Py_NewRef(*known);
    /* line_of(item table, members, row, count, roots, movers, aligned), on the arrays read
       once (sweep_new) */
    double low = 0.0, high = 0.0;
    PyObject *line = line_body(self->line_views[axis].buf, self->count, self->member_rows[row],
                               self->member_sizes[row], row, self->line_views[2].buf,
                               self->line_views[3].buf, PyFloat_AS_DOUBLE(self->aligned), &low,
                               &high);
    if (line == NULL)
        return NULL;
    if (self->memo_on) {
        Py_XSETREF(*known, Py_NewRef(line));
        span->low = low;
        span->high = high;
        span->since = self->swept_count[axis];
    }
    return line;
}

#include "snap_sweep_rest.h"

/* _Snapper.apply: where each group was (moved_from: its members' features before the move,
   as floats in mine's order), then the centres and every table moved, each cell x + shift as
   NumPy's in-place add; the rest check's kept forces of the page as it was forgotten */
static int apply_move(Sweep *self, Moves *moves, const int64_t *rows, Py_ssize_t n, int axis,
                      double shift)
{
    PyObject *item_table = PyTuple_GET_ITEM(self->item_tables, axis);
    Py_buffer view;
    if (read_doubles(item_table, &view, 2, "item table") < 0)
        return -1;
    const double *cells = view.buf;
    for (Py_ssize_t k = 0; k < PyList_GET_SIZE(moves->roots); k++) {
        PyObject *root = PyList_GET_ITEM(moves->roots, k);
        Py_ssize_t index = PyLong_AsSsize_t(root);
        Py_buffer members;
        if (index < 0 || index >= self->count
                || read_rows(PyList_GET_ITEM(self->members, index), &members, self->count) < 0) {
            PyBuffer_Release(&view);
            if (!PyErr_Occurred())
                PyErr_SetString(PyExc_IndexError, "a root outside the page");
            return -1;
        }
        const int64_t *own = members.buf;
        PyObject *spot = PyList_New(3 * members.shape[0]);
        for (Py_ssize_t m = 0; spot != NULL && m < members.shape[0]; m++)
            for (int feature = 0; feature < 3; feature++) {
                PyObject *value = PyFloat_FromDouble(cells[own[m] * COLUMNS + feature]);
                if (value == NULL) {
                    Py_CLEAR(spot);
                    break;
                }
                PyList_SET_ITEM(spot, 3 * m + feature, value);
            }
        PyBuffer_Release(&members);
        int failed = spot == NULL || PyDict_SetItem(self->moved_from, root, spot) < 0;
        Py_XDECREF(spot);
        if (failed) {
            PyBuffer_Release(&view);
            return -1;
        }
    }
    PyBuffer_Release(&view);
    Py_buffer centres;
    if (PyObject_GetBuffer(self->centres, &centres,
                           PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | PyBUF_WRITABLE) < 0)
        return -1;
    if (centres.ndim != 2 || centres.shape[1] != 2 || centres.itemsize != 8
            || centres.shape[0] < self->count) {
        PyBuffer_Release(&centres);
        PyErr_SetString(PyExc_TypeError, "centres: (rows, 2) float64");
        return -1;
    }
    double *at = centres.buf;
    for (Py_ssize_t m = 0; m < n; m++)
        at[2 * rows[m] + axis] += shift;
    PyBuffer_Release(&centres);
    for (int bleed = 0; bleed < 2; bleed++) {
        PyObject *table = self->tables[bleed][axis];
        if (table == NULL)
            continue;
        Py_buffer cells_view;
        if (PyObject_GetBuffer(table, &cells_view,
                               PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | PyBUF_WRITABLE) < 0)
            return -1;
        double *row_cells = cells_view.buf;
        for (Py_ssize_t m = 0; m < n; m++)
            for (int column = 0; column < COLUMNS; column++)
                row_cells[rows[m] * COLUMNS + column] += shift;
        PyBuffer_Release(&cells_view);
    }
    PyDict_Clear(self->rest_before);
    return 0;
}

/* _Snapper.attempt: make the first of the moves that fits and keeps the page at rest */
static int attempt(Sweep *self, Moves *moves, PyObject *shifts, int axis)
{
    if (PyTuple_GET_SIZE(shifts) == 0)
        return 0;
    if (moves->members == NULL) { /* a line's rows as one array, made when first tried */
        moves->members = members_of(self, moves->roots);
        if (moves->members == NULL)
            return -1;
    }
    /* fitting_shifts(members, axis, shifts, *fit_args), on the arrays read once (sweep_new) */
    Py_ssize_t row_count;
    const int64_t *body_rows = line_rows(self, moves->roots, &row_count);
    if (body_rows == NULL)
        return -1;
    if (row_count == 0) {
        PyErr_SetString(PyExc_ValueError, "limits: clearance, farthest, tolerance; members: some");
        return -1;
    }
    PyObject *fitting = fit_body(
        self->fit_views[FIT_CENTRES].buf, self->count, body_rows, row_count, axis, shifts,
        self->fit_views[FIT_HALVES].buf, self->fit_views[FIT_LOWEST].buf,
        self->fit_views[FIT_HIGHEST].buf, self->fit_views[FIT_TABLE_X + axis].buf,
        self->fit_views[FIT_TABLE_X + 1 - axis].buf, self->fit_views[FIT_LIMIT_VALUES].buf);
    if (fitting == NULL)
        return -1;
    if (!PyList_Check(fitting)) {
        Py_DECREF(fitting);
        PyErr_SetString(PyExc_TypeError, "fitting_shifts: a list");
        return -1;
    }
    int made = 0;
    for (Py_ssize_t k = 0; k < PyList_GET_SIZE(fitting) && !made; k++) {
        PyObject *shift = PyList_GET_ITEM(fitting, k);
        double value = PyFloat_AsDouble(shift);
        if (value == -1.0 && PyErr_Occurred())
            goto failed;
        int keeps = fabs(value) <= self->nudge || !self->has_rest;
        if (!keeps) {
            keeps = keeps_rest(self, moves->members, axis, shift);
            if (keeps < 0)
                goto failed;
        }
        if (!keeps)
            continue;
        /* the move: AxisMemo.moved reads each member's low and high edge before and after */
        Py_buffer rows_view, table_view;
        PyObject *table = PyTuple_GET_ITEM(self->item_tables, axis);
        if (read_rows(moves->members, &rows_view, self->count) < 0)
            goto failed;
        Py_ssize_t n = rows_view.shape[0];
        double *before = PyMem_Malloc((2 * n + 1) * sizeof(double));
        if (before == NULL) {
            PyBuffer_Release(&rows_view);
            PyErr_NoMemory();
            goto failed;
        }
        const int64_t *rows = rows_view.buf;
        if (read_doubles(table, &table_view, 2, "item table") < 0) {
            PyMem_Free(before);
            PyBuffer_Release(&rows_view);
            goto failed;
        }
        const double *cells = table_view.buf;
        for (Py_ssize_t m = 0; m < n; m++) {
            before[2 * m] = cells[rows[m] * COLUMNS + LOW_EDGE];
            before[2 * m + 1] = cells[rows[m] * COLUMNS + HIGH_EDGE];
        }
        int bad = apply_move(self, moves, rows, n, axis, value) < 0;
        for (Py_ssize_t m = 0; m < n && !bad; m++) {
            /* np.minimum / np.maximum: a NaN on either side is the answer */
            double low_before = before[2 * m], high_before = before[2 * m + 1];
            double low_after = cells[rows[m] * COLUMNS + LOW_EDGE];
            double high_after = cells[rows[m] * COLUMNS + HIGH_EDGE];
            double low = isnan(low_before) || isnan(low_after) ? NAN
                : (low_after < low_before ? low_after : low_before);
            double high = isnan(high_before) || isnan(high_after) ? NAN
                : (high_after > high_before ? high_after : high_before);
            bad = swept(self, axis, low, high) < 0;
        }
        PyBuffer_Release(&table_view);
        PyBuffer_Release(&rows_view);
        PyMem_Free(before);
        if (bad)
            goto failed;
        if (self->has_rest) /* RestCheck.moved: the forces kept for the page as it was */
            memset(self->before_known, 0, self->count);
        made = 1;
    }
    Py_DECREF(fitting);
    return made;
failed:
    Py_DECREF(fitting);
    return -1;
}

static int unstick(Sweep *self)
{
    return PySet_Clear(self->stuck[0]) < 0 || PySet_Clear(self->stuck[1]) < 0 ? -1 : 0;
}

/* _Snapper.improve: a new reference to the roots moved (an empty list if none) */
static PyObject *improve(Sweep *self, Py_ssize_t row, int axis)
{
    Moves alone, together;
    memset(&together, 0, sizeof(Moves));
    PyObject *line = NULL, *line_key = NULL, *result = NULL;
    int have_together = 0;
    if (options_alone(self, row, axis, &alone) < 0)
        goto done;
    /* a group on no near miss gains nothing from its line's move, and one on no line has none */
    if (alone.missing && alone.lined_up) {
        line = line_of(self, row, axis);
        if (line == NULL)
            goto done;
        line_key = sorted_key(line);
        if (line_key == NULL)
            goto done;
        if (PyList_GET_SIZE(line) > 1) {
            int stuck = PySet_Contains(self->stuck[axis], line_key);
            if (stuck < 0)
                goto done;
            if (!stuck) {
                if (options_line(self, line, line_key, axis, &together) < 0)
                    goto done;
                have_together = 1;
            }
        }
    }
    Moves *choices[2] = {&alone, NULL};
    if (have_together) {
        if (together.gain > alone.gain) {
            choices[0] = &together;
            choices[1] = &alone;
        } else
            choices[1] = &together;
    }
    for (int k = 0; k < 2 && choices[k] != NULL; k++) {
        int made = attempt(self, choices[k], choices[k]->shifts, axis);
        if (made < 0)
            goto done;
        if (made) {
            if (unstick(self) < 0)
                goto done;
            result = Py_NewRef(choices[k]->roots);
            goto done;
        }
        if (PyList_GET_SIZE(choices[k]->roots) > 1 && PySet_Add(self->stuck[axis], line_key) < 0)
            goto done;
    }
    result = PyList_New(0);
done:
    moves_clear(&alone);
    moves_clear(&together);
    Py_XDECREF(line);
    Py_XDECREF(line_key);
    return result;
}

/* _Snapper.try_lesser */
static PyObject *try_lesser(Sweep *self, Py_ssize_t row, int axis)
{
    Moves first, every;
    memset(&every, 0, sizeof(Moves));
    PyObject *result = NULL, *rest = NULL;
    if (options_alone(self, row, axis, &first) < 0)
        goto done;
    if (PyTuple_GET_SIZE(first.shifts) < self->max_tries) {
        result = PyList_New(0);
        goto done;
    }
    /* every move, scored afresh (a throwaway memo: the kept one holds the cut lists) */
    self->memo_on = 0;
    self->tries = self->every_move;
    int failed = options_alone(self, row, axis, &every) < 0;
    self->memo_on = 1;
    self->tries = self->max_tries;
    if (failed)
        goto done;
    rest = PyTuple_GetSlice(every.shifts, self->max_tries, PyTuple_GET_SIZE(every.shifts));
    if (rest == NULL)
        goto done;
    int made = attempt(self, &every, rest, axis);
    if (made < 0)
        goto done;
    if (made) {
        if (unstick(self) < 0)
            goto done;
        result = Py_NewRef(every.roots);
    } else
        result = PyList_New(0);
done:
    moves_clear(&first);
    moves_clear(&every);
    Py_XDECREF(rest);
    return result;
}

/* the sweeps' loops over rows: [root for row in rows for root in step(row, axis)] */
static PyObject *over_rows(Sweep *self, PyObject *args,
                           PyObject *(*step)(Sweep *, Py_ssize_t, int))
{
    PyObject *rows;
    int axis;
    if (!PyArg_ParseTuple(args, "O!i", &PyList_Type, &rows, &axis))
        return NULL;
    if (axis != 0 && axis != 1) {
        PyErr_SetString(PyExc_ValueError, "axis: 0 or 1");
        return NULL;
    }
    PyObject *moved = PyList_New(0);
    if (moved == NULL)
        return NULL;
    for (Py_ssize_t k = 0; k < PyList_GET_SIZE(rows); k++) {
        Py_ssize_t row = PyLong_AsSsize_t(PyList_GET_ITEM(rows, k));
        if (row == -1 && PyErr_Occurred())
            goto failed;
        if (row < 0 || row >= self->count
                || PyList_GET_ITEM(self->members, row) == Py_None) {
            PyErr_SetString(PyExc_IndexError, "rows: movers of the page");
            goto failed;
        }
        PyObject *roots = step(self, row, axis);
        if (roots == NULL)
            goto failed;
        Py_ssize_t end = PyList_GET_SIZE(moved);
        int bad = PyList_SetSlice(moved, end, end, roots) < 0;
        Py_DECREF(roots);
        if (bad)
            goto failed;
    }
    return moved;
failed:
    Py_DECREF(moved);
    return NULL;
}

/* _Snapper.near: the movers (ascending) with a feature within ``window`` of a moved group's
   features, before its last move (moved_from) or now, on ``axis``; a row touched marks its
   group.  The same comparisons as the NumPy: a row's low edge below a spot's highest feature
   plus the window, its high edge above the spot's lowest less it. */
static PyObject *sweep_near(Sweep *self, PyObject *args)
{
    PyObject *moved;
    int axis;
    double window;
    if (!PyArg_ParseTuple(args, "O!id", &PyList_Type, &moved, &axis, &window))
        return NULL;
    if (axis != 0 && axis != 1) {
        PyErr_SetString(PyExc_ValueError, "axis: 0 or 1");
        return NULL;
    }
    Py_ssize_t spots = 2 * PyList_GET_SIZE(moved);
    if (spots == 0)
        return PyList_New(0);
    Py_buffer table_view, roots_view;
    if (read_doubles(PyTuple_GET_ITEM(self->item_tables, axis), &table_view, 2, "item table") < 0)
        return NULL;
    if (read_rows(self->roots, &roots_view, self->count) < 0) {
        PyBuffer_Release(&table_view);
        return NULL;
    }
    PyObject *result = NULL;
    double *lows = PyMem_Malloc(spots * sizeof(double)), *highs = PyMem_Malloc(spots * sizeof(double));
    char *touched = PyMem_Calloc(self->count + 1, 1);
    if (lows == NULL || highs == NULL || touched == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    if (roots_view.shape[0] != self->count || table_view.shape[1] != COLUMNS
            || table_view.shape[0] < self->count) {
        PyErr_SetString(PyExc_ValueError, "roots: one per row; the item table: a row per row");
        goto done;
    }
    const double *cells = table_view.buf;
    for (Py_ssize_t k = 0; k < spots / 2; k++) {
        Py_ssize_t root = PyLong_AsSsize_t(PyList_GET_ITEM(moved, k));
        if (root == -1 && PyErr_Occurred())
            goto done;
        if (root < 0 || root >= self->count || self->member_rows[root] == NULL) {
            PyErr_SetString(PyExc_IndexError, "moved: movers of the page");
            goto done;
        }
        PyObject *before = PyDict_GetItemWithError(self->moved_from, PyList_GET_ITEM(moved, k));
        if (before == NULL) {
            if (!PyErr_Occurred())
                PyErr_SetString(PyExc_KeyError, "moved: a group that has not moved");
            goto done;
        }
        if (!PyList_Check(before) || PyList_GET_SIZE(before) == 0) {
            PyErr_SetString(PyExc_TypeError, "moved_from: a list of floats");
            goto done;
        }
        /* min(spot) - window and max(spot) + window, the spot before, then the one now */
        double low = INFINITY, high = -INFINITY;
        for (Py_ssize_t f = 0; f < PyList_GET_SIZE(before); f++) {
            double at = PyFloat_AsDouble(PyList_GET_ITEM(before, f));
            if (at == -1.0 && PyErr_Occurred())
                goto done;
            if (at < low) low = at;
            if (at > high) high = at;
        }
        lows[2 * k] = low - window;
        highs[2 * k] = high + window;
        low = INFINITY;
        high = -INFINITY;
        for (Py_ssize_t m = 0; m < self->member_sizes[root]; m++)
            for (int feature = LOW_EDGE; feature <= HIGH_EDGE; feature++) {
                double at = cells[self->member_rows[root][m] * COLUMNS + feature];
                if (at < low) low = at;
                if (at > high) high = at;
            }
        lows[2 * k + 1] = low - window;
        highs[2 * k + 1] = high + window;
    }
    for (Py_ssize_t row = 0; row < self->count; row++) {
        double low_edge = cells[row * COLUMNS + LOW_EDGE], high_edge = cells[row * COLUMNS + HIGH_EDGE];
        for (Py_ssize_t k = 0; k < spots && !touched[row]; k++)
            touched[row] = low_edge < highs[k] && high_edge > lows[k];
    }
    const int64_t *roots = roots_view.buf;
    result = PyList_New(0);
    for (Py_ssize_t row = 0; result != NULL && row < self->count; row++) {
        if (self->member_rows[row] == NULL || !(touched[row] || touched[roots[row]]))
            continue;
        PyObject *value = PyLong_FromSsize_t(row);
        if (value == NULL || PyList_Append(result, value) < 0)
            Py_CLEAR(result);
        Py_XDECREF(value);
    }
done:
    PyMem_Free(lows);
    PyMem_Free(highs);
    PyMem_Free(touched);
    PyBuffer_Release(&roots_view);
    PyBuffer_Release(&table_view);
    return result;
}

static PyObject *sweep_improve(Sweep *self, PyObject *args)
{
    return over_rows(self, args, improve);
}

static PyObject *sweep_lesser(Sweep *self, PyObject *args)
{
    return over_rows(self, args, try_lesser);
}

static void sweep_dealloc(Sweep *self)
{
    for (int axis = 0; axis < 2; axis++) {
        for (Py_ssize_t row = 0; row < self->count; row++) {
            if (self->alone_value[axis] != NULL)
                moves_clear(&self->alone_value[axis][row]);
            if (self->line_value[axis] != NULL)
                Py_CLEAR(self->line_value[axis][row]);
        }
        PyMem_Free(self->alone_value[axis]);
        PyMem_Free(self->alone_span[axis]);
        PyMem_Free(self->line_value[axis]);
        PyMem_Free(self->line_span[axis]);
        PyMem_Free(self->swept_low[axis]);
        PyMem_Free(self->swept_high[axis]);
        Py_CLEAR(self->lines_known[axis]);
        Py_CLEAR(self->stuck[axis]);
        for (int bleed = 0; bleed < 2; bleed++) {
            if (self->table_held[bleed][axis])
                PyBuffer_Release(&self->table_views[bleed][axis]);
            self->table_held[bleed][axis] = 0;
            Py_CLEAR(self->tables[bleed][axis]);
        }
    }
    PyMem_Free(self->too_large);
    PyMem_Free(self->bleeds);
    if (self->member_rows != NULL)
        for (Py_ssize_t row = 0; row < self->count; row++)
            PyMem_Free(self->member_rows[row]);
    PyMem_Free(self->member_rows);
    PyMem_Free(self->member_sizes);
    PyMem_Free(self->line_room_rows);
    for (int k = 0; k < self->fit_held; k++)
        PyBuffer_Release(&self->fit_views[k]);
    self->fit_held = 0;
    for (int k = 0; k < self->line_held; k++)
        PyBuffer_Release(&self->line_views[k]);
    self->line_held = 0;
    Py_CLEAR(self->members);
    Py_CLEAR(self->root_lists);
    Py_CLEAR(self->item_tables);
    Py_CLEAR(self->roots);
    Py_CLEAR(self->mover_mask);
    Py_CLEAR(self->aligned);
    Py_CLEAR(self->keeps_rest);
    drop_rest(self);
    PyMem_Free(self->before_known);
    PyMem_Free(self->before_held);
    PyMem_Free(self->before_push);
    PyMem_Free(self->before_net);
    Py_CLEAR(self->line_members);
    Py_CLEAR(self->moved_from);
    Py_CLEAR(self->centres);
    Py_CLEAR(self->rest_before);
    Py_CLEAR(self->concatenate);
    Py_CLEAR(self->fit_args);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static int take_tables(PyObject *pair, PyObject **tables)
{
    if (pair == Py_None)
        return 0;
    if (!PyTuple_Check(pair) || PyTuple_GET_SIZE(pair) != 2) {
        PyErr_SetString(PyExc_TypeError, "tables: (x, y) or None");
        return -1;
    }
    tables[0] = Py_NewRef(PyTuple_GET_ITEM(pair, 0));
    tables[1] = Py_NewRef(PyTuple_GET_ITEM(pair, 1));
    return 0;
}

/* The rest check's parts (RestCheck.compiled_parts), read when the Sweep is made or, from
   their maker (DeferredRest.compiled_parts), before the first move that needs the check: a page
   whose moves are all nudges, or that has none, never builds it (physics/deferred_rest.py). */
static void drop_rest(Sweep *self)
{
    Py_CLEAR(self->reached_by);
    Py_CLEAR(self->rest_net);
    Py_CLEAR(self->net_args);
    Py_CLEAR(self->held_on_lines);
    Py_CLEAR(self->hold_args);
    Py_CLEAR(self->no_rows);
    Py_CLEAR(self->zero);
    Py_CLEAR(self->scratch_rows);
    Py_CLEAR(self->scratch_owner);
    Py_CLEAR(self->root_list);
    Py_CLEAR(self->group_rows);
    Py_CLEAR(self->pairs_of);
    Py_CLEAR(self->line_mates);
    Py_CLEAR(self->mate_args);
    Py_CLEAR(self->unlisted);
    Py_CLEAR(self->unlisted_args);
    Py_CLEAR(self->refind);
    self->rest_taken = 0;
}

static int take_rest(Sweep *self, PyObject *parts)
{
    PyObject *reached_by, *rest_net, *net_args, *held_on_lines, *hold_args, *no_rows,
        *root_list, *group_rows, *pairs_of, *scratch_rows, *scratch_owner, *mates, *mate_args,
        *unlisted, *unlisted_args, *refind;
    int grouped;
    Py_ssize_t count = self->count;
    if (!PyTuple_Check(parts)) {
        PyErr_SetString(PyExc_TypeError, "rest: the parts as a tuple");
        return -1;
    }
    if (!PyArg_ParseTuple(parts, "OOO!OO!OOOO!O!O!pddOO!OO!O:rest", &reached_by, &rest_net,
                          &PyTuple_Type, &net_args, &held_on_lines, &PyTuple_Type,
                          &hold_args, &no_rows, &scratch_rows, &scratch_owner,
                          &PyList_Type, &root_list, &PyList_Type, &group_rows,
                          &PyList_Type, &pairs_of, &grouped, &self->limit, &self->hold,
                          &mates, &PyTuple_Type, &mate_args, &unlisted, &PyTuple_Type,
                          &unlisted_args, &refind))
        return -1;
    if (PyTuple_GET_SIZE(net_args) != 5 || PyTuple_GET_SIZE(hold_args) != 7
            || PyTuple_GET_SIZE(mate_args) != 6 || PyTuple_GET_SIZE(unlisted_args) != 9
            || PyList_GET_SIZE(root_list) != count
            || PyList_GET_SIZE(group_rows) != count || PyList_GET_SIZE(pairs_of) != count) {
        PyErr_SetString(PyExc_ValueError, "rest: five net arguments, lists per row");
        return -1;
    }
    self->grouped = grouped;
    self->reached_by = Py_NewRef(reached_by);
    self->rest_net = Py_NewRef(rest_net);
    self->net_args = Py_NewRef(net_args);
    self->held_on_lines = Py_NewRef(held_on_lines);
    self->hold_args = Py_NewRef(hold_args);
    self->no_rows = Py_NewRef(no_rows);
    self->scratch_rows = Py_NewRef(scratch_rows);
    self->scratch_owner = Py_NewRef(scratch_owner);
    self->root_list = Py_NewRef(root_list);
    self->group_rows = Py_NewRef(group_rows);
    self->pairs_of = Py_NewRef(pairs_of);
    self->line_mates = Py_NewRef(mates);
    self->mate_args = Py_NewRef(mate_args);
    self->unlisted = Py_NewRef(unlisted);
    self->unlisted_args = Py_NewRef(unlisted_args);
    self->refind = Py_NewRef(refind);
    self->zero = PyFloat_FromDouble(0.0);
    if (self->zero == NULL)
        return -1;
    self->rest_taken = 1;
    return 0;
}

static PyObject *sweep_new(PyTypeObject *type, PyObject *args, PyObject *kwargs)
{
    Py_ssize_t count, candidates, max_tries, every_move;
    PyObject *members, *too_large, *bleeds, *plain, *bleeding, *item_tables, *roots, *mover_mask,
        *ranges, *aligned, *keeps_rest, *apply, *concatenate, *fit_args;
    double nudge;
    if (!PyArg_ParseTuple(args, "nO!SSOOO!OOOO!OOOO!nnnd:Sweep", &count, &PyList_Type,
                          &members, &too_large, &bleeds, &plain, &bleeding, &PyTuple_Type,
                          &item_tables, &roots, &mover_mask, &ranges, &PyFloat_Type, &aligned,
                          &keeps_rest, &apply, &concatenate,
                          &PyTuple_Type, &fit_args, &candidates, &max_tries, &every_move,
                          &nudge))
        return NULL;
    if (count < 0 || PyList_GET_SIZE(members) != count || PyBytes_GET_SIZE(too_large) != 2 * count
            || PyBytes_GET_SIZE(bleeds) != count || PyTuple_GET_SIZE(item_tables) != 2
            || PyTuple_GET_SIZE(fit_args) != 6) {
        PyErr_SetString(PyExc_ValueError, "Sweep: one entry per row (two per row of too_large)");
        return NULL;
    }
    Sweep *self = (Sweep *)type->tp_alloc(type, 0);
    if (self == NULL)
        return NULL;
    self->count = count;
    self->members = Py_NewRef(members);
    self->item_tables = Py_NewRef(item_tables);
    self->roots = Py_NewRef(roots);
    self->mover_mask = Py_NewRef(mover_mask);
    self->aligned = Py_NewRef(aligned);
    self->keeps_rest = Py_NewRef(keeps_rest);
    if (!PyTuple_Check(apply) || PyTuple_GET_SIZE(apply) != 3
            || !PyDict_Check(PyTuple_GET_ITEM(apply, 0))
            || !PyDict_Check(PyTuple_GET_ITEM(apply, 2))) {
        PyErr_SetString(PyExc_TypeError, "moved: (moved_from, centres, the rest's kept forces)");
        Py_DECREF(self);
        return NULL;
    }
    self->moved_from = Py_NewRef(PyTuple_GET_ITEM(apply, 0));
    self->centres = Py_NewRef(PyTuple_GET_ITEM(apply, 1));
    self->rest_before = Py_NewRef(PyTuple_GET_ITEM(apply, 2));
    self->concatenate = Py_NewRef(concatenate);
    self->fit_args = Py_NewRef(fit_args);
    self->candidates = candidates;
    self->max_tries = self->tries = max_tries;
    self->every_move = every_move;
    self->nudge = nudge;
    self->memo_on = 1;
    self->line_members = PyDict_New();
    if (self->line_members == NULL)
        goto failed;
    if (take_tables(plain, self->tables[0]) < 0 || take_tables(bleeding, self->tables[1]) < 0)
        goto failed;
    /* what the scoring reads, read once: every table's cells (held until the Sweep goes; the
       moves add to them in place), the ranges, each mover's rows */
    for (int bleed = 0; bleed < 2; bleed++)
        for (int axis = 0; axis < 2; axis++) {
            if (self->tables[bleed][axis] == NULL)
                continue;
            if (read_doubles(self->tables[bleed][axis], &self->table_views[bleed][axis], 2,
                             "table") < 0)
                goto failed;
            self->table_held[bleed][axis] = 1;
            if (self->table_views[bleed][axis].shape[1] != COLUMNS
                    || self->table_views[bleed][axis].shape[0] < count) {
                PyErr_SetString(PyExc_ValueError, "table: the snap's 15 columns, a row per row");
                goto failed;
            }
        }
    {
        Py_buffer range_view;
        if (read_doubles(ranges, &range_view, 1, "ranges") < 0)
            goto failed;
        int fits_ranges = range_view.shape[0] == RANGES;
        if (fits_ranges)
            memcpy(self->range_values, range_view.buf, RANGES * sizeof(double));
        PyBuffer_Release(&range_view);
        if (!fits_ranges) {
            PyErr_SetString(PyExc_ValueError, "ranges: scoring_ranges' array");
            goto failed;
        }
    }
    self->member_rows = PyMem_Calloc(count + 1, sizeof(int64_t *));
    self->member_sizes = PyMem_Calloc(count + 1, sizeof(Py_ssize_t));
    if (self->member_rows == NULL || self->member_sizes == NULL)
        goto no_memory;
    /* what the fit test reads, the same way: the centres, halves, margins (a pair per row),
       the item tables of both axes, the fit limits (moves change the centres and tables in
       place, never the arrays) */
    {
        PyObject *item_pair = PyTuple_GET_ITEM(fit_args, 4);
        if (!PyTuple_Check(item_pair) || PyTuple_GET_SIZE(item_pair) != 2) {
            PyErr_SetString(PyExc_TypeError, "fit_args: the item tables as (x, y)");
            goto failed;
        }
        PyObject *arrays[FIT_VIEWS] = {
            PyTuple_GET_ITEM(fit_args, 0), PyTuple_GET_ITEM(fit_args, 1),
            PyTuple_GET_ITEM(fit_args, 2), PyTuple_GET_ITEM(fit_args, 3),
            PyTuple_GET_ITEM(item_pair, 0), PyTuple_GET_ITEM(item_pair, 1),
            PyTuple_GET_ITEM(fit_args, 5)};
        for (int k = 0; k < FIT_VIEWS; k++) {
            if (read_doubles(arrays[k], &self->fit_views[k], k == FIT_LIMIT_VALUES ? 1 : 2,
                             "fit_args") < 0)
                goto failed;
            self->fit_held = k + 1;
            Py_buffer *view = &self->fit_views[k];
            int fits = k == FIT_LIMIT_VALUES ? view->shape[0] == FIT_LIMITS
                : k >= FIT_TABLE_X ? view->shape[0] >= count && view->shape[1] == COLUMNS
                                   : view->shape[0] == count && view->shape[1] == 2;
            if (!fits) {
                PyErr_SetString(PyExc_ValueError, "fit_args: (rows, 2) centres, halves and "
                                "margins, the snap's tables, three limits");
                goto failed;
            }
        }
    }
    /* and what finding a line reads: the item tables, the roots, the movers' marks */
    for (int k = 0; k < 4; k++) {
        PyObject *array = k < 2 ? PyTuple_GET_ITEM(item_tables, k) : k == 2 ? roots : mover_mask;
        Py_buffer *view = &self->line_views[k];
        int read = k < 2 ? read_doubles(array, view, 2, "item tables")
            : k == 2 ? read_rows(array, view, count) : read_flags(array, view, count);
        if (read < 0)
            goto failed;
        self->line_held = k + 1;
        if (k < 2 ? view->shape[0] < count || view->shape[1] != COLUMNS
                  : k == 2 && view->shape[0] != count) {
            PyErr_SetString(PyExc_ValueError, "item tables: a row per item or more; roots: one "
                            "per row");
            goto failed;
        }
    }
    for (Py_ssize_t row = 0; row < count; row++) {
        PyObject *group = PyList_GET_ITEM(members, row);
        if (group == Py_None)
            continue;
        Py_buffer rows_view;
        if (read_rows(group, &rows_view, count) < 0)
            goto failed;
        Py_ssize_t size = rows_view.shape[0];
        self->member_rows[row] = PyMem_Malloc((size + 1) * sizeof(int64_t));
        if (self->member_rows[row] == NULL) {
            PyBuffer_Release(&rows_view);
            goto no_memory;
        }
        memcpy(self->member_rows[row], rows_view.buf, size * sizeof(int64_t));
        self->member_sizes[row] = size;
        PyBuffer_Release(&rows_view);
    }
    self->too_large = PyMem_Malloc(2 * count + 1);
    self->bleeds = PyMem_Malloc(count + 1);
    self->root_lists = PyList_New(count);
    if (self->too_large == NULL || self->bleeds == NULL || self->root_lists == NULL)
        goto no_memory;
    memcpy(self->too_large, PyBytes_AS_STRING(too_large), 2 * count);
    memcpy(self->bleeds, PyBytes_AS_STRING(bleeds), count);
    if (keeps_rest != Py_None) { /* the rest check: its parts now, or their maker's later */
        self->has_rest = 1;
        self->before_known = PyMem_Calloc(count + 1, 1);
        self->before_held = PyMem_Calloc(2 * count + 2, 1);
        self->before_push = PyMem_Calloc(count + 1, sizeof(double));
        self->before_net = PyMem_Calloc(2 * count + 2, sizeof(double));
        if (self->before_known == NULL || self->before_held == NULL || self->before_push == NULL
                || self->before_net == NULL)
            goto no_memory;
        if (PyTuple_Check(keeps_rest) && take_rest(self, keeps_rest) < 0)
            goto failed;
        if (!PyTuple_Check(keeps_rest) && !PyCallable_Check(keeps_rest)) {
            PyErr_SetString(PyExc_TypeError, "keeps_rest: the rest parts, their maker or None");
            goto failed;
        }
    }
    for (Py_ssize_t row = 0; row < count; row++) {
        PyObject *list = Py_BuildValue("[n]", row);
        if (list == NULL)
            goto failed;
        PyList_SET_ITEM(self->root_lists, row, list);
    }
    for (int axis = 0; axis < 2; axis++) {
        self->alone_span[axis] = PyMem_Malloc((count + 1) * sizeof(Span));
        self->alone_value[axis] = PyMem_Calloc(count + 1, sizeof(Moves));
        self->line_span[axis] = PyMem_Malloc((count + 1) * sizeof(Span));
        self->line_value[axis] = PyMem_Calloc(count + 1, sizeof(PyObject *));
        self->lines_known[axis] = PyDict_New();
        self->stuck[axis] = PySet_New(NULL);
        if (self->alone_span[axis] == NULL || self->alone_value[axis] == NULL
                || self->line_span[axis] == NULL || self->line_value[axis] == NULL)
            goto no_memory;
        if (self->lines_known[axis] == NULL || self->stuck[axis] == NULL)
            goto failed;
        for (Py_ssize_t row = 0; row < count; row++)
            self->alone_span[axis][row].since = self->line_span[axis][row].since = -1;
    }
    return (PyObject *)self;
no_memory:
    PyErr_NoMemory();
failed:
    Py_DECREF(self);
    return NULL;
}

static PyMethodDef sweep_methods[] = {
    {"improve", (PyCFunction)sweep_improve, METH_VARARGS,
     "improve(rows, axis) -> roots moved: _Snapper.improve of each row in turn, the roots of "
     "every move made, in order"},
    {"try_lesser", (PyCFunction)sweep_lesser, METH_VARARGS,
     "try_lesser(rows, axis) -> roots moved: _Snapper.try_lesser of each row in turn"},
    {"near", (PyCFunction)sweep_near, METH_VARARGS,
     "near(moved, axis, window) -> movers: _Snapper.near of the groups moved, as a list"},
    {NULL, NULL, 0, NULL},
};

static PyTypeObject SweepType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "floatpage.physics.snap_sweep_kernel.Sweep",
    .tp_basicsize = sizeof(Sweep),
    .tp_dealloc = (destructor)sweep_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "Sweep(count, members, too_large, bleeds, tables, bleed_tables, item_tables, "
              "roots, mover_mask, ranges, aligned, "
              "keeps_rest, apply, concatenate, fit_args, candidates, max_tries, every_move, "
              "nudge): one page's snap sweeps with their memo (physics.snapping._Snapper."
              "compiled builds it).  keeps_rest: the rest check's parts (RestCheck."
              "compiled_parts), a callable that makes them, called at the first move that "
              "needs the check, or None.  Holds no reference back to a Sweep: apply and "
              "keeps_rest are the snapper's and the rest check's own.",
    .tp_methods = sweep_methods,
    .tp_new = sweep_new,
};

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT, "snap_sweep_kernel",
    "The alignment snap's sweeps and memo, compiled (physics.snapping).", -1, NULL,
};

PyMODINIT_FUNC PyInit_snap_sweep_kernel(void)
{
    if (PyType_Ready(&SweepType) < 0)
        return NULL;
    PyObject *module = PyModule_Create(&module_def);
    if (module == NULL)
        return NULL;
    if (PyModule_AddObjectRef(module, "Sweep", (PyObject *)&SweepType) < 0) {
        Py_DECREF(module);
        return NULL;
    }
    return module;
}
