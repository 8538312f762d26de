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
    if (nargs != 3) {
        PyErr_SetString(PyExc_TypeError, "quaternions_to_matrices takes 3 arguments");
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

static PyMethodDef methods[] = {
    {"quaternions_to_matrices", (PyCFunction)(void (*)(void))quaternions_to_matrices,
     METH_FASTCALL, NULL},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "eulerlib._compiled_rotations",
    "Compiled kernels of quaternions, rotation vectors and matrix operations (optional).", -1,
    methods,
};

PyMODINIT_FUNC
PyInit__compiled_rotations(void)
{
    return PyModule_Create(&module);
}
