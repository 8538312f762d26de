"""``import eulerlib`` is light: numpy only, no SymPy, matplotlib or SciPy."""

import json
import subprocess
import sys

HEAVY = ("sympy", "matplotlib", "scipy")


def modules_after(statement: str) -> list[str]:
    """Top-level packages loaded by ``statement`` in a fresh interpreter."""
    code = f"import json, sys\n{statement}\nprint(json.dumps(sorted(sys.modules)))"
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, timeout=120
    )
    return sorted({name.split(".")[0] for name in json.loads(result.stdout)})


def test_import_loads_numpy_only():
    loaded = modules_after("import eulerlib")
    assert "numpy" in loaded and "eulerlib" in loaded
    for heavy in HEAVY:
        assert heavy not in loaded, f"import eulerlib loaded {heavy}"


def test_using_the_core_stays_light():
    statement = (
        "import warnings, eulerlib\n"
        "warnings.simplefilter('ignore')\n"
        "R = eulerlib.euler_to_matrix([[0.1, 0.2, 0.3], [0.0, 1.5707963267948966, 0.0]])\n"
        "eulerlib.matrix_to_euler(R, 'zxz', repair=True)\n"
        "eulerlib.matrix_to_yaw_pitch_roll(R); eulerlib.matrix_to_heading_attitude_bank(R)\n"
        "eulerlib.gimbal_lock_status(R); eulerlib.rotate_points(R, [1.0, 0.0, 0.0])\n"
        "eulerlib.compose(R, eulerlib.invert(R)); eulerlib.is_rotation_matrix(R)"
    )
    loaded = modules_after(statement)
    for heavy in HEAVY:
        assert heavy not in loaded, f"the core functions loaded {heavy}"


def test_the_check_can_see_a_heavy_import():
    """The probe itself works: importing SymPy does show up."""
    assert "sympy" in modules_after("import sympy")


def test_nothing_printed_on_import():
    result = subprocess.run(
        [sys.executable, "-c", "import eulerlib"], capture_output=True, text=True, timeout=120
    )
    assert (result.returncode, result.stdout, result.stderr) == (0, "", "")
