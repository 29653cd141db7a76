/* What one page's compiled snap sweeps hold (snap_sweep_kernel.c's Sweep): the page's tables
   and groups, the memo (AxisMemo's spans and answers), the lines stuck since the last move,
   and what the rest check reads (snap_sweep_rest.h).  A header of its own so that the rest
   check's functions, which read it, can live apart from the sweeps. */

#ifndef SNAP_SWEEP_STATE_H
#define SNAP_SWEEP_STATE_H

#include "snap_kernel_support.h"

/* one body's candidate moves (snapping.Moves), every reference owned */
typedef struct {
    PyObject *roots;   /* list of ints: the groups moved together */
    PyObject *members; /* int64 array of their rows (None where no move is tried; NULL for a
                          line until attempt needs them) */
    PyObject *shifts;  /* tuple of floats, best first */
    double gain;
    int missing, lined_up;
} Moves;

typedef struct {
    Py_ssize_t since; /* moves along the axis already checked against the span; -1: nothing */
    double low, high;
} Span;

typedef struct {
    PyObject_HEAD
    Py_ssize_t count;
    PyObject *members;       /* list per row: int64 array (a mover's group) or None */
    PyObject *root_lists;    /* list per row: [row], made once */
    char *too_large;         /* row * 2 + axis */
    char *bleeds;            /* per row */
    PyObject *tables[2][2];  /* [bleed][axis], NULL where no mover needs that kind */
    PyObject *item_tables;   /* (x, y): what reads the rows alone */
    PyObject *roots, *mover_mask, *aligned;
    PyObject *keeps_rest, *concatenate; /* keeps_rest: the rest parts, or their maker */
    PyObject *moved_from, *centres, *rest_before; /* what a move changes besides the tables */
    PyObject *fit_args;      /* centres, halves, lowest, highest, item tables, fit limits */
    Py_ssize_t candidates, max_tries, every_move, tries;
    PyObject *line_members; /* dict: a line's roots (in its order) -> their rows, made once */
    double nudge;
    int memo_on;             /* 0 while try_lesser scores afresh (a throwaway memo) */
    /* the memo, per axis: the swept spans of the moved rows, in move order */
    double *swept_low[2], *swept_high[2];
    Py_ssize_t swept_count[2], swept_room[2];
    Span *alone_span[2];     /* per row: a body of one group */
    Moves *alone_value[2];
    Span *line_span[2];      /* per row: its line (line_of) */
    PyObject **line_value[2];
    PyObject *lines_known[2]; /* dict: sorted roots -> [since, low, high, roots, None (the
                                 members, made by attempt), shifts, gain, missing, lined_up] */
    PyObject *stuck[2];      /* set of sorted roots: lines whose move failed since the last */
    /* the rest check (RestCheck.keeps_rest), when the snap has one */
    int has_rest, rest_taken, grouped; /* rest_taken: its parts read (take_rest) */
    double limit, hold;
    PyObject *reached_by, *rest_net, *net_args, *held_on_lines, *hold_args, *no_rows, *zero;
    PyObject *scratch_rows, *scratch_owner; /* int64, one per row: held_of's rows, owners */
    PyObject *root_list, *group_rows, *pairs_of;
    PyObject *line_mates, *mate_args; /* RestCheck.keeps_holds: the function, its arguments */
    PyObject *unlisted, *unlisted_args; /* RestCheck.unlisted_near: the function, its arguments */
    PyObject *refind; /* RestCheck.refind: the check built anew, its parts to read again */
    char *before_known, *before_held; /* per group: RestCheck.as_it_is's, until a move */
    double *before_push, *before_net; /* per group: its push, its net (x, y) */
    /* what the scoring (snap_scoring_core.h, called directly) reads, read once in sweep_new:
       each table's cells (held until the Sweep goes), scoring_ranges' 20 doubles, each mover's
       rows, and room for a line's rows */
    Py_buffer table_views[2][2];
    int table_held[2][2];
    double range_values[20];
    int64_t **member_rows;
    Py_ssize_t *member_sizes;
    int64_t *line_room_rows;
    Py_ssize_t line_room;
    /* what the fit test (snap_fit_core.h, called directly) reads, read once in sweep_new */
    Py_buffer fit_views[7]; /* FIT_CENTRES .. FIT_LIMIT_VALUES */
    int fit_held;           /* how many of them are held */
    /* what finding a line (line_body, called directly) reads: the item tables of x and y,
       the roots, the movers' marks; read once in sweep_new */
    Py_buffer line_views[4];
    int line_held;
} Sweep;

/* the rest check's parts read into the Sweep (snap_sweep_kernel.c), now or at its first use */
static int take_rest(Sweep *self, PyObject *parts);
/* ...and let go of, before they are read again (RestCheck.refind) */
static void drop_rest(Sweep *self);

enum { FIT_CENTRES, FIT_HALVES, FIT_LOWEST, FIT_HIGHEST, FIT_TABLE_X, FIT_TABLE_Y,
       FIT_LIMIT_VALUES, FIT_VIEWS };

#endif
