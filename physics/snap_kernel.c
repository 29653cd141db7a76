/* The alignment snap's scoring (physics.snapping, _Snapper.options), its finding of a group's
   line (_Snapper.line_of), its test of whether a move fits (_Snapper.fits) and its rest
   check's force sum and line hold (physics.rest_check, physics.line_hold), compiled.

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
63 snaps against the NumPy code's, bit for bit.

What the constants are comes from Python (snap_scoring.scoring_ranges): the twelve ends of the
distance ranges, the four window ends around a shift, the escape move, the window around a
body and the relevant distance, in one array of RANGES doubles. */

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
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

/* snap_scoring.scoring_ranges' layout */
#define BOUNDS 0       /* 12 needles, distance_bounds */
#define WINDOW_ENDS 12 /* 4: + NEAR, - ALIGNED, - NEAR, + ALIGNED around a shift */
#define ESCAPE 16      /* the escape move, ESCAPE_MM */
#define WINDOW 17      /* how far beyond a body's edges its near lines reach */
#define RELEVANT 18    /* relevant_distance: no range reads a distance this far */
#define RANGES 19

/* ---- sorting doubles (no NaN reaches here: the cut to the relevant drops them) ---- */

static void insertion_sort(double *values, Py_ssize_t count)
{
    for (Py_ssize_t i = 1; i < count; i++) {
        double value = values[i];
        Py_ssize_t j = i;
        while (j > 0 && values[j - 1] > value) {
            values[j] = values[j - 1];
            j--;
        }
        values[j] = value;
    }
}

static void sort_doubles(double *values, Py_ssize_t count)
{
    /* a quicksort (Hoare's partition about the median of the first, middle and last values,
       moved to the middle so that both parts are never empty), insertion sort below 16
       values; the smaller part is recursed into and the larger looped over */
    while (count > 16) {
        Py_ssize_t middle = count / 2, i = -1, j = count;
        double swap;
#define SWAP(a, b) (swap = values[a], values[a] = values[b], values[b] = swap)
        if (values[middle] < values[0])
            SWAP(0, middle);
        if (values[count - 1] < values[middle]) {
            SWAP(middle, count - 1);
            if (values[middle] < values[0])
                SWAP(0, middle);
        }
        double pivot = values[middle];
        for (;;) {
            do i++; while (values[i] < pivot);
            do j--; while (values[j] > pivot);
            if (i >= j)
                break;
            SWAP(i, j);
        }
#undef SWAP
        Py_ssize_t left = j + 1; /* values[:left] <= pivot <= values[left:] */
        if (left < count - left) {
            sort_doubles(values, left);
            values += left;
            count -= left;
        } else {
            sort_doubles(values + left, count - left);
            count = left;
        }
    }
    insertion_sort(values, count);
}

/* np.searchsorted(ordered, needle) from the left: how many values are below needle.  Without
   branches (a conditional move per step): a scoring makes hundreds of these bisections, and
   their comparisons are the kind a branch predictor cannot guess. */
static Py_ssize_t below(const double *ordered, Py_ssize_t count, double needle)
{
    if (count == 0)
        return 0;
    const double *base = ordered;
    while (count > 1) {
        Py_ssize_t half = count / 2;
        base = base[half - 1] < needle ? base + half : base;
        count -= half;
    }
    return (base - ordered) + (base[0] < needle);
}

/* nextafter(x, +inf) without the library call (a scoring makes a hundred): the next float up
   in the bits, towards 0 for a negative x */
static inline double next_up(double x)
{
    if (x != x || x == INFINITY)
        return x;
    if (x == 0.0)
        return 4.9406564584124654e-324; /* the least subnormal, from 0 and -0 alike */
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    bits += x > 0.0 ? 1 : -1;
    memcpy(&x, &bits, sizeof x);
    return x;
}

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

static long *scores_for(Py_ssize_t count)
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

static int make_room(Py_ssize_t doubles, Py_ssize_t rows)
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

/* ---- the units of a scoring, each as its NumPy ancestor's docstring had it ---- */

typedef struct {
    Py_ssize_t count;  /* candidate shifts, sorted, each once */
    int missing;       /* a feature misses a line now: ALIGNED_MM < |distance| < NEAR_MM */
    int lined_up;      /* a feature is on a line now: |distance| <= ALIGNED_MM */
    long now;          /* staying's score (misses_after of 0) */
} Candidates;

/* Two ascending runs merged into ``into``; returns its length. */
static Py_ssize_t merged(const double *a, Py_ssize_t a_count, const double *b,
                         Py_ssize_t b_count, double *into)
{
    Py_ssize_t i = 0, j = 0, n = 0;
    while (i < a_count && j < b_count)
        into[n++] = b[j] < a[i] ? b[j++] : a[i++];
    while (i < a_count)
        into[n++] = a[i++];
    while (j < b_count)
        into[n++] = b[j++];
    return n;
}

/* Shifts that put a feature on a line at one of the sorted distances ``ordered`` from it
   within reach, or put it just out of a near miss with one (ESCAPE_MM) within ``farthest``,
   and 0 (staying); sorted, each once.  The way out of a near miss may be long: two items of
   nearly the same width cannot line up both edges and centre, and one 1 mm from the other
   stays in near misses until it has moved 4-5 mm.  Each range of distances (the twelve
   needles of distance_bounds, with the reach and the farthest move there) is a slice of the
   sorted ones, so the escape moves need no test of their length, and each kind of move is an
   ascending run (a distance less or plus ESCAPE_MM keeps the order): the candidates are
   merged, not sorted.  Their order and repeats change no choice (best_first orders the moves
   by their keys, each once; staying, and any move of 0 or -0, scores what staying does and is
   never chosen), so they are kept sorted and once, which lets misses_after sweep instead of
   bisect.  ``shifts`` and ``spare`` hold room for 3 * count + 1 each. */
static Candidates candidate_shifts(const double *ordered, Py_ssize_t count,
                                   const double *ranges, double *shifts, double *spare)
{
    Py_ssize_t found[12];
    for (int k = 0; k < 12; k++)
        found[k] = below(ordered, count, ranges[BOUNDS + k]);
    const Py_ssize_t *low = found, *high = found + 4;
    double escape = ranges[ESCAPE];
    Candidates made;
    /* the runs, one after the other in spare: staying; |distance| <= reach; of |distance| <
       farthest + ESCAPE_MM, those whose escape down, then up, stays within farthest */
    Py_ssize_t n = 0, run[4]; /* run[1..3]: where the three runs after staying end */
    spare[n++] = 0.0;
    for (Py_ssize_t i = low[0]; i < high[0]; i++)
        spare[n++] = ordered[i];
    run[1] = n;
    Py_ssize_t start = high[1] > found[8] ? high[1] : found[8];
    Py_ssize_t stop = low[1] < found[9] ? low[1] : found[9];
    for (Py_ssize_t i = start; i < stop; i++)
        spare[n++] = ordered[i] - escape;
    run[2] = n;
    start = high[1] > found[10] ? high[1] : found[10];
    stop = low[1] < found[11] ? low[1] : found[11];
    for (Py_ssize_t i = start; i < stop; i++)
        spare[n++] = ordered[i] + escape;
    run[3] = n;
    /* merged pairwise into shifts, then the halves back into spare, then each value once */
    Py_ssize_t half = merged(spare, 1, spare + 1, run[1] - 1, shifts);
    merged(spare + run[1], run[2] - run[1], spare + run[2], run[3] - run[2], shifts + half);
    merged(shifts, half, shifts + half, n - half, spare);
    Py_ssize_t kept = 1;
    shifts[0] = spare[0];
    for (Py_ssize_t i = 1; i < n; i++)
        if (spare[i] != shifts[kept - 1])
            shifts[kept++] = spare[i];
    made.count = kept;
    made.missing = low[2] > high[2] || low[3] > high[3];
    made.lined_up = high[3] > low[2]; /* -ALIGNED_MM <= distance <= ALIGNED_MM */
    /* staying's score: its four window ends are among the ranges' ends */
    made.now = 2 * (long)low[3] + 3 * (long)low[2] - 2 * (long)high[2] - 3 * (long)high[3];
    return made;
}

/* For each of the sorted ``shifts``, the near misses between a body's features and the lines
   of the same kind at the sorted distances ``ordered`` from them (one per pair), less
   ALIGN_GAIN per exact alignment, twice, in integers.  Counted at the four ends around the
   shift: d < shift + NEAR, d < shift - ALIGNED, d <= shift - NEAR, d <= shift + ALIGNED, the
   last two as "d < the next float after" (weights 2, 3, -2, -3: twice 1 and 1 + ALIGN_GAIN);
   each end, a rounded sum, grows with the shift, so each count is a sweep of the distances
   from where the last shift's stopped (the same counts as a bisection, in a pass). */
static void misses_after(const double *ordered, Py_ssize_t count, const double *shifts,
                         Py_ssize_t shift_count, const double *ranges, long *scores)
{
    static const long weights[4] = {2, 3, -2, -3};
    for (Py_ssize_t k = 0; k < shift_count; k++)
        scores[k] = 0;
    for (int end = 0; end < 4; end++) {
        double at = ranges[WINDOW_ENDS + end];
        long weight = weights[end];
        Py_ssize_t i = 0;
        for (Py_ssize_t k = 0; k < shift_count; k++) {
            double needle = at + shifts[k];
            if (end >= 2)
                needle = next_up(needle);
            while (i < count && ordered[i] < needle)
                i++;
            scores[k] += weight * (long)i;
        }
    }
}

/* The ``wanted`` shifts of ``distinct`` (sorted, each once) nearest to 0, of two as near the
   lower first, in ascending order: the nearest values of a sorted array are a run of it, the
   first run whose left end is no farther from 0 than the value just past its right end, found
   by bisection.  Returns where the run starts (it is min(count, wanted) long). */
static Py_ssize_t nearest_shifts(const double *distinct, Py_ssize_t count, Py_ssize_t wanted)
{
    Py_ssize_t low = 0, high = count > wanted ? count - wanted : 0;
    while (low < high) {
        Py_ssize_t middle = (low + high) / 2;
        if (fabs(distinct[middle]) > fabs(distinct[middle + wanted]))
            low = middle + 1;
        else
            high = middle;
    }
    return low;
}

typedef struct {
    long score;
    double shift;
    Py_ssize_t order; /* its place among the candidates: equal keys keep it (a stable sort) */
} Move;

static int better_move(const void *a, const void *b)
{
    const Move *x = a, *y = b;
    if (x->score != y->score)
        return x->score < y->score ? -1 : 1;
    double length_x = fabs(x->shift), length_y = fabs(y->shift);
    if (length_x != length_y)
        return length_x < length_y ? -1 : 1;
    if (x->shift != y->shift)
        return x->shift < y->shift ? -1 : 1;
    return x->order < y->order ? -1 : (x->order > y->order);
}

/* The moves that lower the score below ``now``, best first: the fewest misses, then the
   shortest move, then the lower; each once (a shift named twice has one score, so its copies
   sort side by side), at most ``tries``.  Returns the tuple of shifts and sets ``best`` to the
   best score; an empty tuple if none lowers it. */
static PyObject *best_first(const double *shifts, const long *scores, Py_ssize_t count,
                            long now, Py_ssize_t tries, long *best)
{
    Py_ssize_t better = 0;
    for (Py_ssize_t k = 0; k < count; k++)
        better += scores[k] < now;
    if (better == 0)
        return PyTuple_New(0);
    Move *moves = PyMem_Malloc(better * sizeof(Move));
    if (moves == NULL)
        return PyErr_NoMemory();
    Py_ssize_t n = 0;
    for (Py_ssize_t k = 0; k < count; k++)
        if (scores[k] < now) {
            moves[n].score = scores[k];
            moves[n].shift = shifts[k];
            moves[n].order = n;
            n++;
        }
    qsort(moves, n, sizeof(Move), better_move);
    *best = moves[0].score;
    Py_ssize_t kept = 0; /* the chosen written over the sorted moves, never ahead of them */
    for (Py_ssize_t k = 0; k < n && kept < tries; k++)
        if (kept == 0 || moves[k].shift != moves[kept - 1].shift)
            moves[kept++].shift = moves[k].shift;
    PyObject *found = PyTuple_New(kept);
    for (Py_ssize_t k = 0; found != NULL && k < kept; k++) {
        PyObject *value = PyFloat_FromDouble(moves[k].shift);
        if (value == NULL)
            Py_CLEAR(found);
        else
            PyTuple_SET_ITEM(found, k, value);
    }
    PyMem_Free(moves);
    return found;
}

/* ---- reading the arguments ---- */

static int read_doubles(PyObject *object, Py_buffer *view, int ndim, const char *name)
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

static int read_rows(PyObject *object, Py_buffer *view, Py_ssize_t limit)
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
    const double *table = table_view.buf, *ranges = ranges_view.buf;
    const int64_t *members = members_view.buf;
    Py_ssize_t member_count = members_view.shape[0];
    if (ranges_view.shape[0] != RANGES || member_count == 0) {
        PyErr_SetString(PyExc_ValueError, "ranges: scoring_ranges' array; members: some rows");
        goto done;
    }
    /* the body's extent widened by the window: the lines near it reach into it */
    double low = table[members[0] * COLUMNS + LOW_EDGE];
    double high = table[members[0] * COLUMNS + HIGH_EDGE];
    for (Py_ssize_t k = 1; k < member_count; k++) {
        double member_low = table[members[k] * COLUMNS + LOW_EDGE];
        double member_high = table[members[k] * COLUMNS + HIGH_EDGE];
        if (member_low < low) low = member_low;
        if (member_high > high) high = member_high;
    }
    low -= ranges[WINDOW];
    high += ranges[WINDOW];
    /* the rows near the body, its own left out; then room for the distances and twice for
       the candidates (at most 3 per distance, and staying) */
    if (make_room(0, rows) < 0) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t k = 0; k < member_count; k++)
        is_member[members[k]] = 1;
    Py_ssize_t near = 0;
    for (Py_ssize_t row = 0; row < rows; row++) {
        const double *line = table + row * COLUMNS;
        if (line[LOWS] < high && line[HIGHS] > low && !is_member[row])
            near_rows[near++] = row;
    }
    for (Py_ssize_t k = 0; k < member_count; k++)
        is_member[members[k]] = 0;
    Py_ssize_t room = member_count * near * PAIRINGS;
    if (make_room(7 * room + 2, rows) < 0) {
        PyErr_NoMemory();
        goto done;
    }
    double *ordered = scratch, *shifts = scratch + room, *spare = shifts + 3 * room + 1;
    double relevant = ranges[RELEVANT];
    Py_ssize_t count = 0;
    for (Py_ssize_t k = 0; k < member_count; k++) {
        const double *mine = table + members[k] * COLUMNS + MINE;
        for (Py_ssize_t n = 0; n < near; n++) {
            const double *theirs = table + near_rows[n] * COLUMNS + THEIRS;
            for (int pairing = 0; pairing < PAIRINGS; pairing++) {
                double distance = theirs[pairing] - mine[pairing];
                ordered[count] = distance;
                count += fabs(distance) < relevant;
            }
        }
    }
    sort_doubles(ordered, count);
    Candidates made = candidate_shifts(ordered, count, ranges, shifts, spare);
    Py_ssize_t first = 0, scored = made.count;
    if (scored > wanted) { /* perhaps a crowded page: the nearest lines only */
        first = nearest_shifts(shifts, scored, wanted);
        scored = wanted;
    }
    long *scores = scores_for(scored + 1);
    if (scores == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    misses_after(ordered, count, shifts + first, scored, ranges, scores);
    long best = made.now;
    PyObject *chosen = best_first(shifts + first, scores, scored, made.now, tries, &best);
    if (chosen == NULL)
        goto done;
    result = Py_BuildValue("(NdNNdd)", chosen, (made.now - best) / 2.0,
                           PyBool_FromLong(made.missing), PyBool_FromLong(made.lined_up),
                           low, high);
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
    shifts = PyMem_Malloc((6 * count + 2) * sizeof(double));
    scores = PyMem_Malloc((3 * count + 1) * sizeof(long));
    if (shifts == NULL || scores == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    Candidates made = candidate_shifts(ordered, count, ranges_view.buf, shifts,
                                       shifts + 3 * count + 1);
    misses_after(ordered, count, shifts, made.count, ranges_view.buf, scores);
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

static int read_flags(PyObject *object, Py_buffer *view, Py_ssize_t count)
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
    if (make_room(0, count) < 0) {
        PyErr_NoMemory();
        goto done;
    }
    const double *table = table_view.buf;
    const int64_t *members = members_view.buf, *roots = roots_view.buf;
    const char *movers = movers_view.buf;
    Py_ssize_t member_count = members_view.shape[0];
    double low = INFINITY, high = -INFINITY;
    for (Py_ssize_t k = 0; k < member_count; k++)
        for (int feature = LOW_EDGE; feature <= HIGH_EDGE; feature++) {
            double at = table[members[k] * COLUMNS + feature];
            if (at < low) low = at;
            if (at > high) high = at;
        }
    /* is_member marks the roots found (all 0 again before returning) */
    Py_ssize_t found = 0;
    for (Py_ssize_t other = 0; other < count; other++) {
        Py_ssize_t root = roots[other];
        if (root == row || !movers[root] || is_member[root])
            continue;
        const double *theirs = table + other * COLUMNS + THEIRS;
        int on = 0;
        for (Py_ssize_t k = 0; k < member_count && !on; k++) {
            const double *mine = table + members[k] * COLUMNS + MINE;
            for (int pairing = 0; pairing < PAIRINGS; pairing++)
                on |= fabs(theirs[pairing] - mine[pairing]) <= aligned;
        }
        if (on) {
            is_member[root] = 1;
            found++;
        }
    }
    PyObject *line = PyList_New(found + 1);
    if (line == NULL)
        goto unmark;
    PyList_SET_ITEM(line, 0, PyLong_FromSsize_t(row));
    for (Py_ssize_t other = 0, n = 1; other < count && n <= found; other++)
        if (is_member[other])
            PyList_SET_ITEM(line, n++, PyLong_FromSsize_t(other));
    for (Py_ssize_t k = 0; k <= found; k++)
        if (PyList_GET_ITEM(line, k) == NULL) {
            Py_CLEAR(line);
            break;
        }
    if (line != NULL)
        result = Py_BuildValue("(Ndd)", line, low - aligned, high + aligned);
unmark:
    for (Py_ssize_t other = 0; other < count; other++)
        is_member[other] = 0;
done:
    if (views > 3) PyBuffer_Release(&movers_view);
    if (views > 2) PyBuffer_Release(&roots_view);
    if (views > 1) PyBuffer_Release(&members_view);
    PyBuffer_Release(&table_view);
    return result;
}

/* ---- whether a move fits (physics.snapping._Snapper.fits) ---- */

enum { CLEARANCE, FARTHEST, TOLERANCE, FIT_LIMITS };

static int read_pairs_of(PyObject *object, Py_buffer *view, Py_ssize_t rows, const char *name)
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

/* ---- which groups a guide line holds (physics.line_hold.LineHold.held) ---- */

PyDoc_STRVAR(held_on_lines_doc,
"held_on_lines(rows, owner, groups, centres, halves, active_rows, roots, page_edges,\n"
"              page_middles, axis, members, shift, on_line) -> [bool per group]\n\n"
"Whether a line holds each group on ``axis`` (``rows`` its rows, ``owner`` each row's group\n"
"index, ``groups`` how many), with ``members`` moved by ``shift`` along the axis: an edge of\n"
"one of its rows within ``on_line`` of an edge of an active row of another group or of one of\n"
"the page's edge lines, or its centre within it of another group's centre or of the page's\n"
"middle (physics.guides).  Every line is worked out from the centres as the kept lines were\n"
"(a centre less or plus its half), the moved rows' from their moved centres, so every answer\n"
"is the same; compiled: the rest check asks it of every group a move pushes too hard, for\n"
"the page as it is and with the move made.");

static PyObject *held_on_lines(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 13) {
        PyErr_SetString(PyExc_TypeError, "held_on_lines(rows, owner, groups, centres, halves, "
                        "active_rows, roots, page_edges, page_middles, axis, members, shift, "
                        "on_line)");
        return NULL;
    }
    Py_ssize_t groups = PyLong_AsSsize_t(args[2]);
    int axis = PyLong_AsLong(args[9]);
    double shift = PyFloat_AsDouble(args[11]), on_line = PyFloat_AsDouble(args[12]);
    if (PyErr_Occurred())
        return NULL;
    if ((axis != 0 && axis != 1) || groups < 0) {
        PyErr_SetString(PyExc_ValueError, "axis: 0 or 1; groups: a count");
        return NULL;
    }
    Py_buffer views[9];
    int held = 0;
    PyObject *result = NULL;
    double *lines = NULL;
    char *found = NULL;
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
    if (read_rows(args[1], &views[2], groups ? groups : 1) < 0)
        goto done;
    held++;
    if (read_pairs_of(args[4], &views[3], count, "halves") < 0)
        goto done;
    held++;
    if (read_rows(args[5], &views[4], count) < 0)
        goto done;
    held++;
    if (read_rows(args[6], &views[5], count) < 0)
        goto done;
    held++;
    if (read_doubles(args[7], &views[6], 1, "page_edges") < 0)
        goto done;
    held++;
    if (read_doubles(args[8], &views[7], 1, "page_middles") < 0)
        goto done;
    held++;
    if (read_rows(args[10], &views[8], count) < 0)
        goto done;
    held++;
    if (views[2].shape[0] != views[1].shape[0] || views[5].shape[0] != count) {
        PyErr_SetString(PyExc_ValueError, "owner: one per row; roots: one per item");
        goto done;
    }
    const double *centres = views[0].buf, *halves = views[3].buf;
    const double *page_edges = views[6].buf, *page_middles = views[7].buf;
    const int64_t *rows = views[1].buf, *owner = views[2].buf, *active_rows = views[4].buf;
    const int64_t *roots = views[5].buf, *members = views[8].buf;
    Py_ssize_t row_count = views[1].shape[0], active = views[4].shape[0];
    Py_ssize_t edge_count = views[6].shape[0], middle_count = views[7].shape[0];
    Py_ssize_t member_count = views[8].shape[0];
    if (make_room(0, count) < 0) {
        PyErr_NoMemory();
        goto done;
    }
    lines = PyMem_Malloc((3 * active + 1) * sizeof(double));
    found = PyMem_Calloc(groups + 1, 1);
    if (lines == NULL || found == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t m = 0; m < member_count; m++)
        is_member[members[m]] = 1;
    /* each active row's low edge, high edge and centre, the moved ones moved */
    for (Py_ssize_t q = 0; q < active; q++) {
        Py_ssize_t row = active_rows[q];
        double at = is_member[row] ? centres[2 * row + axis] + shift : centres[2 * row + axis];
        double half = halves[2 * row + axis];
        lines[3 * q] = at - half;
        lines[3 * q + 1] = at + half;
        lines[3 * q + 2] = at;
    }
    for (Py_ssize_t k = 0; k < row_count; k++) {
        Py_ssize_t row = rows[k], group = owner[k];
        if (group < 0 || group >= groups || found[group])
            continue;
        double at = is_member[row] ? centres[2 * row + axis] + shift : centres[2 * row + axis];
        double half = halves[2 * row + axis];
        double low = at - half, high = at + half;
        int on = 0;
        for (Py_ssize_t q = 0; q < active && !on; q++) {
            if (roots[active_rows[q]] == roots[row])
                continue; /* its own group's lines hold nothing */
            const double *line = lines + 3 * q;
            on = fabs(low - line[0]) <= on_line || fabs(low - line[1]) <= on_line
                 || fabs(high - line[0]) <= on_line || fabs(high - line[1]) <= on_line
                 || fabs(at - line[2]) <= on_line;
        }
        for (Py_ssize_t e = 0; e < edge_count && !on; e++)
            on = fabs(low - page_edges[e]) <= on_line || fabs(high - page_edges[e]) <= on_line;
        for (Py_ssize_t e = 0; e < middle_count && !on; e++)
            on = fabs(at - page_middles[e]) <= on_line;
        found[group] = (char)on;
    }
    for (Py_ssize_t m = 0; m < member_count; m++)
        is_member[members[m]] = 0;
    result = PyList_New(groups);
    for (Py_ssize_t g = 0; result != NULL && g < groups; g++) {
        PyObject *value = found[g] ? Py_True : Py_False;
        Py_INCREF(value);
        PyList_SET_ITEM(result, g, value);
    }
done:
    PyMem_Free(lines);
    PyMem_Free(found);
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

/* ---- the rest check's force sum (physics.rest_check.RestCheck.net) ---- */

/* pair_table's columns: a pair's reach on each axis, whether each axis is blocked (1.0), the
   shares of its push that its ends i and j take */
enum { REACH_X, REACH_Y, BLOCKED_X, BLOCKED_Y, SHARE_I, SHARE_J, PAIR_COLUMNS };
/* row_table's: the rest box (lowest x, y, highest x, y), the anchor spring and its anchor */
enum { LOW_X, LOW_Y, HIGH_X, HIGH_Y, ANCHOR_K, ANCHOR_X, ANCHOR_Y, ROW_COLUMNS };
/* forces: the contact and wall constants and the pushes' sliding share at the probe's heat */
enum { K_CONTACT, K_WALL, RADIAL, FORCES };

/* The fast mode's push of one pair (fast_forces.touching_pushes) on j away from i, in the
   same operations on the same floats in the same order: whether their halos touch. */
static int pair_push(double dx, double dy, const double *pair, double radial_share,
                     double *push_x, double *push_y)
{
    double penetration_x = pair[REACH_X] - fabs(dx), penetration_y = pair[REACH_Y] - fabs(dy);
    double least = penetration_y < penetration_x ? penetration_y : penetration_x;
    if (!(least > 0))
        return 0;
    int blocked_x = pair[BLOCKED_X] != 0.0, blocked_y = pair[BLOCKED_Y] != 0.0;
    double squared_x = penetration_x * penetration_x, squared_y = penetration_y * penetration_y;
    double sharp_x = squared_x * squared_x, sharp_y = squared_y * squared_y;
    if (blocked_x || blocked_y) {
        double x = blocked_y ? 0.0 : sharp_x, y = blocked_x ? 0.0 : sharp_y;
        sharp_x = blocked_x ? x + 1.0 : x;
        sharp_y = blocked_y ? y + 1.0 : y;
    }
    double total = sharp_x + sharp_y;
    if (total == 0)
        total = 1.0;
    double x = copysign(penetration_x, dx) * (sharp_y / total);
    double y = copysign(penetration_y, dy) * (sharp_x / total);
    if (radial_share != 0) {
        double length = sqrt(dx * dx + dy * dy);
        if (length == 0)
            length = 1.0;
        double depth = sqrt(x * x + y * y);
        double along = radial_share * depth / length;
        x += blocked_x ? 0.0 : along * dx;
        y += blocked_y ? 0.0 : along * dy;
    }
    *push_x = x;
    *push_y = y;
    return 1;
}

static double *sums = NULL; /* per row: the pushes summed on it as j (x, y), then as i; 0 */
static Py_ssize_t sum_rows = 0;

static int read_indices(PyObject *list, Py_ssize_t limit, Py_ssize_t *into, const char *name)
{
    Py_ssize_t count = PyList_GET_SIZE(list);
    for (Py_ssize_t k = 0; k < count; k++) {
        Py_ssize_t index = PyLong_AsSsize_t(PyList_GET_ITEM(list, k));
        if (index == -1 && PyErr_Occurred())
            return -1;
        if (index < 0 || index >= limit) {
            PyErr_Format(PyExc_IndexError, "%s: an index outside the table", name);
            return -1;
        }
        into[k] = index;
    }
    return 0;
}

PyDoc_STRVAR(rest_net_doc,
"rest_net(rows, pairs, centres, members, axis, shift, pair_ends, pair_table, row_table,\n"
"         forces) -> [(x, y) per row]\n\n"
"The net acceleration of each of ``rows`` (lists: ``pairs`` must hold every pair that touches\n"
"them) with the items at ``centres`` but ``members`` moved by ``shift`` along ``axis``: the\n"
"fast mode's sums at the probe's heat (ContactPushes, WallPushes, AnchorPulls), worked out\n"
"pair by pair as pair_sums adds them (a row's pushes as j, then as i, each summed from 0.0 in\n"
"the pairs' order), so the same floats bit for bit.  Compiled: the rest check asks it before\n"
"each move the snap tries, and in Python floats it was most of a successful try's time.");

static PyObject *rest_net(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 10 || !PyList_Check(args[0]) || !PyList_Check(args[1])) {
        PyErr_SetString(PyExc_TypeError, "rest_net(rows: list, pairs: list, centres, members, "
                        "axis, shift, pair_ends, pair_table, row_table, forces)");
        return NULL;
    }
    int axis = PyLong_AsLong(args[4]);
    double shift = PyFloat_AsDouble(args[5]);
    if (PyErr_Occurred())
        return NULL;
    if (axis != 0 && axis != 1) {
        PyErr_SetString(PyExc_ValueError, "axis: 0 or 1");
        return NULL;
    }
    Py_buffer views[6];
    int held = 0;
    PyObject *result = NULL;
    Py_ssize_t *indices = NULL;
    if (read_doubles(args[2], &views[0], 2, "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (read_rows(args[3], &views[1], count) < 0)
        goto done;
    held++;
    if (PyObject_GetBuffer(args[6], &views[2], PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        goto done;
    held++;
    if (read_doubles(args[7], &views[3], 2, "pair_table") < 0)
        goto done;
    held++;
    if (read_doubles(args[8], &views[4], 2, "row_table") < 0)
        goto done;
    held++;
    if (read_doubles(args[9], &views[5], 1, "forces") < 0)
        goto done;
    held++;
    Py_ssize_t pair_count = views[3].shape[0];
    const char *format = views[2].format ? views[2].format : "B";
    if (views[0].shape[1] != 2 || views[3].shape[1] != PAIR_COLUMNS
            || views[4].shape[0] != count || views[4].shape[1] != ROW_COLUMNS
            || views[5].shape[0] != FORCES || views[2].ndim != 2 || views[2].itemsize != 8
            || strchr("lqn", format[0]) == NULL || format[1] != '\0'
            || views[2].shape[0] != pair_count || views[2].shape[1] != 2) {
        PyErr_SetString(PyExc_ValueError, "rest_net: centres (n, 2), pair_ends (p, 2) int64, "
                        "pair_table (p, 6), row_table (n, 7), forces (3,)");
        goto done;
    }
    const double *centres = views[0].buf, *pair_table = views[3].buf;
    const double *row_table = views[4].buf, *forces = views[5].buf;
    const int64_t *members = views[1].buf, *ends = views[2].buf;
    Py_ssize_t member_count = views[1].shape[0];
    Py_ssize_t row_count = PyList_GET_SIZE(args[0]), pairs = PyList_GET_SIZE(args[1]);
    indices = PyMem_Malloc((row_count + pairs + 1) * sizeof(Py_ssize_t));
    if (indices == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    Py_ssize_t *rows = indices, *pair_list = indices + row_count;
    if (read_indices(args[0], count, rows, "rows") < 0
            || read_indices(args[1], pair_count, pair_list, "pairs") < 0)
        goto done;
    for (Py_ssize_t k = 0; k < pairs; k++) {
        const int64_t *pair_ends = ends + 2 * pair_list[k];
        if (pair_ends[0] < 0 || pair_ends[0] >= count || pair_ends[1] < 0
                || pair_ends[1] >= count) {
            PyErr_SetString(PyExc_IndexError, "pair_ends: a row outside the table");
            goto done;
        }
    }
    if (make_room(0, count) < 0) {
        PyErr_NoMemory();
        goto done;
    }
    if (count > sum_rows) {
        double *grown = PyMem_Realloc(sums, 4 * count * sizeof(double));
        if (grown == NULL) {
            PyErr_NoMemory();
            goto done;
        }
        memset(grown, 0, 4 * count * sizeof(double));
        sums = grown;
        sum_rows = count;
    }
    /* the moved rows' positions on the axis: their centres plus the shift, the others' as
       they are (is_member marks them, all 0 again before returning) */
    for (Py_ssize_t k = 0; k < member_count; k++)
        is_member[members[k]] = 1;
#define AT(row, a) (is_member[row] && (a) == axis ? centres[2 * (row) + (a)] + shift \
                                                  : centres[2 * (row) + (a)])
    double k_contact = forces[K_CONTACT], k_wall = forces[K_WALL], radial = forces[RADIAL];
    for (Py_ssize_t k = 0; k < pairs; k++) {
        const int64_t *pair_ends = ends + 2 * pair_list[k];
        Py_ssize_t i = pair_ends[0], j = pair_ends[1];
        const double *pair = pair_table + PAIR_COLUMNS * pair_list[k];
        double push_x, push_y;
        if (!pair_push(AT(j, 0) - AT(i, 0), AT(j, 1) - AT(i, 1), pair, radial, &push_x, &push_y))
            continue;
        push_x *= k_contact;
        push_y *= k_contact;
        sums[4 * j] += push_x * pair[SHARE_J];
        sums[4 * j + 1] += push_y * pair[SHARE_J];
        sums[4 * i + 2] += push_x * pair[SHARE_I];
        sums[4 * i + 3] += push_y * pair[SHARE_I];
    }
    result = PyList_New(row_count);
    for (Py_ssize_t k = 0; result != NULL && k < row_count; k++) {
        Py_ssize_t row = rows[k];
        const double *box = row_table + ROW_COLUMNS * row;
        double x = AT(row, 0), y = AT(row, 1);
        double inside_x = x < box[LOW_X] ? box[LOW_X] : x;  /* min(max(x, low), high) */
        inside_x = box[HIGH_X] < inside_x ? box[HIGH_X] : inside_x;
        double inside_y = y < box[LOW_Y] ? box[LOW_Y] : y;
        inside_y = box[HIGH_Y] < inside_y ? box[HIGH_Y] : inside_y;
        double acc_x = sums[4 * row] - sums[4 * row + 2] + k_wall * (inside_x - x);
        double acc_y = sums[4 * row + 1] - sums[4 * row + 3] + k_wall * (inside_y - y);
        double spring = box[ANCHOR_K];
        PyObject *net = Py_BuildValue("(dd)", acc_x + spring * (box[ANCHOR_X] - x),
                                      acc_y + spring * (box[ANCHOR_Y] - y));
        if (net == NULL)
            Py_CLEAR(result);
        else
            PyList_SET_ITEM(result, k, net);
    }
#undef AT
    for (Py_ssize_t k = 0; k < pairs; k++) {
        const int64_t *pair_ends = ends + 2 * pair_list[k];
        memset(sums + 4 * pair_ends[0], 0, 4 * sizeof(double));
        memset(sums + 4 * pair_ends[1], 0, 4 * sizeof(double));
    }
    for (Py_ssize_t k = 0; k < member_count; k++)
        is_member[members[k]] = 0;
done:
    PyMem_Free(indices);
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

static PyMethodDef methods[] = {
    {"score_moves", (PyCFunction)(void (*)(void))score_moves, METH_FASTCALL, score_moves_doc},
    {"scored_candidates", (PyCFunction)(void (*)(void))scored_candidates, METH_FASTCALL,
     scored_candidates_doc},
    {"line_of", (PyCFunction)(void (*)(void))line_of, METH_FASTCALL, line_of_doc},
    {"rest_net", (PyCFunction)(void (*)(void))rest_net, METH_FASTCALL, rest_net_doc},
    {"fitting_shifts", (PyCFunction)(void (*)(void))fitting_shifts, METH_FASTCALL,
     fitting_shifts_doc},
    {"held_on_lines", (PyCFunction)(void (*)(void))held_on_lines, METH_FASTCALL,
     held_on_lines_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "floatpage.physics.snap_kernel",
    "The alignment snap's scoring, compiled (see physics/snap_kernel.c's head comment).",
    0,
    methods,
};

PyMODINIT_FUNC PyInit_snap_kernel(void)
{
    return PyModule_Create(&module);
}
