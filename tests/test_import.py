"""A light core: ``import eulerlib`` loads numpy only, and each optional part names its extra.

Every probe runs in a fresh interpreter. A package is hidden from it by ``sys.modules[name] =
None``, which makes ``import name`` fail exactly as it does where the package is not installed.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

HEAVY = ("sympy", "matplotlib", "scipy", "nbformat", "nbclient", "nbconvert", "IPython")

#: Prints the third-party top-level packages that ``statement`` loads.
PROBE = """\
import json, sys
before = set(sys.modules)
{statement}
loaded = {{name.split(".")[0] for name in set(sys.modules) - before}}
print(json.dumps(sorted(loaded - set(sys.stdlib_module_names))))
"""


def run_python(code: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=False, timeout=120
    )


def packages_loaded_by(statement: str) -> list[str]:
    """Third-party top-level packages (and eulerlib) that ``statement`` loads."""
    result = run_python(PROBE.format(statement=statement))
    assert result.returncode == 0, result.stderr
    loaded: list[str] = json.loads(result.stdout)
    return loaded


def import_error_without(hidden: str, statement: str) -> str:
    """The message of the ImportError that ``statement`` raises when ``hidden`` is missing."""
    code = (
        f"import sys\nsys.modules[{hidden!r}] = None\n"
        f"try:\n    {statement}\nexcept ImportError as error:\n    print(error)\n"
        "else:\n    print('no ImportError')\n"
    )
    result = run_python(code)
    assert result.returncode == 0, result.stderr
    return result.stdout.strip()


def test_import_loads_numpy_only() -> None:
    assert packages_loaded_by("import eulerlib") == ["eulerlib", "numpy"]


def test_using_the_core_stays_light() -> None:
    statement = (
        "import warnings, eulerlib\n"
        "warnings.simplefilter('ignore')\n"
        "R = eulerlib.euler_to_matrix([[0.1, 0.2, 0.3], [0.0, 1.5707963267948966, 0.0]])\n"
        "eulerlib.matrix_to_euler(R, 'zxz', repair=True)\n"
        "eulerlib.matrix_to_yaw_pitch_roll(R); eulerlib.matrix_to_heading_attitude_bank(R)\n"
        "eulerlib.gimbal_lock_status(R); eulerlib.rotate_points(R, [1.0, 0.0, 0.0])\n"
        "eulerlib.compose(R, eulerlib.invert(R)); eulerlib.is_rotation_matrix(R)\n"
        "eulerlib.convert_angles([0.1, 0.2, 0.3], 'rose', 'baker')"
    )
    assert packages_loaded_by(statement) == ["eulerlib", "numpy"]


def test_the_command_line_stays_light() -> None:
    # `eulerlib --help` and `eulerlib convert` must work on a core install.
    assert packages_loaded_by("import eulerlib.cli, eulerlib.convert_cli") == ["eulerlib", "numpy"]


def test_the_probe_sees_a_third_party_import() -> None:
    """The probe itself works: a package outside the standard library does show up."""
    assert packages_loaded_by("import mpmath") == ["mpmath"]


def test_nothing_printed_on_import() -> None:
    result = run_python("import eulerlib")
    assert (result.returncode, result.stdout, result.stderr) == (0, "", "")


@pytest.mark.parametrize(
    ("hidden", "statement", "extra"),
    [
        ("sympy", "import eulerlib.symbolic", "symbolic"),
        ("matplotlib", "import eulerlib.plotting", "plot"),
        ("matplotlib", "from eulerlib.plotting import plot_frames", "plot"),
    ],
)
def test_an_optional_part_names_its_extra(hidden: str, statement: str, extra: str) -> None:
    message = import_error_without(hidden, statement)
    assert message.startswith("eulerlib.")
    assert message.endswith(f'pip install "eulerlib[{extra}]"')
    assert f"needs {hidden}" in message


def test_the_core_works_without_the_extras() -> None:
    hidden = "".join(f"sys.modules[{name!r}] = None\n" for name in HEAVY)
    code = (
        f"import sys\n{hidden}"
        "from eulerlib.cli import main\n"
        "raise SystemExit(main(['convert', '--from', 'rose', '--to', 'baker', '--degrees', "
        "'30', '20', '10']))\n"
    )
    result = run_python(code)
    assert (result.returncode, result.stderr) == (0, ""), result.stderr
    assert "heading" in result.stdout


def test_the_course_commands_are_not_the_librarys() -> None:
    # They belong to the course package and its own command line, eulerlib-course.
    result = run_python("from eulerlib.cli import main\nmain(['notebooks', 'student'])")
    assert result.returncode == 2  # argparse: an unknown command
    assert "notebooks" in result.stderr.splitlines()[-1]
