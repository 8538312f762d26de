"""The argument rules of the plotting functions, checked before anything is drawn.

A plotting function checks every argument first and only then creates a figure, so a bad
argument leaves no half-drawn figure behind in pyplot. The numbers, flags and rotation
matrices go through :mod:`eulerlib._validation` and the conventions through
:func:`eulerlib.get_convention`, exactly as everywhere else in eulerlib; this module adds the
rules that only drawing needs, written on top of those:

* sizes, scales, limits and line widths are finite numbers **> 0**; an opacity lies in [0, 1];
* a figure size is two such numbers, inches;
* a count (points per ring, frames) is an integer (not a bool, not a float) with a minimum;
* labels and titles are strings, in the number asked for;
* colours and line styles are values matplotlib knows;
* an ``ax`` is a 3D axes, a ``fig`` a matplotlib figure.

Each rule raises ``TypeError`` for a value of the wrong kind and ``ValueError`` for a value of
the right kind that is out of range, with a message that starts with the argument's name.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from eulerlib._validation import (
    RotationCheck,
    as_float_array,
    as_rotations,
    as_vectors,
    check_flag,
    real_number,
)

if TYPE_CHECKING:
    from matplotlib.figure import FigureBase
    from mpl_toolkits.mplot3d.axes3d import Axes3D


def check_positive(value: object, name: str) -> float:
    """``value`` as a float, when it is a finite real number > 0.

    Examples
    --------
    >>> check_positive(1.5, "scale")
    1.5
    >>> check_positive(0, "scale")
    Traceback (most recent call last):
    ...
    ValueError: scale must be a finite number > 0, got 0
    """
    number = real_number(value, name)  # the kind of number: one rule, in _validation
    if not (math.isfinite(number) and number > 0.0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")
    return number


def check_alpha(value: object, name: str = "alpha") -> float:
    """An opacity: a real number from 0 (invisible) to 1 (opaque)."""
    number = real_number(value, name)
    if not 0.0 <= number <= 1.0:
        raise ValueError(f"{name} must be a number from 0 to 1, got {value!r}")
    return number


def check_figsize(value: object, name: str = "figsize") -> tuple[float, float]:
    """A figure size: two finite numbers > 0 (width and height in inches)."""
    if value is None:
        raise TypeError(f"{name} must be two numbers (width, height) in inches, got None")
    size = as_float_array(cast(ArrayLike, value), name)
    if size.shape != (2,):
        raise ValueError(
            f"{name} must be two numbers (width, height) in inches, got shape {size.shape}"
        )
    if not np.all(size > 0.0):
        raise ValueError(f"{name} must be two numbers > 0 (inches), got {tuple(size.tolist())}")
    return float(size[0]), float(size[1])


def check_count(value: object, name: str, minimum: int) -> int:
    """An integer (Python or NumPy, not a bool) of at least ``minimum``."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, got {value!r} ({type(value).__name__})")
    if value < minimum:
        raise ValueError(f"{name} must be an integer of at least {minimum}, got {value!r}")
    return int(value)


def check_text(value: object, name: str) -> str:
    """A string."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, got {value!r} ({type(value).__name__})")
    return value


def check_optional_text(value: object, name: str) -> str | None:
    """A string, or None."""
    return None if value is None else check_text(value, name)


def check_texts(value: object, name: str, count: int, what: str) -> tuple[str, ...]:
    """Exactly ``count`` strings in a list or tuple; ``what`` says what each one is for."""
    if not isinstance(value, (list, tuple)):
        raise TypeError(
            f"{name} must be a list or tuple of {count} strings ({what}), got "
            f"{type(value).__name__}"
        )
    if len(value) != count:
        entries = "1 entry" if count == 1 else f"{count} entries"
        raise ValueError(f"{name} must have {entries} ({what}), got {len(value)}")
    for index, item in enumerate(value):
        if not isinstance(item, str):
            raise TypeError(
                f"{name}[{index}] must be a string, got {item!r} ({type(item).__name__})"
            )
    return tuple(value)


def check_color(value: object, name: str) -> Any:
    """A colour matplotlib knows: a name (``"tab:red"``, ``"0.2"``, ``"#1f77b4"``) or RGB(A)."""
    from matplotlib.colors import is_color_like

    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (str, tuple, list)):
        raise TypeError(
            f"{name} must be a colour (a name such as 'tab:red' or an RGB tuple), got "
            f"{value!r} ({type(value).__name__})"
        )
    if not is_color_like(value):
        raise ValueError(f"{name} is not a colour matplotlib knows: {value!r}")
    return value


def check_colors(value: object, name: str, count: int) -> tuple[Any, ...]:
    """Exactly ``count`` colours in a list or tuple."""
    if not isinstance(value, (list, tuple)):
        raise TypeError(
            f"{name} must be a list or tuple of {count} colours, got {type(value).__name__}"
        )
    if len(value) != count:
        raise ValueError(f"{name} must have {count} entries (x, y, z), got {len(value)}")
    return tuple(check_color(item, f"{name}[{index}]") for index, item in enumerate(value))


def check_linestyle(value: object, name: str = "linestyle") -> Any:
    """A matplotlib line style: ``"-"``, ``"--"``, ``":"``, ``"-."``, a name, or a dash tuple."""
    from matplotlib.lines import Line2D

    if not isinstance(value, (str, tuple)):
        raise TypeError(
            f"{name} must be a line style such as '-', '--', ':' or '-.', got {value!r} "
            f"({type(value).__name__})"
        )
    try:
        Line2D([], []).set_linestyle(cast(Any, value))  # matplotlib's rule; makes no figure
    except (ValueError, TypeError):
        raise ValueError(
            f"{name} must be a line style such as '-', '--', ':' or '-.', got {value!r}"
        ) from None
    return value


def check_axes3d(value: object, name: str = "ax") -> Axes3D:
    """A matplotlib 3D axes."""
    from mpl_toolkits.mplot3d.axes3d import Axes3D

    if not isinstance(value, Axes3D):
        raise TypeError(
            f"{name} must be a 3D axes (from new_3d_axes or add_subplot(projection='3d')), got "
            f"{type(value).__name__}"
        )
    return value


def check_figure(value: object, name: str = "fig") -> FigureBase | None:
    """A matplotlib figure (or subfigure), or None."""
    from matplotlib.figure import FigureBase

    if value is not None and not isinstance(value, FigureBase):
        raise TypeError(f"{name} must be a matplotlib figure or None, got {type(value).__name__}")
    return value


def check_position(value: object, name: str = "position") -> tuple[int, int, int]:
    """A subplot position: ``(rows, columns, index)`` or the three digits ``231``."""
    words = "(rows, columns, index) or a three-digit integer such as 111"
    if isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_)):
        if not 111 <= value <= 999:
            raise ValueError(f"{name} must be {words}, got {value!r}")
        digits = str(int(value))
        triple = (int(digits[0]), int(digits[1]), int(digits[2]))
    elif isinstance(value, (tuple, list)):
        if len(value) != 3 or any(
            isinstance(item, (bool, np.bool_)) or not isinstance(item, (int, np.integer))
            for item in value
        ):
            raise TypeError(f"{name} must be {words}, got {value!r}")
        triple = (int(value[0]), int(value[1]), int(value[2]))
    else:
        raise TypeError(f"{name} must be {words}, got {value!r} ({type(value).__name__})")
    rows, columns, index = triple
    if min(triple) < 1 or index > rows * columns:
        raise ValueError(
            f"{name} {value!r} names no subplot: rows and columns must be ≥ 1 and the index "
            f"from 1 to rows × columns"
        )
    return triple


def angle_triple(angles: ArrayLike) -> NDArray[np.float64]:
    """One set of three angles, as given (shape ``(3,)``)."""
    values = as_vectors(angles, "angles")
    if values.shape != (3,):
        raise ValueError(f"angles must be three numbers, got shape {values.shape}")
    return values


def three_angles(angles: ArrayLike, degrees: object) -> NDArray[np.float64]:
    """One set of three angles, in radians (``degrees`` says how they were given)."""
    in_degrees = check_flag(degrees, "degrees")
    values = angle_triple(angles)
    return np.radians(values) if in_degrees else values


def one_rotation(R: ArrayLike | None, name: str, check: RotationCheck) -> NDArray[np.float64]:
    """``R`` as a single 3×3 rotation matrix (the identity when ``R`` is None)."""
    if R is None:
        return np.eye(3)
    matrix = as_rotations(R, name, check)
    if matrix.shape != (3, 3):
        raise ValueError(f"{name} must be one 3×3 rotation matrix, got shape {matrix.shape}")
    return matrix


def rotation_stack(rotations: ArrayLike, name: str, check: RotationCheck) -> NDArray[np.float64]:
    """``rotations`` as a stack ``(n, 3, 3)`` of rotation matrices (one matrix gives n = 1)."""
    matrices = as_rotations(rotations, name, check)
    if matrices.ndim == 2:
        matrices = matrices[None]
    if matrices.ndim != 3:
        raise ValueError(f"{name} must have shape (3, 3) or (n, 3, 3), got shape {matrices.shape}")
    return matrices
