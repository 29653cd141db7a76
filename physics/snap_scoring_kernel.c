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

#include "snap_kernel_support.h"

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

/* room for sort_distances' counts, kept between calls as the support header's room is */
static Py_ssize_t *count_room = NULL;
static Py_ssize_t count_size = 0;

static Py_ssize_t *counts_for(Py_ssize_t count)
{
    if (count > count_size) {
        Py_ssize_t *grown = PyMem_Realloc(count_room, count * sizeof(Py_ssize_t));
        if (grown == NULL)
            return NULL;
        count_room = grown;
        count_size = count;
    }
    return count_room;
}

/* The distances of a scoring sorted: they lie within (-relevant, relevant), so a pass that
   counts them into as many buckets of equal width as there are distances and a pass that
   places them bucket by bucket leave each a few places from its own, and an insertion sort
   finishes (every comparison it makes is between values of one bucket or two neighbouring
   ones; on the 50-item page a bucket holds one or two).  The quicksort it replaces spent most
   of its time on comparisons no branch predictor could guess.  The bucket of a value is a
   rounded, nondecreasing function of it, so the placing keeps the order between buckets; the
   insertion sort would make the array sorted whatever the buckets were.  ``spare`` holds
   room for ``count`` doubles, ``counts`` for count + 1. */
static void sort_distances(double *values, Py_ssize_t count, double relevant, double *spare,
                           Py_ssize_t *counts)
{
    if (count <= 24 || !(relevant > 0.0) || !isfinite(relevant)) {
        if (count <= 24)
            insertion_sort(values, count);
        else
            sort_doubles(values, count);
        return;
    }
    double scale = (double)count / (2.0 * relevant);
    memset(counts, 0, (count + 1) * sizeof(Py_ssize_t));
    for (Py_ssize_t i = 0; i < count; i++) {
        double at = (values[i] + relevant) * scale;
        Py_ssize_t bucket = at <= 0.0 ? 0 : (at >= (double)(count - 1) ? count - 1
                                                                        : (Py_ssize_t)at);
        counts[bucket + 1]++;
    }
    for (Py_ssize_t k = 1; k <= count; k++)
        counts[k] += counts[k - 1];
    for (Py_ssize_t i = 0; i < count; i++) {
        double at = (values[i] + relevant) * scale;
        Py_ssize_t bucket = at <= 0.0 ? 0 : (at >= (double)(count - 1) ? count - 1
                                                                        : (Py_ssize_t)at);
        spare[counts[bucket]++] = values[i];
    }
    memcpy(values, spare, count * sizeof(double));
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
    while (i < a_count && j < b_count) { /* without a branch on the values (a select) */
        double x = a[i], y = b[j];
        int take_b = y < x;
        into[n++] = take_b ? y : x;
        j += take_b;
        i += !take_b;
    }
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
    for (Py_ssize_t i = 1; i < n; i++) { /* written always, kept if new (no branch) */
        shifts[kept] = spare[i];
        kept += spare[i] != shifts[kept - 1];
    }
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
   shift: d < shift + NEAR, d < shift - ALIGNED, d <= shift - NEAR, d <= shift + ALIGNED
   (weights 2, 3, -2, -3: twice 1 and 1 + ALIGN_GAIN); each end, a rounded sum, grows with the
   shift, so each count is a sweep of the distances from where the last shift's stopped (the
   same counts as a bisection).  The four sweeps go side by side, one pass over the shifts,
   each starting where a bisection puts the first shift's end: most distances lie beyond the
   first window, and the four walks are independent work for the processor.  "d <= x" is
   compared as such: NumPy's bisection had it as "d < the next float after x", the same test
   on every float that is not infinite (no distance is: the cut to the relevant drops them). */
static void misses_after(const double *ordered, Py_ssize_t count, const double *shifts,
                         Py_ssize_t shift_count, const double *ranges, long *scores)
{
    if (shift_count == 0)
        return;
    const double near = ranges[WINDOW_ENDS], less_aligned = ranges[WINDOW_ENDS + 1];
    const double less_near = ranges[WINDOW_ENDS + 2], aligned = ranges[WINDOW_ENDS + 3];
    Py_ssize_t a = below(ordered, count, near + shifts[0]);
    Py_ssize_t b = below(ordered, count, less_aligned + shifts[0]);
    Py_ssize_t c = below(ordered, count, next_up(less_near + shifts[0]));
    Py_ssize_t d = below(ordered, count, next_up(aligned + shifts[0]));
    for (Py_ssize_t k = 0; k < shift_count; k++) {
        double shift = shifts[k];
        double to_a = near + shift, to_b = less_aligned + shift;
        double to_c = less_near + shift, to_d = aligned + shift;
        while (a < count && ordered[a] < to_a)
            a++;
        while (b < count && ordered[b] < to_b)
            b++;
        while (c < count && ordered[c] <= to_c)
            c++;
        while (d < count && ordered[d] <= to_d)
            d++;
        scores[k] = 2 * (long)a + 3 * (long)b - 2 * (long)c - 3 * (long)d;
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
    if (make_room(8 * room + 4, rows) < 0) {
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
    /* the spare room past the candidates' (7 * room + 2) for the sort: a double and a count
       per distance */
    double *sort_spare = spare + 3 * room + 1;
    Py_ssize_t *bucket_counts = counts_for(room + 2);
    if (bucket_counts == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    sort_distances(ordered, count, relevant, sort_spare, bucket_counts);
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
