"""Cut the course's excerpt of the x-io x-IMU recording 00033 out of scikit-kinematics 0.10.4.

The recording ships in the wheel of scikit-kinematics 0.10.4 (BSD-3-Clause, copyright Thomas
Haslwanter) under ``tests/data/data_xio/``. Every data row of its CSV files starts with the
packet number the device gave it; the device numbers all its packets in one sequence, so a range
of packet numbers is the same stretch of time in every file. The excerpt keeps the rows whose
packet number lies in ``[first, end)``, where ``first`` and ``end`` are the packet numbers of
the inertial samples at ``START_S`` and ``END_S`` seconds (the inertial stream runs at 256 Hz,
see README.md). Header lines and rows are copied byte for byte (CRLF line ends included); no
column is dropped and no value is rewritten. The register dump, which holds the device's
settings rather than samples, is kept whole. The licence file of the wheel is copied verbatim.

Run it on the downloaded wheel (or on a folder into which the wheel was unpacked)::

    pip download scikit-kinematics==0.10.4 --no-deps -d download
    python notebooks/data/make_excerpt.py download/scikit_kinematics-0.10.4-py3-none-any.whl

It refuses files whose SHA-256 differs from the ones recorded here, and prints the SHA-256 of
what it writes. The tests never run it; it documents how the excerpt was made.
"""

from __future__ import annotations

import argparse
import hashlib
import zipfile
from pathlib import Path

#: Where the recording lies inside the wheel, and the licence that covers it.
DATA_DIR = "tests/data/data_xio"
LICENSE_MEMBER = "scikit_kinematics-0.10.4.dist-info/LICENSE.txt"
LICENSE_OUT = "LICENSE-xio-recording.txt"

#: SHA-256 of the files as shipped in scikit-kinematics 0.10.4.
ORIGINAL_SHA256 = {
    "00033_CalInertialAndMag.csv": (
        "1df47f2c3c20a3094927e3f919083797ad58527fb41199f5c6f75cdab89d5c75"
    ),
    "00033_Quaternion.csv": "93d68060da1524baefc4e98060ec8d6226ae0ac0ba2ca0381cded78300320425",
    "00033_EulerAngles.csv": "7c0e554df4bba8df6135478020b3657bf293257e18426abf53e43e9cb63bed80",
    "00033_RotationMatrix.csv": (
        "d60e71fc40f5a17b756f44a4ec9eca295193463f5b7124b21062e51b095bd120"
    ),
    "00033_DateTime.csv": "8c7b4c261e95711f53a70aefa385d594f68a9b2870d821f8ae91588c868c0203",
    "00033_CalBattAndTherm.csv": "7240cac635dc0aa16fd24326f0514ca52c128ca926599e3064752af44cbac2ed",
    "00033_Registers.csv": "a92665ed5d06d417df409c7411f85503a4f38a18c16d4398cc5b11211f0b5d8d",
    LICENSE_MEMBER: "0b6ec4b0afa43c38ac97ad8363b387297dd526d188cf8d0fdcbd321995130bf1",
}

#: Files whose rows are samples in time: cut to the window. The register dump is kept whole.
TIMED_FILES = (
    "00033_CalInertialAndMag.csv",
    "00033_Quaternion.csv",
    "00033_EulerAngles.csv",
    "00033_RotationMatrix.csv",
    "00033_DateTime.csv",
    "00033_CalBattAndTherm.csv",
)
WHOLE_FILES = ("00033_Registers.csv",)

#: The window, in seconds from the first inertial sample of the recording, and the inertial
#: sample rate that turns it into sample indices (InertialAndMagneticDataRate = 256 Hz).
START_S = 3.0
END_S = 10.5
INERTIAL_RATE_HZ = 256


def read_original(source: Path, name: str) -> bytes:
    """The bytes of one shipped file, from the wheel or an unpacked folder, checked by hash."""
    member = name if name == LICENSE_MEMBER else f"{DATA_DIR}/{name}"
    if source.is_dir():
        data = (source / member).read_bytes()
    else:
        with zipfile.ZipFile(source) as wheel:
            data = wheel.read(member)
    digest = hashlib.sha256(data).hexdigest()
    if digest != ORIGINAL_SHA256[name]:
        raise ValueError(f"{member}: SHA-256 is {digest}, expected {ORIGINAL_SHA256[name]}")
    return data


def packet_number(line: bytes) -> int:
    """The packet number that opens a data row."""
    return int(line.split(b",", 1)[0])


def cut(data: bytes, first: int, end: int) -> bytes:
    """The header line and the rows whose packet number lies in ``[first, end)``."""
    lines = data.splitlines(keepends=True)
    kept = [line for line in lines[1:] if first <= packet_number(line) < end]
    return lines[0] + b"".join(kept)


def main(argv: list[str] | None = None) -> None:
    """Write the excerpt, the licence copy, and print their SHA-256."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source", type=Path, help="the wheel, or a folder it was unpacked into")
    parser.add_argument(
        "--out", type=Path, default=Path(__file__).resolve().parent, help="output folder"
    )
    args = parser.parse_args(argv)

    inertial = read_original(args.source, "00033_CalInertialAndMag.csv").splitlines()[1:]
    first = packet_number(inertial[round(START_S * INERTIAL_RATE_HZ)])
    end = packet_number(inertial[round(END_S * INERTIAL_RATE_HZ)])
    print(f"window: {START_S} s to {END_S} s, packets {first} to {end - 1}")

    outputs = {name: cut(read_original(args.source, name), first, end) for name in TIMED_FILES}
    outputs |= {name: read_original(args.source, name) for name in WHOLE_FILES}
    outputs[LICENSE_OUT] = read_original(args.source, LICENSE_MEMBER)
    args.out.mkdir(parents=True, exist_ok=True)
    for name, data in outputs.items():
        (args.out / name).write_bytes(data)
        print(f"{name:30} {len(data):7d} bytes  sha256 {hashlib.sha256(data).hexdigest()}")


if __name__ == "__main__":
    main()
