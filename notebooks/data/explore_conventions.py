"""Work out the conventions of an x-io x-IMU from its own outputs (recording 00033).

The device wrote the same attitude three ways (a quaternion, a rotation matrix, three Euler
angles) next to its calibrated gyroscope, accelerometer and magnetometer. None of the files says
which convention it follows, so this script lets the numbers decide:

1. the streams: how the packets interleave, the sample rates (registers and the clock);
2. the quaternion: scalar first or last, and is the stored matrix ``R(q)`` or ``R(q)ᵀ``;
3. the direction: does the stored matrix take sensor coordinates to earth coordinates (the
   accelerometer, which measures the upward reaction to gravity, decides);
4. the Euler angles: all 24 sequences, every order of the three columns, both directions,
   with :func:`eulerlib.matrix_to_euler`, :func:`eulerlib.euler_to_matrix` and SciPy;
5. gimbal lock: where the recording comes closest (:func:`eulerlib.gimbal_lock_status`) and
   what the device's yaw and roll do there;
6. the gyroscope: units, frame, timing, and how far integrating it drifts from the device's
   own fused attitude after 1, 2 and 5 s.

Run it with the repository's environment (SciPy is in the ``test`` extra)::

    python notebooks/data/explore_conventions.py            # the excerpt in this folder
    python notebooks/data/explore_conventions.py --data DIR  # e.g. the full recording

Times are in seconds from the first inertial sample of the files read (the excerpt starts
3.0 s into the recording; see README.md). The tests never run it; README.md quotes its output.
"""

from __future__ import annotations

import argparse
import csv
import itertools
import warnings
from pathlib import Path
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray
from scipy.spatial.transform import Rotation

import eulerlib

Array = NDArray[np.float64]

#: Seconds after which the integrated attitude is compared with the device's.
HORIZONS_S = (1.0, 2.0, 5.0)
#: A sample counts as near gimbal lock when its pitch is this close to ±90°.
NEAR_LOCK_DEG = 5.0


class Recording(NamedTuple):
    """The device's outputs, as stored (no unit or convention applied yet)."""

    inertial_packet: Array  # (n,) packet numbers of the inertial samples
    gyroscope: Array  # (n, 3) deg/s according to the header
    accelerometer: Array  # (n, 3) g
    magnetometer: Array  # (n, 3) gauss
    attitude_packet: Array  # (m,) packet numbers of quaternion, Euler and matrix rows
    quaternion: Array  # (m, 4) columns "Element 1" to "Element 4"
    euler: Array  # (m, 3) columns Roll|X, Pitch|Y, Yaw|Z
    matrix: Array  # (m, 3, 3) "Element 11" ... "Element 33", row by row
    clock: Array  # (k, 7) packet, year, month, day, hours, minutes, seconds
    registers: dict[str, float]


def read_table(path: Path) -> Array:
    """A CSV file of numbers with one header line."""
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def load(folder: Path) -> Recording:
    """Read the recording 00033 from ``folder``."""
    inertial = read_table(folder / "00033_CalInertialAndMag.csv")
    quaternion = read_table(folder / "00033_Quaternion.csv")
    euler = read_table(folder / "00033_EulerAngles.csv")
    matrix = read_table(folder / "00033_RotationMatrix.csv")
    for other in (euler, matrix):
        if not np.array_equal(other[:, 0], quaternion[:, 0]):
            raise ValueError("the attitude files do not share their packet numbers")
    with (folder / "00033_Registers.csv").open(newline="") as handle:
        registers = {row["Name"]: float(row["Value"]) for row in csv.DictReader(handle)}
    return Recording(
        inertial_packet=inertial[:, 0],
        gyroscope=inertial[:, 1:4],
        accelerometer=inertial[:, 4:7],
        magnetometer=inertial[:, 7:10],
        attitude_packet=quaternion[:, 0],
        quaternion=quaternion[:, 1:],
        euler=euler[:, 1:],
        matrix=matrix[:, 1:].reshape(-1, 3, 3),
        clock=read_table(folder / "00033_DateTime.csv"),
        registers=registers,
    )


def wrap_degrees(angle: Array) -> Array:
    """Angles in degrees, brought into [-180, 180)."""
    return (angle + 180.0) % 360.0 - 180.0


def angle_between(a: Rotation, b: Rotation) -> Array:
    """The angle of the rotation that takes ``a`` to ``b``, in degrees."""
    return np.degrees((a.inv() * b).magnitude())


def at_attitude_samples(rec: Recording, values: Array) -> Array:
    """An inertial quantity at the attitude samples: the mean of the two inertial samples
    around each attitude packet (attitude row j lies between inertial rows 2j and 2j + 1)."""
    m = len(rec.attitude_packet)
    return 0.5 * (values[0 : 2 * m : 2] + values[1 : 2 * m : 2])


# ----------------------------------------------------------------------------------------------
def streams(rec: Recording) -> tuple[float, float]:
    """Rows, interleaving and sample rates; returns the inertial and attitude rates in Hz."""
    print("== 1. Streams and sample rates")
    n, m = len(rec.inertial_packet), len(rec.attitude_packet)
    print(f"inertial rows {n}, attitude rows {m} (quaternion = Euler = matrix packet numbers)")
    between = (rec.inertial_packet[0 : 2 * m : 2] < rec.attitude_packet) & (
        rec.attitude_packet < rec.inertial_packet[1 : 2 * m : 2]
    )
    print(f"attitude row j lies between inertial rows 2j and 2j+1: {bool(between.all())}")

    # x-IMU API, enum DataOutputRates: 0 disabled, 1 -> 1 Hz, 2 -> 2 Hz, ..., 9 -> 256 Hz.
    def enum_rate(name: str) -> float:
        return 2.0 ** (rec.registers[name] - 1)

    inertial_rate = enum_rate("InertialAndMagneticDataRate")
    attitude_rate = enum_rate("QuaternionDataRate")
    print(
        f"registers: InertialAndMagneticDataRate {rec.registers['InertialAndMagneticDataRate']:.0f}"
        f" -> {inertial_rate:g} Hz, QuaternionDataRate {rec.registers['QuaternionDataRate']:.0f}"
        f" -> {attitude_rate:g} Hz, DateTimeDataRate {rec.registers['DateTimeDataRate']:.0f}"
        f" -> {enum_rate('DateTimeDataRate'):g} Hz"
    )
    seconds = rec.clock[:, 4] * 3600 + rec.clock[:, 5] * 60 + rec.clock[:, 6]
    ticks = np.flatnonzero(np.diff(seconds) > 0) + 1
    if len(ticks) >= 2:
        first, last = rec.clock[ticks[0], 0], rec.clock[ticks[-1], 0]
        counted = np.count_nonzero((rec.inertial_packet >= first) & (rec.inertial_packet < last))
        elapsed = seconds[ticks[-1]] - seconds[ticks[0]]
        clock_rows = np.count_nonzero((rec.clock[:, 0] >= first) & (rec.clock[:, 0] < last))
        print(
            f"clock: {counted} inertial samples between two changes of its seconds, "
            f"{elapsed:.0f} s apart: {counted / elapsed:g} Hz; "
            f"{clock_rows / elapsed:g} DateTime rows per second"
        )
    print(
        f"time: inertial row k at k/{inertial_rate:g} s, attitude row j at j/{attitude_rate:g} s; "
        f"{n / inertial_rate:g} s of data"
    )
    return inertial_rate, attitude_rate


# ----------------------------------------------------------------------------------------------
def quaternion_layout(rec: Recording) -> None:
    """Scalar first or last, and R(q) or R(q)ᵀ, against the stored matrix."""
    print("\n== 2. Quaternion layout (max |stored matrix - candidate| over all samples)")
    norm = np.linalg.norm(rec.quaternion, axis=1)
    print(f"|q| from {norm.min():.7f} to {norm.max():.7f}")
    layouts = {"scalar first": [1, 2, 3, 0], "scalar last": [0, 1, 2, 3]}
    for layout, order in layouts.items():
        R = Rotation.from_quat(rec.quaternion[:, order]).as_matrix()  # SciPy: scalar last
        for name, candidate in (("R(q)", R), ("R(q)^T", R.transpose(0, 2, 1))):
            residual = np.abs(rec.matrix - candidate).max()
            print(f"{layout:13} {name:7} {residual:.2e}")
    stored = rec.matrix
    print(
        "stored matrices: max |M Mᵀ - I| = "
        f"{np.abs(stored @ stored.transpose(0, 2, 1) - np.eye(3)).max():.1e}, "
        f"det from {np.linalg.det(stored).min():.7f} to {np.linalg.det(stored).max():.7f}"
    )


# ----------------------------------------------------------------------------------------------
def frame_direction(rec: Recording) -> None:
    """Does the stored matrix take sensor coordinates to earth coordinates?"""
    print("\n== 3. Direction: the accelerometer (g) turned by M and by Mᵀ, mean over all samples")
    accel = at_attitude_samples(rec, rec.accelerometer)
    for name, matrices in (("M a", rec.matrix), ("Mᵀ a", rec.matrix.transpose(0, 2, 1))):
        turned = np.einsum("nij,nj->ni", matrices, accel)
        print(f"{name:5} mean {np.round(turned.mean(axis=0), 3)}, std {np.round(turned.std(0), 3)}")
    magnet = at_attitude_samples(rec, rec.magnetometer)
    field = np.einsum("nij,nj->ni", rec.matrix, magnet)
    mean_bearing = np.degrees(np.arctan2(field[:, 1].mean(), field[:, 0].mean()))
    spread = wrap_degrees(np.degrees(np.arctan2(field[:, 1], field[:, 0])) - mean_bearing)
    size = np.linalg.norm(magnet, axis=1)
    print(
        f"magnetometer turned by M: horizontal part of the mean field at {mean_bearing:.1f}° "
        f"from earth x, 5-95 % of the samples within {np.percentile(spread, 5):+.1f}° to "
        f"{np.percentile(spread, 95):+.1f}° of that; vertical part {field[:, 2].mean():.3f} G; "
        f"|m| from {size.min():.2f} to {size.max():.2f} G"
    )


# ----------------------------------------------------------------------------------------------
class Hypothesis(NamedTuple):
    seq: str
    columns: tuple[int, int, int]  # which stored column goes with letter 1, 2, 3 of seq
    direction: str  # "M" or "Mᵀ"
    rebuild: Array  # per sample: max |euler_to_matrix(columns, seq) - target|
    eulerlib_angles: Array  # per sample: max |wrapped difference|, degrees
    scipy_angles: Array


COLUMN_NAMES = ("roll", "pitch", "yaw")


def euler_hypotheses(rec: Recording) -> list[Hypothesis]:
    """Every sequence, column order and direction, scored against the stored angles."""
    targets = {"M": rec.matrix, "Mᵀ": rec.matrix.transpose(0, 2, 1)}
    found = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # lock warnings of wrong hypotheses are not the point
        for seq, (direction, target) in itertools.product(eulerlib.ALL_SEQUENCES, targets.items()):
            ours = eulerlib.matrix_to_euler(target, seq, degrees=True)
            theirs = Rotation.from_matrix(target).as_euler(seq, degrees=True)
            for columns in itertools.permutations(range(3)):
                stored = rec.euler[:, columns]
                rebuilt = eulerlib.euler_to_matrix(stored, seq, degrees=True)
                found.append(
                    Hypothesis(
                        seq,
                        columns,
                        direction,
                        np.abs(rebuilt - target).max(axis=(1, 2)),
                        np.abs(wrap_degrees(ours - stored)).max(axis=1),
                        np.abs(wrap_degrees(theirs - stored)).max(axis=1),
                    )
                )
    return sorted(found, key=lambda h: (h.rebuild.max(), h.seq.islower()))


def euler_sequence(rec: Recording) -> None:
    """Rank the hypotheses; equivalent spellings (ZYX ≡ xyz reversed) are listed together."""
    print("\n== 4. Euler angles: 24 sequences x 6 column orders x 2 directions")
    ranked = euler_hypotheses(rec)
    groups: list[list[Hypothesis]] = []
    for h in ranked:
        for group in groups:
            if np.array_equal(group[0].rebuild, h.rebuild):
                group.append(h)
                break
        else:
            groups.append([h])
    print(f"{len(ranked)} hypotheses, {len(groups)} distinct; the best three:")
    for rank, group in enumerate(groups[:3], start=1):
        spellings = " = ".join(
            f"{h.seq}({', '.join(COLUMN_NAMES[c] for c in h.columns)}) of {h.direction}"
            for h in group
        )
        h = group[0]
        print(f"{rank}. {spellings}")
        print(
            f"   rebuilt matrix vs target: max {h.rebuild.max():.1e}, median "
            f"{np.median(h.rebuild):.1e}; angles (deg) eulerlib max {h.eulerlib_angles.max():.1e}"
            f" median {np.median(h.eulerlib_angles):.1e}, SciPy max {h.scipy_angles.max():.1e}"
        )
    winner = groups[0][0]
    as_radians = eulerlib.euler_to_matrix(rec.euler[:, winner.columns], winner.seq)
    print(
        "the winner with the stored numbers read as radians: max |rebuilt - M| = "
        f"{np.abs(as_radians - rec.matrix).max():.2f}; stored ranges "
        + ", ".join(
            f"{name} [{lo:.2f}, {hi:.2f}]"
            for name, lo, hi in zip(COLUMN_NAMES, rec.euler.min(0), rec.euler.max(0), strict=True)
        )
    )
    worst = np.argmax(winner.eulerlib_angles)
    status = eulerlib.gimbal_lock_status(rec.matrix[worst], winner.seq, degrees=True)
    print(
        f"largest angle residual of the winner at attitude row {worst}, "
        f"{float(status.distance):.2f}° from gimbal lock"
    )


# ----------------------------------------------------------------------------------------------
def gimbal_lock(rec: Recording, attitude_rate: float) -> None:
    """Where the recording comes closest to gimbal lock, and what yaw and roll do there."""
    print("\n== 5. Gimbal lock of z-y-x (yaw, pitch, roll) of M")
    roll, pitch, yaw = rec.euler.T
    distance = eulerlib.gimbal_lock_status(rec.matrix, "ZYX", degrees=True).distance
    t = np.arange(len(distance)) / attitude_rate
    closest = int(np.argmin(distance))
    print(
        f"closest at t = {t[closest]:.4f} s (attitude row {closest}, packet "
        f"{rec.attitude_packet[closest]:.0f}): {distance[closest]:.4f}° from the pole, "
        f"stored pitch {pitch[closest]:.5f}°, roll {roll[closest]:.4f}°, yaw {yaw[closest]:.4f}°"
    )
    _, words = eulerlib.lock_combination("rose", 90 if pitch[closest] > 0 else -90)
    print(f"at this pole (Rose's yaw-pitch-roll, the same sequence) M depends on {words} only;")
    print(
        "yaw and roll respond to the matrix entries 1/cos(pitch) = "
        f"{1 / np.cos(np.radians(pitch[closest])):.0f} times as strongly as at pitch 0 there"
    )
    near = np.flatnonzero(distance < NEAR_LOCK_DEG)
    if not len(near):
        near = np.array([closest])
    for run in np.split(near, np.flatnonzero(np.diff(near) > 1) + 1):
        if len(run):
            print(
                f"within {NEAR_LOCK_DEG:g}°: t = {t[run[0]]:.4f} to {t[run[-1]]:.4f} s, "
                f"{len(run)} samples, closest {distance[run].min():.3f}°"
            )
    attitude = Rotation.from_matrix(rec.matrix)
    turned = np.concatenate([[np.nan], angle_between(attitude[:-1], attitude[1:])])
    combination = roll - yaw if pitch[closest] > 0 else roll + yaw
    step = {
        "yaw": np.abs(wrap_degrees(np.diff(yaw, prepend=np.nan))),
        "roll": np.abs(wrap_degrees(np.diff(roll, prepend=np.nan))),
        "combination": np.abs(wrap_degrees(np.diff(combination, prepend=np.nan))),
    }
    lo, hi = max(near[0] - 1, 0), near[-1] + 2
    window = slice(lo, hi)
    largest = {name: np.nanmax(change[window]) for name, change in step.items()}
    print(
        f"from t = {t[lo]:.3f} to {t[hi - 1]:.3f} s, largest change between consecutive samples "
        f"(1/{attitude_rate:g} s): yaw {largest['yaw']:.1f}°, roll {largest['roll']:.1f}°, "
        f"{words} {largest['combination']:.1f}°, while the device turned at most "
        f"{np.nanmax(turned[window]):.2f}°"
    )
    big = window.start + np.flatnonzero(step["yaw"][window] > 10)
    same_sign = np.sign(wrap_degrees(yaw[big] - yaw[big - 1])) == np.sign(
        wrap_degrees(roll[big] - roll[big - 1])
    )
    print(
        f"samples there where yaw jumps by more than 10°: {len(big)}; roll jumps the same way "
        f"in {np.count_nonzero(same_sign)} of them"
    )
    ours = eulerlib.matrix_to_euler(rec.matrix[near], "ZYX", degrees=True)[:, ::-1]
    locked = eulerlib.gimbal_lock_status(rec.matrix[near], "ZYX").locked
    print(
        f"eulerlib's angles of M vs the stored ones in the {len(near)} samples within "
        f"{NEAR_LOCK_DEG:g}°: max {np.abs(wrap_degrees(ours - rec.euler[near])).max():.1e}°; "
        f"locked by GIMBAL_LOCK_TOLERANCE: {np.count_nonzero(locked)}"
    )
    print("    t [s]   dist°     roll°    pitch°      yaw°   roll-yaw°  turned°")
    for j in range(max(closest - 8, 0), min(closest + 9, len(distance))):
        print(
            f"{t[j]:9.4f} {distance[j]:7.3f} {roll[j]:9.3f} {pitch[j]:9.4f} {yaw[j]:9.3f} "
            f"{wrap_degrees(roll[j] - yaw[j]):9.3f} {turned[j]:8.3f}"
        )


# ----------------------------------------------------------------------------------------------
def after_horizons(errors: Array) -> str:
    """Errors at the horizons, in words."""
    return ", ".join(f"{h:g} s {e:.2f}°" for h, e in zip(HORIZONS_S, errors, strict=True))


def integrate(start: Rotation, rates: Array, dt: float) -> Rotation:
    """Attitudes from body rates (rad/s): ``R ← R · exp(ω dt)`` per sample, exact per step."""
    steps = Rotation.from_rotvec(rates * dt)
    attitudes = [start]
    for step in steps:
        attitudes.append(attitudes[-1] * step)
    return Rotation.concatenate(attitudes)


def gyroscope(rec: Recording, inertial_rate: float, attitude_rate: float) -> None:
    """Units, frame, timing, and integration against the device's attitude."""
    print("\n== 6. Gyroscope")
    steps = rec.gyroscope * 16
    print(
        f"values are whole multiples of 1/16 deg/s: {bool(np.all(steps == np.round(steps)))}; "
        f"largest |component| {np.abs(rec.gyroscope).max():g} deg/s (GyroscopeFullScale "
        f"{rec.registers['GyroscopeFullScale']:.0f}: ±2000 deg/s)"
    )
    print(
        f"accelerometer: largest |component| {np.abs(rec.accelerometer).max():.2f} g "
        f"(AccelerometerFullScale {rec.registers['AccelerometerFullScale']:.0f}: ±8 g)"
    )
    attitude = Rotation.from_matrix(rec.matrix)
    rates = np.radians(rec.gyroscope)  # the header says deg/s
    per_attitude = round(inertial_rate / attitude_rate)  # inertial samples per attitude sample
    m = len(attitude)
    body = (attitude[:-1].inv() * attitude[1:]).as_rotvec()  # R_j⁻¹ R_j+1: body frame
    space = (attitude[1:] * attitude[:-1].inv()).as_rotvec()  # R_j+1 R_j⁻¹: earth frame
    print("turn between attitude samples vs the gyro (deg/s -> rad/s) summed over the samples")
    print("between them; shift moves the gyro samples by whole inertial samples:")
    for shift in range(-2, 3):
        first = per_attitude * np.arange(m - 1) + 1 + shift  # rows 2j+1, 2j+2 for shift 0
        usable = (first >= 0) & (first + per_attitude <= len(rates))
        summed = sum(rates[first[usable] + k] for k in range(per_attitude)) / inertial_rate
        for frame, turn in (("body", body[usable]), ("earth", space[usable])):
            residual = np.degrees(np.sqrt(np.mean(np.sum((turn - summed) ** 2, axis=1))))
            scale = np.sum(turn * summed) / np.sum(summed * summed)
            print(f"  shift {shift:+d} {frame:5} rms residual {residual:.3f}°, scale {scale:.3f}")
    rms_turn = np.degrees(np.sqrt(np.mean(np.sum(body**2, axis=1))))
    print(f"rms turn per attitude sample: {rms_turn:.3f}°")

    first = per_attitude * np.arange(m - 1) + 1
    summed = sum(rates[first + k] for k in range(per_attitude)) / inertial_rate
    residual = np.degrees(np.linalg.norm(body - summed, axis=1))
    g_off = np.abs(np.linalg.norm(at_attitude_samples(rec, rec.accelerometer), axis=1) - 1)[:-1]
    print("per-sample residual (body, shift 0) against how far |a| is from 1 g:")
    for lo, hi in ((0, 0.1), (0.1, 0.3), (0.3, 1.0), (1.0, np.inf)):
        chosen = (g_off >= lo) & (g_off < hi)
        if chosen.any():
            rms = np.sqrt(np.mean(residual[chosen] ** 2))
            print(f"  ||a| - 1| in [{lo:g}, {hi:g}) g: {chosen.sum():4d} samples, rms {rms:.3f}°")

    print("integrating from the device's attitude at t0 (one rotvec per inertial sample):")
    horizons = [round(h * attitude_rate) for h in HORIZONS_S]
    starts = range(0, m - horizons[-1], round(attitude_rate / 4))
    errors = []
    for j0 in starts:
        rows = slice(per_attitude * j0 + 1, per_attitude * (j0 + horizons[-1]) + 1)
        path = integrate(attitude[j0], rates[rows], 1 / inertial_rate)[::per_attitude]
        error = angle_between(path, attitude[j0 : j0 + horizons[-1] + 1])
        errors.append(error[horizons])
        if j0 % round(attitude_rate) == 0:
            print(f"  t0 = {j0 / attitude_rate:5.2f} s: after {after_horizons(error[horizons])}")
    table = np.array(errors)
    print(
        f"  over {len(table)} starts every 0.25 s: median {after_horizons(np.median(table, 0))}; "
        f"max {after_horizons(table.max(0))}"
    )


def main(argv: list[str] | None = None) -> None:
    """Print the evidence, section by section."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--data",
        type=Path,
        default=Path(__file__).resolve().parent,
        help="folder with the 00033_*.csv files (default: the excerpt next to this script)",
    )
    args = parser.parse_args(argv)
    np.set_printoptions(precision=3, suppress=True)
    rec = load(args.data)
    inertial_rate, attitude_rate = streams(rec)
    quaternion_layout(rec)
    frame_direction(rec)
    euler_sequence(rec)
    gimbal_lock(rec, attitude_rate)
    gyroscope(rec, inertial_rate, attitude_rate)


if __name__ == "__main__":
    main()
