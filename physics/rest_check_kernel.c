/* The snap's rest check (physics.rest_check), compiled: the force sums of a move's few pairs
   (RestCheck.net) and which groups a guide line holds (physics.line_hold).  Asked before each
   move the snap tries; in Python floats and NumPy they were most of a successful try's time.
   The same operations on the same floats in the same order as the fast mode's terms
   (tests/physics/test_rest_check_sums.py, test_snap_units.py hold them to those). */

#include "snap_kernel_support.h"

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
    if (read_row_pairs(args[3], &views[0], "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
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

/* ---- the groups a move may take a line from (physics.rest_check.RestCheck.keeps_rest) ---- */

PyDoc_STRVAR(line_mates_doc,
"line_mates(members, axis, centres, halves, active_rows, roots, movable, on_line)\n"
"    -> [root per group, sorted]\n\n"
"The movable groups (``movable``: per row, whether it is a movable group's root) other than\n"
"the groups of ``members`` with a feature on one of the members' lines on ``axis``: an edge\n"
"of one of their rows within ``on_line`` of a member's edge, or its centre within it of a\n"
"member's centre (physics.guides).  A move of ``members`` along the axis takes those lines\n"
"away, and with them the hold of every group that nothing else holds, wherever it lies on\n"
"the page: the rest check asks each of those again (a group held on a line with an item\n"
"20 cm away lost its hold when that item moved, and drifted in the next probe).  Each line\n"
"worked out as held_on_lines works it out (a centre less or plus its half).");

static PyObject *line_mates(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 8) {
        PyErr_SetString(PyExc_TypeError, "line_mates(members, axis, centres, halves, "
                        "active_rows, roots, movable, on_line)");
        return NULL;
    }
    int axis = PyLong_AsLong(args[1]);
    double on_line = PyFloat_AsDouble(args[7]);
    if (PyErr_Occurred())
        return NULL;
    if (axis != 0 && axis != 1) {
        PyErr_SetString(PyExc_ValueError, "axis: 0 or 1");
        return NULL;
    }
    Py_buffer views[6];
    int held = 0;
    PyObject *result = NULL;
    char *found = NULL;
    if (read_row_pairs(args[2], &views[0], "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (read_rows(args[0], &views[1], count) < 0)
        goto done;
    held++;
    if (read_pairs_of(args[3], &views[2], count, "halves") < 0)
        goto done;
    held++;
    if (read_rows(args[4], &views[3], count) < 0)
        goto done;
    held++;
    if (read_rows(args[5], &views[4], count) < 0)
        goto done;
    held++;
    if (PyObject_GetBuffer(args[6], &views[5], PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        goto done;
    held++;
    if (views[4].shape[0] != count || views[5].ndim != 1 || views[5].shape[0] != count
            || views[5].itemsize != 1) {
        PyErr_SetString(PyExc_ValueError, "roots: one per item; movable: one bool per item");
        goto done;
    }
    const double *centres = views[0].buf, *halves = views[2].buf;
    const int64_t *members = views[1].buf, *active_rows = views[3].buf, *roots = views[4].buf;
    const char *movable = views[5].buf;
    Py_ssize_t member_count = views[1].shape[0], active = views[3].shape[0];
    for (Py_ssize_t m = 0; m < member_count; m++)
        if (roots[members[m]] < 0 || roots[members[m]] >= count) {
            PyErr_SetString(PyExc_IndexError, "roots: a row outside the table");
            goto done;
        }
    found = PyMem_Calloc(count + 1, 1); /* per root: 1 a mate, 2 a member's group */
    if (found == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t m = 0; m < member_count; m++)
        found[roots[members[m]]] = 2;
    for (Py_ssize_t q = 0; q < active; q++) {
        Py_ssize_t row = active_rows[q], root = roots[row];
        if (root < 0 || root >= count || found[root] || !movable[root])
            continue;
        double at = centres[2 * row + axis], half = halves[2 * row + axis];
        double low = at - half, high = at + half;
        int on = 0;
        for (Py_ssize_t m = 0; m < member_count && !on; m++) {
            Py_ssize_t member = members[m];
            double mine = centres[2 * member + axis], mine_half = halves[2 * member + axis];
            double mine_low = mine - mine_half, mine_high = mine + mine_half;
            on = fabs(low - mine_low) <= on_line || fabs(low - mine_high) <= on_line
                 || fabs(high - mine_low) <= on_line || fabs(high - mine_high) <= on_line
                 || fabs(at - mine) <= on_line;
        }
        if (on)
            found[root] = 1;
    }
    result = PyList_New(0);
    for (Py_ssize_t root = 0; result != NULL && root < count; root++) {
        if (found[root] != 1)
            continue;
        PyObject *value = PyLong_FromSsize_t(root);
        if (value == NULL || PyList_Append(result, value) < 0)
            Py_CLEAR(result);
        Py_XDECREF(value);
    }
done:
    PyMem_Free(found);
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

PyDoc_STRVAR(reach_of_doc,
"reach_of(members, pair_lists, pair_ends, roots, movable, group_rows) -> (groups, rows, pairs)\n\n"
"RestCheck.reached_by's answer for the rigid body ``members`` (int64 rows), worked out anew:\n"
"the movable groups it touches by a pair of ``pair_lists`` (per row, its pairs' numbers) whose\n"
"ends are ``pair_ends`` ((pairs, 2) int64), itself among them, in ascending order as the int64\n"
"bytes of an array (``roots``: int64 per row; ``movable``: one bool per row, read at a root);\n"
"their rows, group by group as ``group_rows`` lists them; and every pair of those rows, in\n"
"ascending order.  Compiled: in Python sets it was a seventh of a 50-item page's snap\n"
"(RestCheck.reach_python is the definition, tests/physics/test_rest_reach.py).");

static PyObject *reach_of(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 6 || !PyList_Check(args[1]) || !PyList_Check(args[5])) {
        PyErr_SetString(PyExc_TypeError, "reach_of(members, pair_lists: list, pair_ends, roots, "
                        "movable, group_rows: list)");
        return NULL;
    }
    PyObject *pair_lists = args[1], *group_rows = args[5];
    Py_ssize_t count = PyList_GET_SIZE(pair_lists);
    Py_buffer views[4];
    int held = 0;
    PyObject *result = NULL, *groups = NULL, *rows = NULL, *pairs = NULL;
    char *touched = NULL, *is_group = NULL, *is_pair = NULL;
    int64_t *group_buf = NULL;
    if (PyList_GET_SIZE(group_rows) != count) {
        PyErr_SetString(PyExc_ValueError, "group_rows: one list per row");
        return NULL;
    }
    if (read_rows(args[0], &views[0], count) < 0)
        goto done;
    held++;
    if (PyObject_GetBuffer(args[2], &views[1], PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        goto done;
    held++;
    if (views[1].itemsize != 8 || (views[1].ndim != 2 && views[1].len != 0)
            || (views[1].ndim == 2 && views[1].shape[1] != 2)) {
        PyErr_SetString(PyExc_TypeError, "pair_ends: a contiguous (pairs, 2) int64 array");
        goto done;
    }
    Py_ssize_t pair_count = views[1].len / 16;
    if (read_rows(args[3], &views[2], count) < 0)
        goto done;
    held++;
    if (views[2].shape[0] != count) {
        PyErr_SetString(PyExc_ValueError, "roots: one per row");
        goto done;
    }
    if (read_flags(args[4], &views[3], count) < 0)
        goto done;
    held++;
    const int64_t *members = views[0].buf, *ends = views[1].buf, *roots = views[2].buf;
    const char *movable = views[3].buf;
    Py_ssize_t member_count = views[0].shape[0];
    touched = PyMem_Calloc(count + 1, 1);
    is_group = PyMem_Calloc(count + 1, 1);
    is_pair = PyMem_Calloc(pair_count + 1, 1);
    group_buf = PyMem_Malloc((count + 1) * sizeof(int64_t));
    if (touched == NULL || is_group == NULL || is_pair == NULL || group_buf == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t m = 0; m < member_count; m++) {
        Py_ssize_t member = members[m];
        touched[member] = 1;
        PyObject *list = PyList_GET_ITEM(pair_lists, member);
        if (!PyList_Check(list)) {
            PyErr_SetString(PyExc_TypeError, "pair_lists: a list per row");
            goto done;
        }
        for (Py_ssize_t k = 0; k < PyList_GET_SIZE(list); k++) {
            Py_ssize_t pair = PyLong_AsSsize_t(PyList_GET_ITEM(list, k));
            if (pair == -1 && PyErr_Occurred())
                goto done;
            if (pair < 0 || pair >= pair_count) {
                PyErr_SetString(PyExc_IndexError, "pair_lists: a pair outside the table");
                goto done;
            }
            int64_t i = ends[2 * pair], j = ends[2 * pair + 1];
            if (i < 0 || i >= count || j < 0 || j >= count) {
                PyErr_SetString(PyExc_IndexError, "pair_ends: a row outside the table");
                goto done;
            }
            touched[i] = 1;
            touched[j] = 1;
        }
    }
    for (Py_ssize_t row = 0; row < count; row++) {
        if (!touched[row])
            continue;
        int64_t root = roots[row];
        if (root < 0 || root >= count) {
            PyErr_SetString(PyExc_IndexError, "roots: a row outside the table");
            goto done;
        }
        if (movable[root])
            is_group[root] = 1;
    }
    Py_ssize_t group_count = 0;
    rows = PyList_New(0);
    if (rows == NULL)
        goto done;
    for (Py_ssize_t group = 0; group < count; group++) {
        if (!is_group[group])
            continue;
        group_buf[group_count++] = group;
        PyObject *list = PyList_GET_ITEM(group_rows, group);
        if (!PyList_Check(list)) {
            PyErr_SetString(PyExc_TypeError, "group_rows: a list per row");
            goto done;
        }
        for (Py_ssize_t k = 0; k < PyList_GET_SIZE(list); k++) {
            PyObject *item = PyList_GET_ITEM(list, k);
            Py_ssize_t row = PyLong_AsSsize_t(item);
            if (row == -1 && PyErr_Occurred())
                goto done;
            if (row < 0 || row >= count) {
                PyErr_SetString(PyExc_IndexError, "group_rows: a row outside the table");
                goto done;
            }
            if (PyList_Append(rows, item) < 0)
                goto done;
            PyObject *its = PyList_GET_ITEM(pair_lists, row);
            if (!PyList_Check(its)) {
                PyErr_SetString(PyExc_TypeError, "pair_lists: a list per row");
                goto done;
            }
            for (Py_ssize_t q = 0; q < PyList_GET_SIZE(its); q++) {
                Py_ssize_t pair = PyLong_AsSsize_t(PyList_GET_ITEM(its, q));
                if (pair == -1 && PyErr_Occurred())
                    goto done;
                if (pair < 0 || pair >= pair_count) {
                    PyErr_SetString(PyExc_IndexError, "pair_lists: a pair outside the table");
                    goto done;
                }
                is_pair[pair] = 1;
            }
        }
    }
    pairs = PyList_New(0);
    if (pairs == NULL)
        goto done;
    for (Py_ssize_t pair = 0; pair < pair_count; pair++) {
        if (!is_pair[pair])
            continue;
        PyObject *value = PyLong_FromSsize_t(pair);
        if (value == NULL || PyList_Append(pairs, value) < 0) {
            Py_XDECREF(value);
            goto done;
        }
        Py_DECREF(value);
    }
    groups = PyBytes_FromStringAndSize((const char *)group_buf,
                                       group_count * (Py_ssize_t)sizeof(int64_t));
    if (groups == NULL)
        goto done;
    result = PyTuple_Pack(3, groups, rows, pairs);
done:
    Py_XDECREF(groups);
    Py_XDECREF(rows);
    Py_XDECREF(pairs);
    PyMem_Free(touched);
    PyMem_Free(is_group);
    PyMem_Free(is_pair);
    PyMem_Free(group_buf);
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

PyDoc_STRVAR(unlisted_near_doc,
"unlisted_near(members, axis, shift, centres, found_at, halves, active_rows, roots,\n"
"              pair_lists, pair_ends, gap, margin) -> bool\n\n"
"Whether the rigid body ``members`` moved by ``shift`` along ``axis`` would touch (within\n"
"``gap``, edge to edge on both axes) an active row its pairs do not list.  The pairs were found\n"
"at ``found_at`` within ``gap`` + ``margin``: none can be missing unless the members' travel\n"
"from there (this move included) and the farthest any active row has travelled add up to more\n"
"than ``margin``, the larger of |dx| and |dy| each; only then are the rows looked at.  The rest\n"
"check's sums read the listed pairs alone, so a body that travelled past them could be pushed\n"
"beyond the limit unseen (RestCheck.keeps_rest).");

static PyObject *unlisted_near(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 12 || !PyList_Check(args[8])) {
        PyErr_SetString(PyExc_TypeError, "unlisted_near(members, axis, shift, centres, found_at, "
                        "halves, active_rows, roots, pair_lists: list, pair_ends, gap, margin)");
        return NULL;
    }
    int axis = PyLong_AsLong(args[1]);
    double shift = PyFloat_AsDouble(args[2]);
    double gap = PyFloat_AsDouble(args[10]), margin = PyFloat_AsDouble(args[11]);
    if (PyErr_Occurred())
        return NULL;
    if (axis != 0 && axis != 1) {
        PyErr_SetString(PyExc_ValueError, "axis: 0 or 1");
        return NULL;
    }
    PyObject *pair_lists = args[8];
    Py_buffer views[7];
    int held = 0, near = 0;
    char *listed = NULL;
    PyObject *result = NULL;
    if (read_row_pairs(args[3], &views[0], "centres") < 0)
        goto done;
    held++;
    Py_ssize_t count = views[0].shape[0];
    if (PyList_GET_SIZE(pair_lists) != count) {
        PyErr_SetString(PyExc_ValueError, "pair_lists: one list per row");
        goto done;
    }
    if (read_rows(args[0], &views[1], count) < 0)
        goto done;
    held++;
    if (read_pairs_of(args[4], &views[2], count, "found_at") < 0)
        goto done;
    held++;
    if (read_pairs_of(args[5], &views[3], count, "halves") < 0)
        goto done;
    held++;
    if (read_rows(args[6], &views[4], count) < 0)
        goto done;
    held++;
    if (read_rows(args[7], &views[5], count) < 0)
        goto done;
    held++;
    if (views[5].shape[0] != count) {
        PyErr_SetString(PyExc_ValueError, "roots: one per row");
        goto done;
    }
    if (PyObject_GetBuffer(args[9], &views[6], PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        goto done;
    held++;
    if (views[6].itemsize != 8 || (views[6].ndim != 2 && views[6].len != 0)
            || (views[6].ndim == 2 && views[6].shape[1] != 2)) {
        PyErr_SetString(PyExc_TypeError, "pair_ends: a contiguous (pairs, 2) int64 array");
        goto done;
    }
    const double *centres = views[0].buf, *found_at = views[2].buf, *halves = views[3].buf;
    const int64_t *members = views[1].buf, *active_rows = views[4].buf, *ends = views[6].buf;
    Py_ssize_t member_count = views[1].shape[0], active = views[4].shape[0];
    Py_ssize_t pair_count = views[6].len / 16;
    double others = 0.0, mine = 0.0;
    for (Py_ssize_t q = 0; q < active; q++) {
        Py_ssize_t row = active_rows[q];
        for (int a = 0; a < 2; a++) {
            double travel = fabs(centres[2 * row + a] - found_at[2 * row + a]);
            others = travel > others ? travel : others;
        }
    }
    for (Py_ssize_t m = 0; m < member_count; m++) {
        Py_ssize_t row = members[m];
        for (int a = 0; a < 2; a++) {
            double at = a == axis ? centres[2 * row + a] + shift : centres[2 * row + a];
            double travel = fabs(at - found_at[2 * row + a]);
            mine = travel > mine ? travel : mine;
        }
    }
    if (mine + others <= margin)
        goto answer;
    listed = PyMem_Calloc(count + 1, 1); /* 1: a member; 2: a listed partner of this member */
    if (listed == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    for (Py_ssize_t m = 0; m < member_count; m++)
        listed[members[m]] = 1;
    for (Py_ssize_t m = 0; m < member_count && !near; m++) {
        Py_ssize_t row = members[m];
        PyObject *list = PyList_GET_ITEM(pair_lists, row);
        if (!PyList_Check(list)) {
            PyErr_SetString(PyExc_TypeError, "pair_lists: a list per row");
            goto done;
        }
        Py_ssize_t size = PyList_GET_SIZE(list);
        for (int mark = 2; mark >= 0; mark -= 2) { /* mark the partners, look, unmark them */
            if (mark == 0) {
                double x = centres[2 * row] + (axis == 0 ? shift : 0.0);
                double y = centres[2 * row + 1] + (axis == 1 ? shift : 0.0);
                for (Py_ssize_t q = 0; q < active && !near; q++) {
                    Py_ssize_t other = active_rows[q];
                    if (listed[other])
                        continue;
                    near = fabs(centres[2 * other] - x) < halves[2 * row] + halves[2 * other] + gap
                           && fabs(centres[2 * other + 1] - y)
                              < halves[2 * row + 1] + halves[2 * other + 1] + gap;
                }
            }
            for (Py_ssize_t k = 0; k < size; k++) {
                Py_ssize_t pair = PyLong_AsSsize_t(PyList_GET_ITEM(list, k));
                if (pair == -1 && PyErr_Occurred())
                    goto done;
                if (pair < 0 || pair >= pair_count) {
                    PyErr_SetString(PyExc_IndexError, "pair_lists: a pair outside the table");
                    goto done;
                }
                int64_t other = ends[2 * pair] == row ? ends[2 * pair + 1] : ends[2 * pair];
                if (other < 0 || other >= count) {
                    PyErr_SetString(PyExc_IndexError, "pair_ends: a row outside the table");
                    goto done;
                }
                if (listed[other] != 1)
                    listed[other] = (char)mark;
            }
        }
    }
answer:
    result = PyBool_FromLong(near);
done:
    PyMem_Free(listed);
    for (int k = 0; k < held; k++)
        PyBuffer_Release(&views[k]);
    return result;
}

static PyMethodDef methods[] = {
    {"rest_net", (PyCFunction)(void (*)(void))rest_net, METH_FASTCALL, rest_net_doc},
    {"held_on_lines", (PyCFunction)(void (*)(void))held_on_lines, METH_FASTCALL,
     held_on_lines_doc},
    {"line_mates", (PyCFunction)(void (*)(void))line_mates, METH_FASTCALL, line_mates_doc},
    {"reach_of", (PyCFunction)(void (*)(void))reach_of, METH_FASTCALL, reach_of_doc},
    {"unlisted_near", (PyCFunction)(void (*)(void))unlisted_near, METH_FASTCALL,
     unlisted_near_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "floatpage.physics.rest_check_kernel",
    "The snap's rest check, compiled (physics/rest_check_kernel.c).",
    0,
    methods,
};

PyMODINIT_FUNC PyInit_rest_check_kernel(void)
{
    return PyModule_Create(&module);
}
