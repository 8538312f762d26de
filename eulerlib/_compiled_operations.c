/* Compiled kernels of the operations on rotation matrices: rotating points, inverting,
 * composing, interpolating and integrating. Each loops over a batch, checks each rotation as
 * the Python-float path does and computes the same formulas (eulerlib/_compiled.h says how they
 * stay identical to the numpy-only results); it returns False to hand the whole call to the
 * array path. Private: called only by eulerlib's modules, through eulerlib/_compiled.py. */
#include "_compiled.h"

/* the most factors compose takes in one call; more are handed to the array path */
#define MOST_FACTORS 32

/* invert(out, R, validate, atol) -> bool
 * The transposes (n, 3, 3) of matrices (n, 3, 3), as invert's swapaxes; False when one is not
 * finite or, with validate, not a rotation within atol. */
static PyObject *
invert(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 4, "invert") < 0) {
        return NULL;
    }
    int validate;
    double atol;
    if (rotation_check(args[2], args[3], &validate, &atol) < 0) {
        return NULL;
    }
    Py_buffer out, R;
    if (doubles(args[0], &out, 1) < 0) {
        return NULL;
    }
    if (doubles(args[1], &R, 0) < 0) {
        PyBuffer_Release(&out);
        return NULL;
    }
    Py_ssize_t n = count_of(&R) / 9;
    const double *in = R.buf;
    double *e = out.buf;
    int ok = count_of(&out) == 9 * n && count_of(&R) == 9 * n &&
             all_rotations(in, n, validate, atol);
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *a = in + 9 * m;
        double *t = e + 9 * m;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                t[3 * i + j] = a[3 * j + i];
            }
        }
    }
    PyBuffer_Release(&R);
    PyBuffer_Release(&out);
    return PyBool_FromLong(ok);
}

/* compose(out, validate, atol, *factors) -> bool
 * The products (n, 3, 3), left to right and without negative zeros, of factors that each hold
 * one matrix (used for every product) or n matrices (compose's product and += 0.0 per factor;
 * a single factor is copied). False when a matrix is not finite or, with validate, not a
 * rotation within atol, or when a factor holds another number of matrices. */
static PyObject *
compose(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (nargs < 4) {
        PyErr_SetString(PyExc_TypeError, "compose takes at least 4 arguments");
        return NULL;
    }
    Py_ssize_t count = nargs - 3;
    if (count > MOST_FACTORS) {
        Py_RETURN_FALSE;
    }
    int validate;
    double atol;
    if (rotation_check(args[1], args[2], &validate, &atol) < 0) {
        return NULL;
    }
    Py_buffer out, factor[MOST_FACTORS];
    if (doubles(args[0], &out, 1) < 0) {
        return NULL;
    }
    Py_ssize_t taken = 0;
    for (; taken < count; taken++) {
        if (doubles(args[3 + taken], &factor[taken], 0) < 0) {
            break;
        }
    }
    int failed = taken < count;
    Py_ssize_t n = count_of(&out) / 9;
    int ok = !failed && count_of(&out) == 9 * n;
    const double *source[MOST_FACTORS];
    Py_ssize_t step[MOST_FACTORS]; /* 9 for a factor of n matrices, 0 for one matrix */
    for (Py_ssize_t k = 0; ok && k < count; k++) {
        Py_ssize_t matrices = count_of(&factor[k]) / 9;
        source[k] = factor[k].buf;
        step[k] = matrices == n ? 9 : 0;
        ok = count_of(&factor[k]) == 9 * matrices && (matrices == n || matrices == 1) &&
             all_rotations(source[k], matrices, validate, atol);
    }
    double *e = out.buf;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double *result = e + 9 * m;
        if (count == 1) {
            memcpy(result, source[0] + step[0] * m, 9 * sizeof(double));
            continue;
        }
        double left[9], right[9];
        memcpy(left, source[0] + step[0] * m, sizeof left);
        for (Py_ssize_t k = 1; k < count; k++) {
            if (k + 1 == count) {
                product(left, source[k] + step[k] * m, result);
            } else {
                product(left, source[k] + step[k] * m, right);
                memcpy(left, right, sizeof left);
            }
        }
    }
    for (Py_ssize_t k = 0; k < taken; k++) {
        PyBuffer_Release(&factor[k]);
    }
    PyBuffer_Release(&out);
    if (failed) {
        return NULL;
    }
    return PyBool_FromLong(ok);
}

/* rotate_points(out, R, points, validate, atol) -> bool
 * R p for n pairs (out (n, 3)) of one matrix or n matrices (n, 3, 3) and one point or n points
 * (n, 3), each coordinate (r0 x + r1 y) + r2 z as rotate_points' _rotated. False when a number
 * is not finite, a matrix is not a rotation within atol (with validate), a rotated point is not
 * finite (the array path rescales it), or the counts do not match. */
static PyObject *
rotate_points(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 5, "rotate_points") < 0) {
        return NULL;
    }
    int validate;
    double atol;
    if (rotation_check(args[3], args[4], &validate, &atol) < 0) {
        return NULL;
    }
    Py_buffer out, R, points;
    if (doubles(args[0], &out, 1) < 0) {
        return NULL;
    }
    if (doubles(args[1], &R, 0) < 0) {
        PyBuffer_Release(&out);
        return NULL;
    }
    if (doubles(args[2], &points, 0) < 0) {
        PyBuffer_Release(&R);
        PyBuffer_Release(&out);
        return NULL;
    }
    Py_ssize_t n = count_of(&out) / 3;
    Py_ssize_t matrices = count_of(&R) / 9, vectors = count_of(&points) / 3;
    const double *r = R.buf, *p = points.buf;
    double *e = out.buf;
    int ok = count_of(&out) == 3 * n && count_of(&R) == 9 * matrices &&
             count_of(&points) == 3 * vectors && (matrices == n || matrices == 1) &&
             (vectors == n || vectors == 1) && all_rotations(r, matrices, validate, atol);
    /* A point that is not finite makes its rotated point not finite (a finite matrix turns an
     * infinity into an infinity or a NaN, and a NaN stays one), so one test of the results, in
     * the same pass, checks both; it collects flags, without a branch per point. */
    int bad = 0;
    if (ok && matrices == 1) { /* one matrix turning many points: its rows stay in registers */
        double a0 = r[0], a1 = r[1], a2 = r[2], a3 = r[3], a4 = r[4], a5 = r[5], a6 = r[6],
               a7 = r[7], a8 = r[8];
        Py_ssize_t p_step = vectors == n ? 3 : 0;
        for (Py_ssize_t m = 0; m < n; m++) {
            const double *v = p + p_step * m;
            double *x = e + 3 * m;
            double t0 = a0 * v[0], t1 = a3 * v[0], t2 = a6 * v[0];
            t0 += a1 * v[1];
            t1 += a4 * v[1];
            t2 += a7 * v[1];
            x[0] = t0 + a2 * v[2];
            x[1] = t1 + a5 * v[2];
            x[2] = t2 + a8 * v[2];
            bad |= !(x[0] - x[0] == 0.0) | !(x[1] - x[1] == 0.0) | !(x[2] - x[2] == 0.0);
        }
    } else if (ok) {
        Py_ssize_t p_step = vectors == n ? 3 : 0;
        for (Py_ssize_t m = 0; m < n; m++) {
            const double *a = r + 9 * m, *v = p + p_step * m;
            double *x = e + 3 * m;
            for (int i = 0; i < 3; i++) {
                double total = a[3 * i] * v[0];
                total += a[3 * i + 1] * v[1];
                x[i] = total + a[3 * i + 2] * v[2];
            }
            bad |= !(x[0] - x[0] == 0.0) | !(x[1] - x[1] == 0.0) | !(x[2] - x[2] == 0.0);
        }
    }
    ok = ok && !bad;
    PyBuffer_Release(&points);
    PyBuffer_Release(&R);
    PyBuffer_Release(&out);
    return PyBool_FromLong(ok);
}

/* slerp_relative(relative, sine, R0, R1, validate, atol) -> bool
 * First stage of slerp for n rotations (slerp_entries up to its arctangent): the canonical
 * quaternion (w, x, y, z) of R0ᵀ R1 into relative (n, 4) and the length of its vector part
 * into sine (n); R0 and R1 hold one matrix or n each. False when a matrix is not finite or,
 * with validate, not a rotation within atol, or when the length needs rescaling. */
static PyObject *
slerp_relative(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 6, "slerp_relative") < 0) {
        return NULL;
    }
    int validate;
    double atol;
    if (rotation_check(args[4], args[5], &validate, &atol) < 0) {
        return NULL;
    }
    Py_buffer view[4];
    int taken = 0;
    for (; taken < 4; taken++) {
        if (doubles(args[taken], &view[taken], taken < 2) < 0) {
            break;
        }
    }
    if (taken < 4) {
        for (int k = 0; k < taken; k++) {
            PyBuffer_Release(&view[k]);
        }
        return NULL;
    }
    Py_ssize_t n = count_of(&view[1]);
    Py_ssize_t first = count_of(&view[2]) / 9, second = count_of(&view[3]) / 9;
    const double *a = view[2].buf, *b = view[3].buf;
    double *relative = view[0].buf, *sine = view[1].buf;
    int ok = count_of(&view[0]) == 4 * n && count_of(&view[2]) == 9 * first &&
             count_of(&view[3]) == 9 * second && (first == n || first == 1) &&
             (second == n || second == 1) && all_rotations(a, first, validate, atol) &&
             all_rotations(b, second, validate, atol);
    Py_ssize_t a_step = first == n ? 9 : 0, b_step = second == n ? 9 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        double e[9], *q = relative + 4 * m;
        transposed_product(a + a_step * m, b + b_step * m, e);
        entries_to_quaternion(e, q);
        double squared = squared_length(q + 1, 3);
        ok = squared >= 0.0;
        sine[m] = ok ? sqrt(squared) : 0.0;
    }
    for (int k = 0; k < 4; k++) {
        PyBuffer_Release(&view[k]);
    }
    return PyBool_FromLong(ok);
}

/* slerp_half_turns(angle, t) -> bool
 * The half turns t θ / 2 of slerp (slerp_entries' arctangent times t), in place of the angles
 * θ / 2 (n); t holds one fraction or n. False when one is not finite: t was not, or the
 * product overflowed (the array path refuses it). */
static PyObject *
slerp_half_turns(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 2, "slerp_half_turns") < 0) {
        return NULL;
    }
    Py_buffer angle, t;
    if (doubles(args[0], &angle, 1) < 0) {
        return NULL;
    }
    if (doubles(args[1], &t, 0) < 0) {
        PyBuffer_Release(&angle);
        return NULL;
    }
    Py_ssize_t n = count_of(&angle), fractions = count_of(&t);
    double *half = angle.buf;
    const double *by = t.buf;
    int ok = fractions == n || fractions == 1;
    Py_ssize_t step = fractions == n ? 1 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        half[m] = half[m] * by[step * m];
        ok = half[m] - half[m] == 0.0;
    }
    PyBuffer_Release(&t);
    PyBuffer_Release(&angle);
    return PyBool_FromLong(ok);
}

/* slerp_turn(out, R0, relative, sine, tangent) -> bool
 * Second stage of slerp (slerp_entries after its tangent): R0 Rot(n, t θ) (out (n, 3, 3))
 * from the quaternions and lengths of the first stage and tangent = tan(t θ / 2) (n); R0
 * holds one matrix or n. False when the turn's quaternion needs rescaling. */
static PyObject *
slerp_turn(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 5, "slerp_turn") < 0) {
        return NULL;
    }
    Py_buffer view[5];
    int taken = 0;
    for (; taken < 5; taken++) {
        if (doubles(args[taken], &view[taken], taken == 0) < 0) {
            break;
        }
    }
    if (taken < 5) {
        for (int k = 0; k < taken; k++) {
            PyBuffer_Release(&view[k]);
        }
        return NULL;
    }
    Py_ssize_t n = count_of(&view[3]), first = count_of(&view[1]) / 9;
    const double *a = view[1].buf, *relative = view[2].buf, *sine = view[3].buf;
    const double *tangent = view[4].buf;
    double *e = view[0].buf;
    int ok = count_of(&view[0]) == 9 * n && count_of(&view[1]) == 9 * first &&
             (first == n || first == 1) && count_of(&view[2]) == 4 * n &&
             count_of(&view[4]) == n;
    Py_ssize_t a_step = first == n ? 9 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *q = relative + 4 * m;
        double factor = tangent[m] / sine[m], turn[9];
        ok = quaternion_to_entries(1.0, q[1] * factor, q[2] * factor, q[3] * factor, turn);
        if (ok) {
            product(a + a_step * m, turn, e + 9 * m);
        }
    }
    for (int k = 0; k < 5; k++) {
        PyBuffer_Release(&view[k]);
    }
    return PyBool_FromLong(ok);
}

/* integration_turns(half, turns, R, omega, dt, degrees, validate, atol) -> bool
 * First stage of integrate_angular_velocity for n steps (rotvec_to_entries up to its
 * tangent): the rotation vector ω dt, its length and, with degrees, the whole quarter turns of
 * the length into turns (n, 5) as (x, y, z, length, quarter), and the half angle whose tangent
 * the second stage needs into half (n). R, omega and dt hold one item or n each. False when a
 * number is not finite, a matrix is not a rotation within atol (with validate), ω dt
 * overflows, or its length needs rescaling. */
static PyObject *
integration_turns(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 8, "integration_turns") < 0) {
        return NULL;
    }
    int degrees = PyObject_IsTrue(args[5]), validate;
    double atol;
    if (degrees < 0 || rotation_check(args[6], args[7], &validate, &atol) < 0) {
        return NULL;
    }
    Py_buffer view[5];
    int taken = 0;
    for (; taken < 5; taken++) {
        if (doubles(args[taken], &view[taken], taken < 2) < 0) {
            break;
        }
    }
    if (taken < 5) {
        for (int k = 0; k < taken; k++) {
            PyBuffer_Release(&view[k]);
        }
        return NULL;
    }
    Py_ssize_t n = count_of(&view[0]);
    Py_ssize_t matrices = count_of(&view[2]) / 9, rates = count_of(&view[3]) / 3;
    Py_ssize_t steps = count_of(&view[4]);
    double *half = view[0].buf, *turns = view[1].buf;
    const double *R = view[2].buf, *omega = view[3].buf, *dt = view[4].buf;
    int ok = count_of(&view[1]) == 5 * n && count_of(&view[2]) == 9 * matrices &&
             count_of(&view[3]) == 3 * rates && (matrices == n || matrices == 1) &&
             (rates == n || rates == 1) && (steps == n || steps == 1) &&
             all_rotations(R, matrices, validate, atol);
    Py_ssize_t omega_step = rates == n ? 3 : 0, dt_step = steps == n ? 1 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *w = omega + omega_step * m;
        double step = dt[dt_step * m], *v = turns + 5 * m;
        v[0] = w[0] * step;
        v[1] = w[1] * step;
        v[2] = w[2] * step;
        double squared = squared_length(v, 3); /* -1 for a NaN or an infinity too */
        ok = squared >= 0.0;
        double length = ok ? sqrt(squared) : 0.0;
        v[3] = length;
        if (degrees) { /* length = k · 90° + r exactly */
            half[m] = 0.5 * quarter_turns(length, &v[4]);
        } else {
            v[4] = 0.0;
            half[m] = 0.5 * length;
        }
    }
    for (int k = 0; k < 5; k++) {
        PyBuffer_Release(&view[k]);
    }
    return PyBool_FromLong(ok);
}

/* integration_steps(out, R, turns, tangent, degrees, in_space) -> bool
 * Second stage of integrate_angular_velocity (rotvec_to_entries after its tangent, then the
 * product without negative zeros): R exp([ω dt]×), or exp([ω dt]×) R in_space, into out
 * (n, 3, 3), from the first stage's turns and tangent = tan(half) (n); R holds one matrix or
 * n. False when the step's quaternion needs rescaling. */
static PyObject *
integration_steps(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (argument_count(nargs, 6, "integration_steps") < 0) {
        return NULL;
    }
    int degrees = PyObject_IsTrue(args[4]);
    int in_space = degrees < 0 ? -1 : PyObject_IsTrue(args[5]);
    if (in_space < 0) {
        return NULL;
    }
    Py_buffer view[4];
    int taken = 0;
    for (; taken < 4; taken++) {
        if (doubles(args[taken], &view[taken], taken == 0) < 0) {
            break;
        }
    }
    if (taken < 4) {
        for (int k = 0; k < taken; k++) {
            PyBuffer_Release(&view[k]);
        }
        return NULL;
    }
    Py_ssize_t n = count_of(&view[3]), matrices = count_of(&view[1]) / 9;
    const double *R = view[1].buf, *turns = view[2].buf, *tangent = view[3].buf;
    double *e = view[0].buf;
    int ok = count_of(&view[0]) == 9 * n && count_of(&view[1]) == 9 * matrices &&
             (matrices == n || matrices == 1) && count_of(&view[2]) == 5 * n;
    Py_ssize_t R_step = matrices == n ? 9 : 0;
    for (Py_ssize_t m = 0; ok && m < n; m++) {
        const double *v = turns + 5 * m;
        double a, b;
        half_pair(tangent[m], v[4], degrees, &a, &b);
        double factor = b / v[3], step[9];
        ok = quaternion_to_entries(a, v[0] * factor, v[1] * factor, v[2] * factor, step);
        if (ok && in_space) {
            product(step, R + R_step * m, e + 9 * m);
        } else if (ok) {
            product(R + R_step * m, step, e + 9 * m);
        }
    }
    for (int k = 0; k < 4; k++) {
        PyBuffer_Release(&view[k]);
    }
    return PyBool_FromLong(ok);
}

static PyMethodDef methods[] = {
    KERNEL(invert),
    KERNEL(compose),
    KERNEL(rotate_points),
    KERNEL(slerp_relative),
    KERNEL(slerp_half_turns),
    KERNEL(slerp_turn),
    KERNEL(integration_turns),
    KERNEL(integration_steps),
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "eulerlib._compiled_operations",
    "Compiled kernels of operations on rotation matrices (optional).", -1,
    methods, NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC
PyInit__compiled_operations(void)
{
    return PyModule_Create(&module);
}
