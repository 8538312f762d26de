/* Compiled kernels of Euler angles: angles to matrices and quaternions and back. Each loops
 * over a batch, checks each rotation as the Python-float path does and computes the same
 * formulas (eulerlib/_compiled.h says how they stay identical to the numpy-only results); it
 * returns False to hand the whole call to the array path. Private: called only by eulerlib's
 * modules, through eulerlib/_compiled.py.
 *
 * A convention reaches these kernels as one integer, `code` (eulerlib._euler.compiled_code):
 * bits 0-1, 2-3, 4-5 the axes i, j, k of the frame (eulerlib._euler_kernels.frame), bit 6 set
 * when the third axis is −e_k, bit 7 for a proper Euler sequence, bit 8 when the written order
 * is the reverse of the intrinsic one (an extrinsic sequence), bit 9 when the lock policy
 * zeroes the first intrinsic angle. Sines, cosines and arctangents are numpy's, computed by
 * the Python caller between two stages. */
#include "_compiled.h"

typedef struct {
    int index[3];   /* the frame's axes i, j, k */
    double sign[3]; /* its column signs: 1, 1, ±1 */
    int proper, reversed, zero_first;
} Frame;

static int
frame_of(PyObject *object, Frame *f)
{
    long code = PyLong_AsLong(object);
    if (code == -1 && PyErr_Occurred()) {
        return -1;
    }
    for (int n = 0; n < 3; n++) {
        f->index[n] = (int)((code >> (2 * n)) & 3);
        f->sign[n] = 1.0;
    }
    if (code & 64) {
        f->sign[2] = -1.0;
    }
    f->proper = (code & 128) != 0;
    f->reversed = (code & 256) != 0;
    f->zero_first = (code & 512) != 0;
    return 0;
}

/* The rest, in radians, of an angle in degrees after its quarter turns, and their number k
 * mod 4 (quarter_turns). */
static inline double
quarter_rest(double angle, int *turn)
{
    double quarter, rest = quarter_turns(angle, &quarter);
    *turn = quarter_index(quarter);
    return rest;
}

/* angle_rests(out, angles, degrees) -> bool
 * False when an angle is not finite; else, in degrees, writes into `out` the rests that
 * numpy's sine and cosine take (_trig.quarter_turns). In radians `out` is not touched. */
static PyObject *
angle_rests(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 3, "angle_rests") < 0) {
        return NULL;
    }
    int degrees = PyObject_IsTrue(args[2]);
    if (degrees < 0) {
        return NULL;
    }
    Py_buffer angles;
    if (doubles(args[1], &angles, 0) < 0) {
        return NULL;
    }
    const double *a = angles.buf;
    Py_ssize_t n = count_of(&angles);
    int ok = all_finite(a, n);
    if (ok && degrees) {
        Py_buffer out;
        if (doubles(args[0], &out, 1) < 0) {
            PyBuffer_Release(&angles);
            return NULL;
        }
        ok = count_of(&out) == n;
        double *rest = out.buf;
        int turn;
        for (Py_ssize_t m = 0; ok && m < n; m++) {
            rest[m] = quarter_rest(a[m], &turn);
        }
        PyBuffer_Release(&out);
    }
    PyBuffer_Release(&angles);
    return PyBool_FromLong(ok);
}

/* The sine and cosine of three angles from numpy's sine and cosine of their rests, turned by
 * the quarter turns in degrees, with no −0.0 there (_scalar_kernels.sin_cos). */
static inline void
turned(const double *angles, const double *sines, const double *cosines, int degrees, double *s,
       double *c)
{
    for (int n = 0; n < 3; n++) {
        if (!degrees) {
            s[n] = sines[n];
            c[n] = cosines[n];
            continue;
        }
        int turn;
        (void)quarter_rest(angles[n], &turn);
        double sine = sines[n], cosine = cosines[n];
        if (turn == 1) {
            sine = cosines[n];
            cosine = -sines[n];
        } else if (turn == 2) {
            sine = -sines[n];
            cosine = -cosines[n];
        } else if (turn == 3) {
            sine = -cosines[n];
            cosine = sines[n];
        }
        s[n] = sine + 0.0;
        c[n] = cosine + 0.0;
    }
}

/* The entries of the matrix of intrinsic angles with sines s and cosines c
 * (_scalar_kernels.angles_to_entries). */
static void
entries_of(const Frame *f, const double *s, const double *c, double *e)
{
    double s1 = s[0], s2 = s[1], s3 = s[2], c1 = c[0], c2 = c[1], c3 = c[2];
    double M[3][3];
    if (f->proper) {
        M[0][0] = c2;
        M[0][1] = s2 * s3;
        M[0][2] = s2 * c3;
        M[1][0] = s1 * s2;
        M[1][1] = c1 * c3 - s1 * c2 * s3;
        M[1][2] = -c1 * s3 - s1 * c2 * c3;
        M[2][0] = -c1 * s2;
        M[2][1] = s1 * c3 + c1 * c2 * s3;
        M[2][2] = c1 * c2 * c3 - s1 * s3;
    } else {
        s3 = s3 * f->sign[2];
        M[0][0] = c2 * c3;
        M[0][1] = -c2 * s3;
        M[0][2] = s2;
        M[1][0] = c1 * s3 + s1 * s2 * c3;
        M[1][1] = c1 * c3 - s1 * s2 * s3;
        M[1][2] = -s1 * c2;
        M[2][0] = s1 * s3 - c1 * s2 * c3;
        M[2][1] = s1 * c3 + c1 * s2 * s3;
        M[2][2] = c1 * c2;
    }
    for (int r = 0; r < 3; r++) {
        for (int col = 0; col < 3; col++) {
            double value = f->sign[r] * f->sign[col] > 0 ? M[r][col] : -M[r][col];
            e[3 * f->index[r] + f->index[col]] = value + 0.0;
        }
    }
}

/* angles_to_matrices(out, angles, sines, cosines, code, degrees) -> bool
 * The matrices (n, 3, 3) of angles (n, 3) in written order, given numpy's sines and cosines
 * of their rests (angle_rests) in the same layout (_scalar_kernels.angles_to_entries). */
static PyObject *
angles_to_matrices(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 6, "angles_to_matrices") < 0) {
        return NULL;
    }
    Frame f;
    int degrees = PyObject_IsTrue(args[5]);
    if (degrees < 0 || frame_of(args[4], &f) < 0) {
        return NULL;
    }
    Py_buffer v[4];
    if (take_buffers(args, 4, 1, v) < 0) {
        return NULL;
    }
    Py_ssize_t n = count_of(&v[1]) / 3;
    int ok = count_of(&v[0]) == 9 * n && count_of(&v[2]) == 3 * n && count_of(&v[3]) == 3 * n;
    double *e = v[0].buf;
    const double *a = v[1].buf, *sines = v[2].buf, *cosines = v[3].buf;
    int first = f.reversed ? 2 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double s[3], c[3], si[3], ci[3];
        turned(a + 3 * m, sines + 3 * m, cosines + 3 * m, degrees, s, c);
        for (int p = 0; p < 3; p++) { /* written order to intrinsic order */
            si[p] = s[first == 0 ? p : 2 - p];
            ci[p] = c[first == 0 ? p : 2 - p];
        }
        entries_of(&f, si, ci, e + 9 * m);
    }
    release_buffers(v, 4);
    return PyBool_FromLong(ok);
}

/* Entry (r, c) of M = Pᵀ R P (_scalar_kernels.intrinsic_angles's m). */
static inline double
relabelled(const Frame *f, const double *e, int r, int c)
{
    double entry = e[3 * f->index[r] + f->index[c]];
    return f->sign[r] * f->sign[c] > 0 ? entry : -entry;
}

/* The four (y, x) pairs whose arctangents give the angles of one rotation matrix: the middle
 * angle, its distance from lock, the outer angle read from its own ratio and the one solved
 * from it (_scalar_kernels.intrinsic_angles, before its lock test). */
static void
pairs_of(const Frame *f, const double *e, double *y, double *x)
{
#define m(r, c) relabelled(f, e, r, c)
    double sine, cosine, a, b, o0, o1;
    if (f->proper) {
        a = m(0, 1);
        b = m(0, 2);
        sine = sqrt(a * a + b * b);
        cosine = m(0, 0);
        y[0] = sine;
        x[0] = cosine;
        y[1] = sine;
        x[1] = fabs(cosine);
        o0 = f->zero_first ? m(1, 0) : m(0, 1);
        o1 = f->zero_first ? -m(2, 0) : m(0, 2);
    } else {
        sine = m(0, 2);
        a = m(0, 0);
        b = m(0, 1);
        cosine = sqrt(a * a + b * b);
        y[0] = sine;
        x[0] = cosine;
        y[1] = cosine;
        x[1] = fabs(sine);
        o0 = f->zero_first ? -m(1, 2) : -m(0, 1);
        o1 = f->zero_first ? m(2, 2) : m(0, 0);
    }
    y[2] = o0;
    x[2] = o1;
    double length = sqrt(o0 * o0 + o1 * o1), sr = 0.0, cr = 1.0;
    if (length != 0.0) {
        sr = o0 / length;
        cr = o1 / length;
    }
    if (f->proper) {
        if (f->zero_first) {
            y[3] = -(cr * m(1, 2) + sr * m(2, 2));
            x[3] = cr * m(1, 1) + sr * m(2, 1);
        } else {
            y[3] = cr * m(2, 1) - sr * m(2, 2);
            x[3] = cr * m(1, 1) - sr * m(1, 2);
        }
    } else {
        if (f->zero_first) {
            y[3] = cr * m(1, 0) + sr * m(2, 0);
            x[3] = cr * m(1, 1) + sr * m(2, 1);
        } else {
            y[3] = sr * m(2, 0) + cr * m(2, 1);
            x[3] = sr * m(1, 0) + cr * m(1, 1);
        }
    }
#undef m
}

/* Whether every number is at most 2⁵⁰⁰ in size, so that no square or product of two
 * overflows: an overflow makes the array path warn, so the kernels leave it to that path. */
static inline int
all_modest(const double *x, Py_ssize_t n)
{
    for (Py_ssize_t i = 0; i < n; i++) {
        if (!(fabs(x[i]) <= 0x1p+500)) {
            return 0;
        }
    }
    return 1;
}

/* matrices_to_pairs(pairs, R, code, validate, atol) -> bool
 * For matrices R (n, 3, 3), writes into pairs (2, n, 4) the y and x of the four arctangents
 * of each (pairs_of); False when one is not finite, has an entry above 2⁵⁰⁰ or, with
 * validate, is not a rotation. */
static PyObject *
matrices_to_pairs(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 5, "matrices_to_pairs") < 0) {
        return NULL;
    }
    Frame f;
    int validate;
    double atol;
    if (rotation_check(args[3], args[4], &validate, &atol) < 0 || frame_of(args[2], &f) < 0) {
        return NULL;
    }
    Py_buffer v[2];
    if (take_buffers(args, 2, 1, v) < 0) {
        return NULL;
    }
    Py_ssize_t n = count_of(&v[1]) / 9;
    const double *e = v[1].buf;
    double *y = v[0].buf, *x = y + 4 * n;
    int ok = count_of(&v[0]) == 8 * n && all_rotations(e, n, validate, atol) &&
             all_modest(e, 9 * n);
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        pairs_of(&f, e + 9 * m, y + 4 * m, x + 4 * m);
    }
    release_buffers(v, 2);
    return PyBool_FromLong(ok);
}

/* quaternions_to_pairs(pairs, q, scalar_first, code) -> bool
 * matrices_to_pairs for the matrices of quaternions (n, 4) of any length, stored (x, y, z, w)
 * or (w, x, y, z); False when one is not finite or its length needs rescaling. */
static PyObject *
quaternions_to_pairs(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 4, "quaternions_to_pairs") < 0) {
        return NULL;
    }
    Frame f;
    int first = PyObject_IsTrue(args[2]);
    if (first < 0 || frame_of(args[3], &f) < 0) {
        return NULL;
    }
    Py_buffer v[2];
    if (take_buffers(args, 2, 1, v) < 0) {
        return NULL;
    }
    Py_ssize_t n = count_of(&v[1]) / 4;
    const double *q = v[1].buf;
    double *y = v[0].buf, *x = y + 4 * n;
    int ok = count_of(&v[0]) == 8 * n && all_finite(q, 4 * n);
    int w = first ? 0 : 3, i = first ? 1 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *row = q + 4 * m;
        double e[9];
        ok = quaternion_to_entries(row[w], row[i], row[i + 1], row[i + 2], e);
        if (ok) {
            pairs_of(&f, e, y + 4 * m, x + 4 * m);
        }
    }
    release_buffers(v, 2);
    return PyBool_FromLong(ok);
}

/* angles_to_pairs(pairs, angles, sines, cosines, code_in, degrees, code_out) -> bool
 * matrices_to_pairs, for convention code_out, of the matrices of angles in convention code_in
 * (angles_to_matrices), without the matrices. */
static PyObject *
angles_to_pairs(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 7, "angles_to_pairs") < 0) {
        return NULL;
    }
    Frame in, out;
    int degrees = PyObject_IsTrue(args[5]);
    if (degrees < 0 || frame_of(args[4], &in) < 0 || frame_of(args[6], &out) < 0) {
        return NULL;
    }
    Py_buffer v[4];
    if (take_buffers(args, 4, 1, v) < 0) {
        return NULL;
    }
    Py_ssize_t n = count_of(&v[1]) / 3;
    int ok = count_of(&v[0]) == 8 * n && count_of(&v[2]) == 3 * n && count_of(&v[3]) == 3 * n;
    double *y = v[0].buf, *x = y + 4 * n;
    const double *a = v[1].buf, *sines = v[2].buf, *cosines = v[3].buf;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double s[3], c[3], si[3], ci[3], e[9];
        turned(a + 3 * m, sines + 3 * m, cosines + 3 * m, degrees, s, c);
        for (int p = 0; p < 3; p++) {
            si[p] = s[in.reversed ? 2 - p : p];
            ci[p] = c[in.reversed ? 2 - p : p];
        }
        entries_of(&in, si, ci, e);
        pairs_of(&out, e, y + 4 * m, x + 4 * m);
    }
    release_buffers(v, 4);
    return PyBool_FromLong(ok);
}

/* pairs_to_angles(out, arctangents, code, degrees, tolerance) -> bool
 * The angles (n, 3) in written order from the four arctangents (n, 4) of matrices_to_pairs;
 * False when a rotation is within `tolerance` of gimbal lock (_scalar_kernels.intrinsic_angles
 * after its arctangents, then eulerlib._euler.entries_to_angles). */
static PyObject *
pairs_to_angles(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 5, "pairs_to_angles") < 0) {
        return NULL;
    }
    Frame f;
    int degrees = PyObject_IsTrue(args[3]);
    double tolerance = PyFloat_AsDouble(args[4]);
    if (degrees < 0 || (tolerance == -1.0 && PyErr_Occurred()) || frame_of(args[2], &f) < 0) {
        return NULL;
    }
    Py_buffer v[2];
    if (take_buffers(args, 2, 1, v) < 0) {
        return NULL;
    }
    Py_ssize_t n = count_of(&v[1]) / 4;
    int ok = count_of(&v[0]) == 3 * n;
    const double *t = v[1].buf;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        ok = !(t[4 * m + 1] <= tolerance);
    }
    double *angles = v[0].buf;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *row = t + 4 * m;
        double first = f.zero_first ? row[2] : row[3];
        double third = f.zero_first ? row[3] : row[2];
        if (!f.proper) {
            third = third * f.sign[2];
        }
        double intrinsic[3] = {first + 0.0, row[0] + 0.0, third + 0.0};
        for (int p = 0; p < 3; p++) {
            double angle = intrinsic[f.reversed ? 2 - p : p];
            if (angle == -M_PI) {
                angle = M_PI;
            }
            angles[3 * m + p] = degrees ? angle * (180.0 / M_PI) : angle;
        }
    }
    release_buffers(v, 2);
    return PyBool_FromLong(ok);
}

/* half_angles(out, angles, degrees) -> bool
 * False when an angle is not finite; else writes into `out` the half angles whose tangents
 * numpy gives (_trig.half_angle_pair): half of each angle in radians, half of its rest after
 * the quarter turns in degrees. */
static PyObject *
half_angles(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 3, "half_angles") < 0) {
        return NULL;
    }
    int degrees = PyObject_IsTrue(args[2]);
    if (degrees < 0) {
        return NULL;
    }
    Py_buffer v[2];
    if (take_buffers(args, 2, 1, v) < 0) {
        return NULL;
    }
    Py_ssize_t n = count_of(&v[1]);
    double *half = v[0].buf;
    const double *a = v[1].buf;
    int ok = count_of(&v[0]) == n && all_finite(a, n);
    int turn;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        half[m] = 0.5 * (degrees ? quarter_rest(a[m], &turn) : a[m]);
    }
    release_buffers(v, 2);
    return PyBool_FromLong(ok);
}

/* The canonical quaternion (w, x, y, z) of intrinsic angles given by the multiples (c, s) of
 * the cosines and sines of their halves (_scalar_kernels.euler_to_quaternion). */
static void
quaternion_of(const Frame *f, const double *c, const double *s, double *q)
{
    double c1 = c[0], c2 = c[1], c3 = c[2], s1 = s[0], s2 = s[1], s3 = s[2];
    int i = f->index[0], j = f->index[1], k = f->index[2];
    if (f->proper) {
        q[0] = c2 * (c1 * c3 - s1 * s3);
        q[1 + i] = c2 * (c1 * s3 + s1 * c3);
        q[1 + j] = s2 * (c1 * c3 + s1 * s3);
        q[1 + k] = s2 * (s1 * c3 - c1 * s3);
    } else {
        s3 = s3 * f->sign[2];
        double c1c2 = c1 * c2, s1s2 = s1 * s2, s1c2 = s1 * c2, c1s2 = c1 * s2;
        q[0] = c1c2 * c3 - s1s2 * s3;
        q[1 + i] = s1c2 * c3 + c1s2 * s3;
        q[1 + j] = c1s2 * c3 - s1c2 * s3;
        q[1 + k] = c1c2 * s3 + s1s2 * c3;
    }
    if (f->sign[2] < 0) {
        q[1 + k] *= -1.0;
    }
    double factor =
        sqrt(1.0 / ((c1 * c1 + s1 * s1) * (c2 * c2 + s2 * s2) * (c3 * c3 + s3 * s3)));
    for (int n = 0; n < 4; n++) {
        q[n] = q[n] * factor;
    }
    make_canonical(q);
}

/* angles_to_quaternions(out, angles, tangents, code, degrees, scalar_first) -> bool
 * The canonical quaternions (n, 4), stored (x, y, z, w) or (w, x, y, z), of angles (n, 3) in
 * written order, given numpy's tangents of their half angles (half_angles). */
static PyObject *
angles_to_quaternions(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 6, "angles_to_quaternions") < 0) {
        return NULL;
    }
    Frame f;
    int degrees = PyObject_IsTrue(args[4]);
    int first = PyObject_IsTrue(args[5]);
    if (degrees < 0 || first < 0 || frame_of(args[3], &f) < 0) {
        return NULL;
    }
    Py_buffer v[3];
    if (take_buffers(args, 3, 1, v) < 0) {
        return NULL;
    }
    Py_ssize_t n = count_of(&v[1]) / 3;
    int ok = count_of(&v[0]) == 4 * n && count_of(&v[2]) == 3 * n;
    double *out = v[0].buf;
    const double *a = v[1].buf, *t = v[2].buf;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double c[3], s[3], q[4];
        for (int p = 0; p < 3; p++) { /* intrinsic angle p is written angle w */
            int w = f.reversed ? 2 - p : p;
            double quarter = 0.0;
            if (degrees) {
                (void)quarter_turns(a[3 * m + w], &quarter);
            }
            half_pair(t[3 * m + w], quarter, degrees, &c[p], &s[p]);
        }
        quaternion_of(&f, c, s, q);
        double *row = out + 4 * m;
        if (first) {
            memcpy(row, q, sizeof q);
        } else {
            row[0] = q[1];
            row[1] = q[2];
            row[2] = q[3];
            row[3] = q[0];
        }
    }
    release_buffers(v, 3);
    return PyBool_FromLong(ok);
}

/* elementary_matrices(out, angles, sines, cosines, axis, degrees) -> bool
 * The matrices (n, 3, 3) of turns by n angles about the axis 0, 1 or 2, given numpy's sines
 * and cosines of their rests (angle_rests); as eulerlib.elementary_rotation writes them. */
static PyObject *
elementary_matrices(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 6, "elementary_matrices") < 0) {
        return NULL;
    }
    long axis = PyLong_AsLong(args[4]);
    int degrees = PyObject_IsTrue(args[5]);
    if ((axis == -1 && PyErr_Occurred()) || degrees < 0) {
        return NULL;
    }
    Py_buffer v[4];
    if (take_buffers(args, 4, 1, v) < 0) {
        return NULL;
    }
    Py_ssize_t n = count_of(&v[1]);
    int ok = 0 <= axis && axis <= 2 && count_of(&v[0]) == 9 * n && count_of(&v[2]) == n &&
             count_of(&v[3]) == n;
    int index = (int)axis, i = (index + 1) % 3, j = (index + 2) % 3;
    double *e = v[0].buf;
    const double *a = v[1].buf, *sines = v[2].buf, *cosines = v[3].buf;
    /* where each entry goes: the turn's axis is index, the plane is spanned by i and j */
    int zero0 = 3 * index + i, zero1 = 3 * index + j, zero2 = 3 * i + index, zero3 = 3 * j + index;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double sine = sines[m], cosine = cosines[m];
        if (degrees) {
            double three[3] = {a[m], 0.0, 0.0}, s3[3] = {sine, 0.0, 0.0};
            double c3[3] = {cosine, 1.0, 1.0}, s[3], c[3];
            turned(three, s3, c3, degrees, s, c);
            sine = s[0];
            cosine = c[0];
        }
        double *r = e + 9 * m;
        r[4 * index] = 1.0;
        r[zero0] = 0.0;
        r[zero1] = 0.0;
        r[zero2] = 0.0;
        r[zero3] = 0.0;
        r[4 * i] = cosine;
        r[4 * j] = cosine;
        r[3 * i + j] = 0.0 - sine;
        r[3 * j + i] = sine;
    }
    release_buffers(v, 4);
    return PyBool_FromLong(ok);
}


static PyMethodDef methods[] = {
    KERNEL(angle_rests),
    KERNEL(angles_to_matrices),
    KERNEL(matrices_to_pairs),
    KERNEL(quaternions_to_pairs),
    KERNEL(angles_to_pairs),
    KERNEL(pairs_to_angles),
    KERNEL(half_angles),
    KERNEL(angles_to_quaternions),
    KERNEL(elementary_matrices),
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "eulerlib._compiled_euler",
    "Compiled kernels of Euler angles (optional).", -1,
    methods, NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC
PyInit__compiled_euler(void)
{
    return PyModule_Create(&module);
}
