/* The alignment snap's scoring of one body's moves along one axis, shared by the module that
   exposes it to Python (snap_scoring_kernel.c, score_moves) and the compiled sweeps
   (snap_sweep_kernel.c), which call it directly: through Python, each of the tens of thousands
   of scorings of a page paid a call, three buffer requests and a result tuple, a fifth of its
   cost once the arithmetic had become cheap.  Each module includes its own copy (all static),
   as with snap_kernel_support.h; the room below is the including module's. */

#ifndef SNAP_SCORING_CORE_H
#define SNAP_SCORING_CORE_H

#include "snap_kernel_support.h"

/* snap_scoring.scoring_ranges' layout */
#define BOUNDS 0       /* 12 needles, distance_bounds */
#define WINDOW_ENDS 12 /* 4: + NEAR, - ALIGNED, - NEAR, + ALIGNED around a shift */
#define ESCAPE 16      /* the escape move, ESCAPE_MM */
#define WINDOW 17      /* how far beyond a body's edges its near lines reach */
#define RELEVANT 18    /* relevant_distance: no range reads a distance this far */
#define GRID 19        /* steps per mm every candidate shift is rounded to (0: none) */
#define RANGES 20
#define ROUNDING_MAGIC 6755399441055744.0 /* 1.5 * 2^52: x + it - it is x rounded, ties to even */

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
   bisect.  ``shifts`` holds room for 3 * count + 1, ``spare`` for 3 * count + 4. */
static Candidates candidate_shifts(const double *ordered, Py_ssize_t count,
                                   const double *ranges, double *shifts, double *spare)
{
    Py_ssize_t found[12];
    for (int k = 0; k < 12; k++)
        found[k] = below(ordered, count, ranges[BOUNDS + k]);
    const Py_ssize_t *low = found, *high = found + 4;
    double escape = ranges[ESCAPE], grid = ranges[GRID], step = grid > 0.0 ? 1.0 / grid : 0.0;
    Candidates made;
    /* the runs in spare, each followed by +inf (below no value: a run used up is never
       taken again): staying and |distance| <= reach, staying placed where a merge puts it
       (after the distances below 0, before the others: a bisection); then of |distance| <
       farthest + ESCAPE_MM, those whose escape down, then up, stays within farthest */
    Py_ssize_t reach_count = high[0] > low[0] ? high[0] - low[0] : 0;
    const double *reach = ordered + low[0];
    Py_ssize_t below_zero = below(reach, reach_count, 0.0);
    double *staying_run = spare;
    memcpy(staying_run, reach, below_zero * sizeof(double));
    staying_run[below_zero] = 0.0;
    memcpy(staying_run + below_zero + 1, reach + below_zero,
           (reach_count - below_zero) * sizeof(double));
    Py_ssize_t n = reach_count + 1;
    staying_run[n] = INFINITY;
    double *down_run = staying_run + n + 1, *up_run;
    Py_ssize_t downs = 0, ups = 0;
    Py_ssize_t start = high[1] > found[8] ? high[1] : found[8];
    Py_ssize_t stop = low[1] < found[9] ? low[1] : found[9];
    for (Py_ssize_t i = start; i < stop; i++)
        down_run[downs++] = ordered[i] - escape;
    down_run[downs] = INFINITY;
    up_run = down_run + downs + 1;
    start = high[1] > found[10] ? high[1] : found[10];
    stop = low[1] < found[11] ? low[1] : found[11];
    for (Py_ssize_t i = start; i < stop; i++)
        up_run[ups++] = ordered[i] + escape;
    up_run[ups] = INFINITY;
    n += downs + ups;
    /* one merge of the three runs into shifts, ties to the earlier run (as merging the
       escapes first, then the result into staying's run: the order the shifts always had),
       each value kept once: a value is new if it differs (!=: a -0 after a 0 is no new
       value) from the one merged before it.  Without a branch on the values: each step
       takes the least head and writes it, kept or not. */
    const double *from_staying = staying_run, *from_down = down_run, *from_up = up_run;
    Py_ssize_t kept = 0;
    double last = 0.0;
    for (Py_ssize_t t = 0; t < n; t++) {
        double x = *from_staying, y = *from_down, z = *from_up;
        int take_x = (x <= y) & (x <= z);
        int take_y = !take_x & (y <= z);
        double value = take_x ? x : (take_y ? y : z);
        /* onto the save's grid (ranges[GRID]: physics.save_grid.STEPS_PER_MM): a body the
           snap put on it stays on it, so the layout saved is the layout the snap scored.
           Rounded to the nearest step (ties to even: adding and taking away 1.5 * 2^52, no
           call of floor), times the step.  Monotone, so the merged values stay sorted and
           repeats stay together */
        if (grid > 0.0) {
            double steps = value * grid + ROUNDING_MAGIC;
            value = (steps - ROUNDING_MAGIC) * step;
        }
        from_staying += take_x;
        from_down += take_y;
        from_up += !(take_x | take_y);
        shifts[kept] = value;
        kept += (t == 0) | (value != last);
        last = value;
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
   first window.  "d <= x" is compared as such: NumPy's bisection had it as "d < the next
   float after x", the same test on every float that is not infinite (no distance is: the cut
   to the relevant drops them).

   A sweep steps four distances at a time: of four sorted distances, those below an end are
   the first ones, so their count is how far to step, and it is 4 only when the walk goes on.
   The step taken one distance at a time was a branch per distance that no predictor could
   guess (a shift's end passes one or two distances).  ``ordered`` holds four +inf past its
   ``count`` (below every end), so that no step reads past it. */
#define STEP4(at, test)                                                                    \
    for (;;) {                                                                             \
        const double *from = ordered + at;                                                 \
        int step = (test(from[0])) + (test(from[1])) + (test(from[2])) + (test(from[3]));  \
        at += step;                                                                        \
        if (step < 4)                                                                      \
            break;                                                                         \
    }
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
#define BELOW_A(x) ((x) < to_a)
#define BELOW_B(x) ((x) < to_b)
#define UP_TO_C(x) ((x) <= to_c)
#define UP_TO_D(x) ((x) <= to_d)
        STEP4(a, BELOW_A)
        STEP4(b, BELOW_B)
        STEP4(c, UP_TO_C)
        STEP4(d, UP_TO_D)
#undef BELOW_A
#undef BELOW_B
#undef UP_TO_C
#undef UP_TO_D
        scores[k] = 2 * (long)a + 3 * (long)b - 2 * (long)c - 3 * (long)d;
    }
}
#undef STEP4

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
    /* a handful as a rule (at most the candidates scored, 64): on the stack, sorted by
       insertion; the order is total (``order`` breaks every tie), so any sort gives this one */
    Move kept_here[64];
    Move *moves = better <= 64 ? kept_here : PyMem_Malloc(better * sizeof(Move));
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
    if (n <= 64)
        for (Py_ssize_t k = 1; k < n; k++) {
            Move move = moves[k];
            Py_ssize_t j = k;
            for (; j > 0 && better_move(&moves[j - 1], &move) > 0; j--)
                moves[j] = moves[j - 1];
            moves[j] = move;
        }
    else
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
    if (moves != kept_here)
        PyMem_Free(moves);
    return found;
}

/* A scoring's answer: the moves best first (a tuple of floats, owned), what the best gains,
   whether the body misses a line now and whether it is on one, the span of lines read. */
typedef struct {
    PyObject *shifts;
    double gain;
    int missing, lined_up;
    double low, high;
} Scored;

/* score_moves on raw arrays: ``table`` (``rows`` rows of COLUMNS), the body's ``members``
   (``member_count`` rows, each checked to be in the table by the caller), ``ranges``
   (scoring_ranges' RANGES doubles).  Returns 0, or -1 with an exception set. */
static int score_body(const double *table, Py_ssize_t rows, const int64_t *members,
                      Py_ssize_t member_count, const double *ranges, Py_ssize_t wanted,
                      Py_ssize_t tries, Scored *out)
{
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
        return -1;
    }
    for (Py_ssize_t k = 0; k < member_count; k++)
        is_member[members[k]] = 1;
    Py_ssize_t near = 0;
    for (Py_ssize_t row = 0; row < rows; row++) { /* written always, kept if near */
        const double *line = table + row * COLUMNS;
        near_rows[near] = row;
        near += (line[LOWS] < high) & (line[HIGHS] > low) & !is_member[row];
    }
    for (Py_ssize_t k = 0; k < member_count; k++)
        is_member[members[k]] = 0;
    Py_ssize_t room = member_count * near * PAIRINGS;
    if (make_room(8 * room + 12, rows) < 0) {
        PyErr_NoMemory();
        return -1;
    }
    /* the distances (and four +inf past them: misses_after), the candidates (3 * room + 1),
       the runs they are merged from (3 * room + 4), the sort's spare (room) */
    double *ordered = scratch, *shifts = scratch + room + 4, *spare = shifts + 3 * room + 1;
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
    double *sort_spare = spare + 3 * room + 4;
    Py_ssize_t *bucket_counts = counts_for(room + 2);
    if (bucket_counts == NULL) {
        PyErr_NoMemory();
        return -1;
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
        return -1;
    }
    for (int pad = 0; pad < 4; pad++)
        ordered[count + pad] = INFINITY;
    misses_after(ordered, count, shifts + first, scored, ranges, scores);
    long best = made.now;
    PyObject *chosen = best_first(shifts + first, scores, scored, made.now, tries, &best);
    if (chosen == NULL)
        return -1;
    out->shifts = chosen;
    out->gain = (made.now - best) / 2.0;
    out->missing = made.missing;
    out->lined_up = made.lined_up;
    out->low = low;
    out->high = high;
    return 0;
}

/* line_of on raw arrays: ``row`` and the movers (roots marked in ``movers``) with a feature on
   one of the lines of ``row``'s group (its rows ``members``, checked by the caller) on the axis
   of ``table`` (its first ``count`` rows: the items), in row order after ``row``; and the
   span of the group's features widened by ``aligned`` in ``low_out``, ``high_out``.  A new
   list, or NULL with an exception set. */
static PyObject *line_body(const double *table, Py_ssize_t count, const int64_t *members,
                           Py_ssize_t member_count, Py_ssize_t row, const int64_t *roots,
                           const char *movers, double aligned, double *low_out,
                           double *high_out)
{
    if (make_room(0, count) < 0)
        return PyErr_NoMemory();
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
    *low_out = low - aligned;
    *high_out = high + aligned;
unmark:
    for (Py_ssize_t other = 0; other < count; other++)
        is_member[other] = 0;
    return line;
}

#endif
