/* What the optional compiled kernels share: reading arguments, and the formulas that more than
 * one kernel needs, each a C transcription of its Python-float twin in eulerlib/_scalar.py and
 * eulerlib/_scalar_kernels.py, operation for operation in the same order.
 *
 * The rules that keep the compiled results identical to the numpy-only ones:
 * - only IEEE double arithmetic in the same order as the Python twin; the extensions are built
 *   with -ffp-contract=off, so no multiply-add is fused;
 * - no transcendental function: sines, cosines, tangents and arctangents are numpy's, called
 *   by the Python wrapper between two compiled stages (numpy's vectorized loops may round
 *   them differently from the C library);
 * - a kernel declines, by returning False, whenever the Python twin would return None or the
 *   array path would raise or warn: the public function then takes the array path, which
 *   words the refusal or the warning.
 */
#ifndef EULERLIB_COMPILED_H
#define EULERLIB_COMPILED_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <string.h>

/* A C-contiguous buffer of doubles; `writable` for an output. 0 on success, -1 with an error
 * set. The caller releases it with PyBuffer_Release. */
static int
doubles(PyObject *object, Py_buffer *view, int writable)
{
    int flags = PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0);
    if (PyObject_GetBuffer(object, view, flags) < 0) {
        return -1;
    }
    if (view->itemsize != 8 || view->format == NULL || strcmp(view->format, "d") != 0) {
        PyBuffer_Release(view);
        PyErr_SetString(PyExc_TypeError, "a compiled kernel takes float64 arrays only");
        return -1;
    }
    return 0;
}

/* The buffers of a kernel's arguments args[0..count-1], the first `outputs` writable; 0 on
 * success, -1 with an error set and every buffer taken so far released. */
static inline int
take_buffers(PyObject *const *args, Py_ssize_t count, Py_ssize_t outputs, Py_buffer *views)
{
    for (Py_ssize_t i = 0; i < count; i++) {
        if (doubles(args[i], &views[i], i < outputs) < 0) {
            while (i > 0) {
                PyBuffer_Release(&views[--i]);
            }
            return -1;
        }
    }
    return 0;
}

/* Releases the buffers take_buffers took. */
static inline void
release_buffers(Py_buffer *views, Py_ssize_t count)
{
    for (Py_ssize_t i = 0; i < count; i++) {
        PyBuffer_Release(&views[i]);
    }
}

/* 0 when a kernel got `expected` arguments, else -1 with a TypeError naming it. */
static inline int
argument_count(Py_ssize_t nargs, Py_ssize_t expected, const char *name)
{
    if (nargs != expected) {
        PyErr_Format(PyExc_TypeError, "%s takes %zd arguments", name, expected);
        return -1;
    }
    return 0;
}

/* Reads `validate` (a bool) and `atol` (a float) from two arguments; -1 with an error set. */
static inline int
rotation_check(PyObject *validate_object, PyObject *atol_object, int *validate, double *atol)
{
    *validate = PyObject_IsTrue(validate_object);
    if (*validate < 0) {
        return -1;
    }
    *atol = PyFloat_AsDouble(atol_object);
    if (*atol == -1.0 && PyErr_Occurred()) {
        return -1;
    }
    return 0;
}

static inline Py_ssize_t
count_of(const Py_buffer *view)
{
    return view->len / 8;
}

/* Whether every number is finite: x − x is 0 for a finite x and NaN otherwise
 * (_scalar.finite). */
static inline int
all_finite(const double *x, Py_ssize_t n)
{
    for (Py_ssize_t i = 0; i < n; i++) {
        if (!(x[i] - x[i] == 0.0)) {
            return 0;
        }
    }
    return 1;
}

/* Python's max(a, b): the first argument unless the second is larger. */
static inline double
max2(double a, double b)
{
    return b > a ? b : a;
}

/* The rotation test of one matrix (_scalar.is_rotation): det ≥ 0, max |R Rᵀ − I| ≤ atol,
 * |det − 1| ≤ atol. */
static inline int
is_rotation(const double *e, double atol)
{
    double a = e[0], b = e[1], c = e[2], d = e[3], f = e[4], g = e[5], h = e[6], i = e[7],
           j = e[8];
    double det = a * (f * j - g * i) - b * (d * j - g * h) + c * (d * i - f * h);
    if (det < 0) {
        return 0;
    }
    double worst = fabs((a * a + b * b + c * c) - 1.0);
    worst = max2(max2(worst, fabs((d * d + f * f + g * g) - 1.0)),
                 fabs((h * h + i * i + j * j) - 1.0));
    worst = max2(max2(worst, fabs(a * d + b * f + c * g)), fabs(a * h + b * i + c * j));
    worst = max2(worst, fabs(d * h + f * i + g * j));
    return worst <= atol && fabs(det - 1.0) <= atol;
}

/* Every matrix of a buffer of n matrices finite and, when `validate`, a rotation. */
static inline int
all_rotations(const double *e, Py_ssize_t n, int validate, double atol)
{
    if (!all_finite(e, 9 * n)) {
        return 0;
    }
    if (validate) {
        for (Py_ssize_t m = 0; m < n; m++) {
            if (!is_rotation(e + 9 * m, atol)) {
                return 0;
            }
        }
    }
    return 1;
}

/* squared lengths between these bounds need no rescaling (_scalar_kernels._SMALL, _LARGE) */
#define EULERLIB_SMALL 0x1p-1000
#define EULERLIB_LARGE 0x1p+1000

/* x² + y² + … in order; -1 when it leaves the range that needs no rescaling
 * (_scalar_kernels.squared_length). */
static inline double
squared_length(const double *v, int n)
{
    double total = v[0] * v[0];
    for (int i = 1; i < n; i++) {
        total += v[i] * v[i];
    }
    return (EULERLIB_SMALL <= total && total <= EULERLIB_LARGE) ? total : -1.0;
}

/* The matrix entries of a quaternion (w, x, y, z) of any length; 0 when its squared length
 * needs rescaling (_scalar_kernels.quaternion_to_entries). */
static inline int
quaternion_to_entries(double w, double x, double y, double z, double *e)
{
    double ww = w * w, xx = x * x, yy = y * y, zz = z * z;
    double a = ww - zz, b = xx - yy;
    ww += zz;
    xx += yy;
    double squared = ww + xx;
    if (!(EULERLIB_SMALL <= squared && squared <= EULERLIB_LARGE)) {
        return 0;
    }
    double r = 1.0 / squared;
    double e0 = (a + b) * r, e4 = (a - b) * r, e8 = (ww - xx) * r;
    r += r;
    double xs = x * r, ys = y * r, zs = z * r;
    double wx = w * xs, wy = w * ys, wz = w * zs;
    double t01 = xs * y + 0.0, t02 = xs * z + 0.0, t12 = ys * z + 0.0;
    e[0] = e0;
    e[1] = t01 - wz;
    e[2] = t02 + wy;
    e[3] = t01 + wz;
    e[4] = e4;
    e[5] = t12 - wx;
    e[6] = t02 - wy;
    e[7] = t12 + wx;
    e[8] = e8;
    return 1;
}

/* The one of q and −q with w > 0, or at w = 0 with the first nonzero of (x, y, z) positive;
 * no −0.0 (_scalar_kernels.make_canonical). q is (w, x, y, z), changed in place. */
static inline void
make_canonical(double *q)
{
    double sign = copysign(1.0, q[0]);
    for (int n = 0; n < 4; n++) {
        q[n] = q[n] * sign;
    }
    if (q[0] == 0.0) {
        double first = q[1] != 0.0 ? q[1] : (q[2] != 0.0 ? q[2] : q[3]);
        sign = copysign(1.0, first);
        for (int n = 0; n < 4; n++) {
            q[n] = q[n] * sign;
        }
    }
    for (int n = 0; n < 4; n++) {
        q[n] = q[n] + 0.0;
    }
}

/* The canonical quaternion (w, x, y, z) of a rotation matrix by Shepperd's method, not
 * normalized (_scalar_kernels.entries_to_quaternion). */
static inline void
entries_to_quaternion(const double *e, double *q)
{
    /* (p, r, sign) for each pair of components, as _quaternion_kernels._OFF_DIAGONAL */
    static const int part[4][4][2] = {
        {{0, 0}, {7, 5}, {2, 6}, {3, 1}},
        {{7, 5}, {0, 0}, {1, 3}, {2, 6}},
        {{2, 6}, {1, 3}, {0, 0}, {5, 7}},
        {{3, 1}, {2, 6}, {5, 7}, {0, 0}},
    };
    static const double part_sign[4][4] = {
        {0.0, -1.0, -1.0, -1.0},
        {-1.0, 0.0, 1.0, 1.0},
        {-1.0, 1.0, 0.0, 1.0},
        {-1.0, 1.0, 1.0, 0.0},
    };
    double r00 = e[0], r11 = e[4], r22 = e[8];
    double d[4] = {
        (1.0 + r00) + (r11 + r22),
        (1.0 + r00) - (r11 + r22),
        (1.0 + r11) - (r00 + r22),
        (1.0 + r22) - (r00 + r11),
    };
    int second = d[1] > d[0], fourth = d[3] > d[2];
    int upper = max2(d[2], d[3]) > max2(d[0], d[1]);
    int k = second + upper * (2 + fourth - second);
    double row[4];
    row[k] = d[k];
    for (int other = 0; other < 4; other++) {
        if (other != k) {
            int p = part[k][other][0], r = part[k][other][1];
            row[other] = e[r] * part_sign[k][other] + e[p];
        }
    }
    double factor = sqrt(row[k]) / (2.0 * row[k]);
    for (int n = 0; n < 4; n++) {
        q[n] = row[n] * factor;
    }
    make_canonical(q);
}

/* Entries of Aᵀ B (_scalar_kernels.transposed_product). */
static inline void
transposed_product(const double *a, const double *b, double *e)
{
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            double total = a[i] * b[j];
            total += a[3 + i] * b[3 + j];
            total += a[6 + i] * b[6 + j];
            e[3 * i + j] = total;
        }
    }
}

/* Entries of A B without negative zeros (_scalar_kernels.product). */
static inline void
product(const double *a, const double *b, double *e)
{
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            double total = a[3 * i] * b[j];
            total += a[3 * i + 1] * b[3 + j];
            e[3 * i + j] = (total + a[3 * i + 2] * b[6 + j]) + 0.0;
        }
    }
}

/* An angle in degrees as k · 90° + r exactly: r in radians is returned, the whole number k
 * goes to *quarter (_scalar_kernels.quarter_turns, whose k is float(round(...)): no −0.0). */
static inline double
quarter_turns(double angle, double *quarter)
{
    double reduced = fmod(angle, 360.0);
    *quarter = nearbyint(reduced / 90.0) + 0.0;
    return (reduced - 90.0 * *quarter) * (Py_MATH_PI / 180.0);
}

/* k mod 4, from 0 to 3, of a whole number k of quarter turns. */
static inline int
quarter_index(double quarter)
{
    int k = (int)fmod(quarter, 4.0);
    return k < 0 ? k + 4 : k;
}

/* Positive multiples (a, b) of (cos(θ/2), sin(θ/2)) from t, numpy's tangent of half of θ in
 * radians, or in degrees of half the rest r of θ = k · 90° + r (quarter_turns)
 * (_scalar_kernels.half_angle_pair). */
static inline void
half_pair(double t, double quarter, int degrees, double *a, double *b)
{
    /* (cos, sin) of k · 45°, times √2 for odd k, by k mod 4 (_scalar_kernels._HALF_QUARTER) */
    static const double half_quarter[4][2] = {{1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {-1.0, 1.0}};
    if (!degrees) {
        *a = 1.0;
        *b = t;
        return;
    }
    int k = quarter_index(quarter);
    double c = half_quarter[k][0], s = half_quarter[k][1];
    *a = c - s * t + 0.0;
    *b = s + c * t + 0.0;
}

/* The entry of a kernel `name` in its module's method table (called with METH_FASTCALL). */
#define KERNEL(name) {#name, (PyCFunction)(void (*)(void))name, METH_FASTCALL, NULL}

#endif
