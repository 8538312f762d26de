/* Compiled kernels of rotations other than Euler angles: quaternions, rotation vectors, axis
 * and angle, and the operations on matrices. Each loops over a batch, checks each rotation as
 * the Python-float path does and computes the same formulas (eulerlib/_compiled.h says how they
 * stay identical to the numpy-only results); it returns False to hand the whole call to the
 * array path. Private: called only by eulerlib's modules, through eulerlib/_compiled.py. */
#include "_compiled.h"

/* quaternions_to_matrices(out, q, scalar_first) -> bool
 * The matrices (n, 3, 3) of quaternions (n, 4) of any length, stored (x, y, z, w) or, with
 * scalar_first, (w, x, y, z); False when one is not finite or its length needs rescaling. */
static PyObject *
quaternions_to_matrices(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 3, "quaternions_to_matrices") < 0) {
        return NULL;
    }
    int first = PyObject_IsTrue(args[2]);
    if (first < 0) {
        return NULL;
    }
    Py_buffer out, q;
    if (doubles(args[0], &out, 1) < 0) {
        return NULL;
    }
    if (doubles(args[1], &q, 0) < 0) {
        PyBuffer_Release(&out);
        return NULL;
    }
    Py_ssize_t n = count_of(&q) / 4;
    const double *in = q.buf;
    double *e = out.buf;
    int ok = count_of(&out) == 9 * n && all_finite(in, 4 * n);
    int w = first ? 0 : 3, x = first ? 1 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *row = in + 4 * m;
        ok = quaternion_to_entries(row[w], row[x], row[x + 1], row[x + 2], e + 9 * m);
    }
    PyBuffer_Release(&q);
    PyBuffer_Release(&out);
    return PyBool_FromLong(ok);
}

/* What numpy's tan takes for the half angle of `angle` (_scalar_kernels.half_angle_pair): θ/2,
 * or in degrees r/2 of angle = k·90° + r with r in radians (_scalar_kernels.quarter_turns);
 * k goes to *quarter (0 in radians). */
static inline double
half_argument(double angle, int degrees, double *quarter)
{
    *quarter = 0.0;
    if (!degrees) {
        return 0.5 * angle;
    }
    return 0.5 * quarter_turns(angle, quarter);
}

/* matrices_to_quaternions(out, R, scalar_first, validate, atol) -> bool
 * Canonical unit quaternions (n, 4) of matrices (n, 3, 3), stored (x, y, z, w) or with
 * scalar_first (w, x, y, z) (matrix_to_quaternion's Python-float path: entries_to_quaternion,
 * then normalized); False when a matrix is not finite or, with validate, not a rotation within
 * atol, or a result is not finite. */
static PyObject *
matrices_to_quaternions(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 5, "matrices_to_quaternions") < 0) {
        return NULL;
    }
    int first = PyObject_IsTrue(args[2]), validate;
    double atol;
    if (first < 0 || rotation_check(args[3], args[4], &validate, &atol) < 0) {
        return NULL;
    }
    Py_buffer views[2];
    if (take_buffers(args, 2, 1, views) < 0) {
        return NULL;
    }
    double *out = views[0].buf;
    const double *e = views[1].buf;
    Py_ssize_t n = count_of(&views[1]) / 9;
    int ok = count_of(&views[0]) == 4 * n && all_rotations(e, n, validate, atol);
    int w = first ? 0 : 3, x = first ? 1 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double q[4];
        entries_to_quaternion(e + 9 * m, q);
        double length = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        double *row = out + 4 * m;
        row[w] = q[0] / length;
        row[x] = q[1] / length;
        row[x + 1] = q[2] / length;
        row[x + 2] = q[3] / length;
        ok = all_finite(row, 4);
    }
    release_buffers(views, 2);
    return PyBool_FromLong(ok);
}

/* rotvec_half_angles(half, v, degrees) -> bool
 * Stage 1 of rotvec_to_matrix (_scalar_kernels.rotvec_to_entries): for each vector (n, 3), the
 * argument of numpy's tan for half its length; False when a squared length needs rescaling
 * (the zero vector included) or is not finite. */
static PyObject *
rotvec_half_angles(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 3, "rotvec_half_angles") < 0) {
        return NULL;
    }
    int degrees = PyObject_IsTrue(args[2]);
    if (degrees < 0) {
        return NULL;
    }
    Py_buffer views[2];
    if (take_buffers(args, 2, 1, views) < 0) {
        return NULL;
    }
    double *half = views[0].buf;
    const double *v = views[1].buf;
    Py_ssize_t n = count_of(&views[1]) / 3;
    int ok = count_of(&views[0]) == n;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double squared = squared_length(v + 3 * m, 3), quarter;
        ok = squared >= 0.0;
        half[m] = half_argument(sqrt(squared), degrees, &quarter);
    }
    release_buffers(views, 2);
    return PyBool_FromLong(ok);
}

/* rotvecs_to_matrices(out, v, t, degrees) -> bool
 * Stage 2 of rotvec_to_matrix (_scalar_kernels.rotvec_to_entries): the matrices (n, 3, 3) of
 * rotation vectors (n, 3) that passed stage 1, with t the tangents of its half angles. */
static PyObject *
rotvecs_to_matrices(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 4, "rotvecs_to_matrices") < 0) {
        return NULL;
    }
    int degrees = PyObject_IsTrue(args[3]);
    if (degrees < 0) {
        return NULL;
    }
    Py_buffer views[3];
    if (take_buffers(args, 3, 1, views) < 0) {
        return NULL;
    }
    double *e = views[0].buf;
    const double *v = views[1].buf, *t = views[2].buf;
    Py_ssize_t n = count_of(&views[1]) / 3;
    int ok = count_of(&views[0]) == 9 * n && count_of(&views[2]) == n;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *r = v + 3 * m;
        double squared = squared_length(r, 3), quarter, a, b;
        double length = sqrt(squared);
        ok = squared >= 0.0;
        half_argument(length, degrees, &quarter);
        half_pair(t[m], quarter, degrees, &a, &b);
        double factor = b / length;
        ok = ok && quaternion_to_entries(a, r[0] * factor, r[1] * factor, r[2] * factor,
                                         e + 9 * m);
    }
    release_buffers(views, 3);
    return PyBool_FromLong(ok);
}

/* half_angles(half, angle, degrees) -> bool
 * Stage 1 of axis_angle_to_matrix (_scalar_kernels.half_angle_pair): the argument of numpy's
 * tan for each angle (n,); False when one is not finite. */
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
    Py_buffer views[2];
    if (take_buffers(args, 2, 1, views) < 0) {
        return NULL;
    }
    double *half = views[0].buf;
    const double *angle = views[1].buf;
    Py_ssize_t n = count_of(&views[1]);
    int ok = count_of(&views[0]) == n && all_finite(angle, n);
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double quarter;
        half[m] = half_argument(angle[m], degrees, &quarter);
    }
    release_buffers(views, 2);
    return PyBool_FromLong(ok);
}

/* axis_angles_to_matrices(out, axis, angle, t, degrees) -> bool
 * Stage 2 of axis_angle_to_matrix (_scalar_kernels.axis_angle_to_entries): the matrices
 * (n, 3, 3) of turns about axes (n, 3) or one axis (1, 3) by angles (n,) or one angle (1,)
 * that passed stage 1, t the tangents of their half angles; False when an axis is zero or not
 * finite. */
static PyObject *
axis_angles_to_matrices(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 5, "axis_angles_to_matrices") < 0) {
        return NULL;
    }
    int degrees = PyObject_IsTrue(args[4]);
    if (degrees < 0) {
        return NULL;
    }
    Py_buffer views[4];
    if (take_buffers(args, 4, 1, views) < 0) {
        return NULL;
    }
    double *e = views[0].buf;
    const double *axis = views[1].buf, *angle = views[2].buf, *t = views[3].buf;
    Py_ssize_t n = count_of(&views[0]) / 9, axes = count_of(&views[1]) / 3;
    Py_ssize_t angles = count_of(&views[2]);
    int ok = count_of(&views[3]) == angles && (axes == n || axes == 1) &&
             (angles == n || angles == 1) && all_finite(axis, 3 * axes);
    Py_ssize_t axis_step = axes == n ? 3 : 0, angle_step = angles == n ? 1 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *r = axis + axis_step * m;
        double largest = max2(max2(fabs(r[0]), fabs(r[1])), fabs(r[2]));
        if (largest == 0.0) {
            ok = 0;
            break;
        }
        int exponent;
        frexp(largest, &exponent);
        double x = ldexp(r[0], -exponent), y = ldexp(r[1], -exponent),
               z = ldexp(r[2], -exponent);
        double squared = x * x;
        squared += y * y;
        squared += z * z;
        double quarter, a, b;
        half_argument(angle[angle_step * m], degrees, &quarter);
        half_pair(t[angle_step * m], quarter, degrees, &a, &b);
        ok = quaternion_to_entries(a * sqrt(squared), x * b, y * b, z * b, e + 9 * m);
    }
    release_buffers(views, 4);
    return PyBool_FromLong(ok);
}

/* The Euclidean length of a vector of three at any scale, as the array path's
 * _length_kernels.lengths: sqrt of the sum of squares in order, or where that sum needs
 * rescaling, the same for the vector scaled exactly by the power of two of its largest
 * component, scaled back (the Python-float twins return None there instead). */
static inline double
scaled_length(const double *v)
{
    double squared = v[0] * v[0];
    squared += v[1] * v[1];
    squared += v[2] * v[2];
    if (EULERLIB_SMALL <= squared && squared <= EULERLIB_LARGE) {
        return sqrt(squared);
    }
    int exponent;
    frexp(max2(max2(fabs(v[0]), fabs(v[1])), fabs(v[2])), &exponent);
    double x = ldexp(v[0], -exponent), y = ldexp(v[1], -exponent), z = ldexp(v[2], -exponent);
    squared = x * x;
    squared += y * y;
    squared += z * z;
    return ldexp(sqrt(squared), exponent);
}

/* the smallest subnormal, which the array path divides by instead of a zero length
 * (_length_kernels.TINY) */
#define EULERLIB_TINY 0x1p-1074

/* The vector part v of the canonical quaternion of a rotation matrix (entries_to_quaternion),
 * its length, and what the array path divides v by: the length, or EULERLIB_TINY for a zero
 * vector part (_quaternion_kernels.unit_axes and rotation_vectors). 0 when the quaternion is
 * not finite or zero, which only an unchecked matrix with entries near the largest float
 * gives, and where the array path warns of an overflow. */
static inline int
vector_part(const double *e, double *v, double *length, double *divisor)
{
    double q[4];
    entries_to_quaternion(e, q);
    v[0] = q[1];
    v[1] = q[2];
    v[2] = q[3];
    *length = scaled_length(v);
    *divisor = max2(*length, EULERLIB_TINY);
    return all_finite(q, 4) && (q[0] != 0.0 || *length != 0.0);
}

/* angle_arguments(yx, R, validate, atol) -> bool
 * Stage 1 of rotation_angle (_scalar_kernels.rotation_angle, and for |s| at any scale
 * _quaternion_kernels.rotation_angles): for matrices (n, 3, 3), the arguments of numpy's
 * arctan2 as rows (2, n), y = |s| for the skew part s and x = trace − 1; False when a matrix
 * is not finite or, with validate, not a rotation within atol, or a sum overflows. */
static PyObject *
angle_arguments(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 4, "angle_arguments") < 0) {
        return NULL;
    }
    int validate;
    double atol;
    if (rotation_check(args[2], args[3], &validate, &atol) < 0) {
        return NULL;
    }
    Py_buffer views[2];
    if (take_buffers(args, 2, 1, views) < 0) {
        return NULL;
    }
    double *yx = views[0].buf;
    const double *entries = views[1].buf;
    Py_ssize_t n = count_of(&views[1]) / 9;
    int ok = count_of(&views[0]) == 2 * n && all_rotations(entries, n, validate, atol);
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *e = entries + 9 * m;
        double s[3] = {e[7] - e[5], e[2] - e[6], e[3] - e[1]};
        double trace = e[0] + e[4];
        trace += e[8];
        yx[m] = scaled_length(s);
        yx[n + m] = trace - 1.0;
        ok = all_finite(s, 3) && all_finite(yx + m, 1) && all_finite(yx + n + m, 1);
    }
    release_buffers(views, 2);
    return PyBool_FromLong(ok);
}

/* relative_angle_arguments(yx, R0, R1, validate, atol) -> bool
 * Stage 1 of angle_between (_scalar_kernels.relative_angle, and for |s| at any scale
 * _quaternion_kernels.relative_angles): for matrices R0 and R1, (n, 3, 3) or one (1, 3, 3),
 * the arguments of numpy's arctan2 for the angle of R0ᵀ R1 as rows (2, n); False when a matrix
 * is not finite or, with validate, not a rotation within atol, or a sum overflows. */
static PyObject *
relative_angle_arguments(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 5, "relative_angle_arguments") < 0) {
        return NULL;
    }
    int validate;
    double atol;
    if (rotation_check(args[3], args[4], &validate, &atol) < 0) {
        return NULL;
    }
    Py_buffer views[3];
    if (take_buffers(args, 3, 1, views) < 0) {
        return NULL;
    }
    double *yx = views[0].buf;
    const double *first = views[1].buf, *second = views[2].buf;
    Py_ssize_t n = count_of(&views[0]) / 2;
    Py_ssize_t n0 = count_of(&views[1]) / 9, n1 = count_of(&views[2]) / 9;
    int ok = (n0 == n || n0 == 1) && (n1 == n || n1 == 1) &&
             all_rotations(first, n0, validate, atol) &&
             all_rotations(second, n1, validate, atol);
    Py_ssize_t step0 = n0 == n ? 9 : 0, step1 = n1 == n ? 9 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *a = first + step0 * m, *b = second + step1 * m;
        double trace = a[0] * b[0];
        for (int i = 1; i < 9; i++) {
            trace += a[i] * b[i];
        }
        double skew[3] = {0.0, 0.0, 0.0};
        for (int k = 0; k < 3; k++) {
            const double *p = a + 3 * k, *q = b + 3 * k;
            skew[0] += q[1] * p[2] - q[2] * p[1];
            skew[1] += q[2] * p[0] - q[0] * p[2];
            skew[2] += q[0] * p[1] - q[1] * p[0];
        }
        yx[m] = scaled_length(skew);
        yx[n + m] = trace - 1.0;
        ok = all_finite(skew, 3) && all_finite(yx + m, 1) && all_finite(yx + n + m, 1);
    }
    release_buffers(views, 3);
    return PyBool_FromLong(ok);
}

/* matrices_to_rotvecs(out, R, turn) -> bool
 * Stage 2 of matrix_to_rotvec (its Python-float path, and for the identity and tiny turns
 * _quaternion_kernels.rotation_vectors): the rotation vectors (n, 3) of matrices (n, 3, 3)
 * that passed angle_arguments, turn their angles (radians or degrees); False when a turn over
 * the length of the vector part overflows (a matrix that is not a rotation, unchecked). */
static PyObject *
matrices_to_rotvecs(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 3, "matrices_to_rotvecs") < 0) {
        return NULL;
    }
    Py_buffer views[3];
    if (take_buffers(args, 3, 1, views) < 0) {
        return NULL;
    }
    double *out = views[0].buf;
    const double *entries = views[1].buf, *turn = views[2].buf;
    Py_ssize_t n = count_of(&views[1]) / 9;
    int ok = count_of(&views[0]) == 3 * n && count_of(&views[2]) == n;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double v[3], length, divisor;
        ok = vector_part(entries + 9 * m, v, &length, &divisor);
        double factor = turn[m] / divisor;
        ok = ok && all_finite(&factor, 1); /* else the array path warns of an overflow */
        for (int i = 0; i < 3; i++) {
            out[3 * m + i] = v[i] * factor;
        }
    }
    release_buffers(views, 3);
    return PyBool_FromLong(ok);
}

/* matrices_to_axes(out, R) -> bool
 * The unit axes (n, 3) of matrices (n, 3, 3) that passed angle_arguments, as
 * matrix_to_axis_angle's Python-float path (_one_axis_angle), and for the identity and tiny
 * turns as _quaternion_kernels.unit_axes; False for an unchecked matrix whose quaternion
 * overflows. */
static PyObject *
matrices_to_axes(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 2, "matrices_to_axes") < 0) {
        return NULL;
    }
    Py_buffer views[2];
    if (take_buffers(args, 2, 1, views) < 0) {
        return NULL;
    }
    double *out = views[0].buf;
    const double *entries = views[1].buf;
    Py_ssize_t n = count_of(&views[1]) / 9;
    int ok = count_of(&views[0]) == 3 * n;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double v[3], length, divisor;
        ok = vector_part(entries + 9 * m, v, &length, &divisor);
        for (int i = 0; i < 3; i++) {
            out[3 * m + i] = v[i] / divisor;
        }
        if (length == 0.0) { /* the identity: (1, 0, 0) by convention */
            out[3 * m] = 1.0;
        }
    }
    release_buffers(views, 2);
    return PyBool_FromLong(ok);
}

/* vector_directions(unit, length, v) -> bool
 * Stage 1 of the exponential of pure quaternions (_algebra_kernels.directions where every
 * squared length is in range): for each vector (n, 3) its length and v / length; False when a
 * squared length needs rescaling (the zero vector included) or is not finite. */
static PyObject *
vector_directions(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 3, "vector_directions") < 0) {
        return NULL;
    }
    Py_buffer views[3];
    if (take_buffers(args, 3, 2, views) < 0) {
        return NULL;
    }
    double *unit = views[0].buf, *length = views[1].buf;
    const double *v = views[2].buf;
    Py_ssize_t n = count_of(&views[2]) / 3;
    int ok = count_of(&views[0]) == 3 * n && count_of(&views[1]) == n;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double squared = squared_length(v + 3 * m, 3);
        ok = squared >= 0.0;
        double size = sqrt(squared);
        length[m] = size;
        for (int i = 0; i < 3; i++) {
            unit[3 * m + i] = v[3 * m + i] / size;
        }
    }
    release_buffers(views, 3);
    return PyBool_FromLong(ok);
}

/* pure_exponentials(out, unit, sines, cosines, scalar_first) -> bool
 * Stage 2 (_algebra_kernels.exponentials of pure quaternions, stored as quaternion_exp
 * writes them, without -0.0): (cos, sin · unit) for n vectors, given numpy's sine and cosine
 * of their lengths. */
static PyObject *
pure_exponentials(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 5, "pure_exponentials") < 0) {
        return NULL;
    }
    int first = PyObject_IsTrue(args[4]);
    if (first < 0) {
        return NULL;
    }
    Py_buffer views[4];
    if (take_buffers(args, 4, 1, views) < 0) {
        return NULL;
    }
    double *out = views[0].buf;
    const double *unit = views[1].buf, *sines = views[2].buf, *cosines = views[3].buf;
    Py_ssize_t n = count_of(&views[2]);
    int ok = count_of(&views[0]) == 4 * n && count_of(&views[1]) == 3 * n &&
             count_of(&views[3]) == n;
    int w = first ? 0 : 3, x = first ? 1 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double *q = out + 4 * m;
        q[w] = cosines[m] + 0.0;
        for (int i = 0; i < 3; i++) {
            q[x + i] = unit[3 * m + i] * sines[m] + 0.0;
        }
    }
    release_buffers(views, 4);
    return PyBool_FromLong(ok);
}

static PyMethodDef methods[] = {
    KERNEL(quaternions_to_matrices),
    KERNEL(matrices_to_quaternions),
    KERNEL(rotvec_half_angles),
    KERNEL(rotvecs_to_matrices),
    KERNEL(half_angles),
    KERNEL(axis_angles_to_matrices),
    KERNEL(angle_arguments),
    KERNEL(relative_angle_arguments),
    KERNEL(matrices_to_rotvecs),
    KERNEL(matrices_to_axes),
    KERNEL(vector_directions),
    KERNEL(pure_exponentials),
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "eulerlib._compiled_rotations",
    "Compiled kernels of quaternions, rotation vectors and matrix operations (optional).", -1,
    methods, NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC
PyInit__compiled_rotations(void)
{
    return PyModule_Create(&module);
}
