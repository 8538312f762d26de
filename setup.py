"""The optional compiled kernels of eulerlib (eulerlib/_compiled.py says what they are).

Everything else about the package is in pyproject.toml. The extensions are ``optional``: on a
machine without a C compiler or Python's headers, the install goes on without them and eulerlib
runs its numpy-only path, which gives the same results.
"""

from setuptools import Extension, setup

# No fused multiply-add and no fast-math: the compiled arithmetic must round, operation for
# operation, as numpy's and Python's do.
_FLAGS = ["-O2", "-ffp-contract=off", "-fno-fast-math"]

setup(
    ext_modules=[
        Extension(
            f"eulerlib.{name}",
            [f"eulerlib/{name}.c"],
            depends=["eulerlib/_compiled.h"],
            extra_compile_args=_FLAGS,
            optional=True,
        )
        for name in ("_compiled_euler", "_compiled_rotations", "_compiled_operations")
    ]
)
