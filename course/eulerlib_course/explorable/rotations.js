// The arithmetic of the explorables, for a page with no Python behind it.
//
// A small port of the parts of eulerlib that the explorables show: the 24 Euler sequences and
// the presets, Euler angles to a matrix and back with each convention's choice at gimbal lock
// (K. Shoemake's method, as eulerlib computes it), the distance to gimbal lock, quaternions
// (scalar first, w > 0) and slerp. Angles are in degrees, reduced exactly as eulerlib reduces
// them, so that 90° gives exact zeros and ones. Matrices are arrays of three rows.
// The course's tests run this module in Chromium and hold every result against eulerlib's on
// the same inputs (course/tests/test_explorable_browser.py).

const AXES = "xyz";

/** The 24 sequences: 12 intrinsic (uppercase), then 12 extrinsic (lowercase). */
export const ALL_SEQUENCES = (() => {
  const tait = ["XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"];
  const proper = ["XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"];
  const upper = [...tait, ...proper];
  return [...upper, ...upper.map((seq) => seq.toLowerCase())];
})();

/** An axis sequence, parsed: its axes (0, 1, 2 for x, y, z) and those of its intrinsic form. */
export function parseSequence(seq) {
  if (!ALL_SEQUENCES.includes(seq)) {
    throw new Error(`seq ${JSON.stringify(seq)} is not one of the 24 sequences`);
  }
  const axes = [...seq.toLowerCase()].map((letter) => AXES.indexOf(letter));
  const intrinsic = seq === seq.toUpperCase();
  return {
    seq,
    axes,
    intrinsic,
    proper: axes[0] === axes[2],
    intrinsicAxes: intrinsic ? axes : [...axes].reverse(),
  };
}

const PRESETS = {
  rose: { seq: "ZYX", names: ["yaw", "pitch", "roll"], lockZeroes: "first" },
  aerospace: { seq: "ZYX", names: ["yaw", "pitch", "roll"], lockZeroes: "first" },
  baker: { seq: "YZX", names: ["heading", "attitude", "bank"], lockZeroes: "third" },
  ros: { seq: "xyz", names: ["roll", "pitch", "yaw"], lockZeroes: "third" },
};

/** The preset names, in the order the chooser offers them. */
export const PRESET_NAMES = Object.keys(PRESETS);

/** A convention by preset name or sequence: name, seq, angle names, lock policy, label. */
export function getConvention(name) {
  if (typeof name === "object" && name !== null) {
    // a convention spelled out: { name, seq, names, lockZeroes }
    return { ...name, label: `${name.name} (${name.seq})`, parsed: parseSequence(name.seq) };
  }
  const preset = PRESETS[String(name).toLowerCase()];
  if (preset) {
    const key = String(name).toLowerCase();
    return { name: key, ...preset, label: `${key} (${preset.seq})`, parsed: parseSequence(preset.seq) };
  }
  const parsed = parseSequence(name);
  const letters = parsed.axes.map((axis) => AXES[axis]);
  const names = parsed.intrinsic
    ? [letters[0], `${letters[1]}'`, `${letters[2]}''`]
    : [letters[0], letters[1], parsed.proper ? `${letters[2]}2` : letters[2]];
  return {
    name,
    seq: name,
    names,
    lockZeroes: parsed.intrinsic ? "first" : "third",
    label: name,
    parsed,
  };
}

/** Whether the angle set to 0 at lock is the first one of the intrinsic form. */
function zeroesIntrinsicFirst(convention) {
  return (convention.lockZeroes === "first") === convention.parsed.intrinsic;
}

function intrinsicOrder(convention, values) {
  return convention.parsed.intrinsic ? [...values] : [...values].reverse();
}

const RADIANS = Math.PI / 180;
const DEGREES = 180 / Math.PI;

/** Round half to even, as numpy does. */
function roundEven(x) {
  const r = Math.round(x);
  return Math.abs(x % 1) === 0.5 && r % 2 !== 0 ? r - 1 : r;
}

/** sin and cos of an angle in degrees, exact at multiples of 90° (eulerlib's reduction). */
export function sinCosDegrees(angle) {
  const reduced = angle % 360; // exact, as fmod
  const quarter = roundEven(reduced / 90);
  const rest = (reduced - 90 * quarter) * RADIANS;
  const s = Math.sin(rest);
  const c = Math.cos(rest);
  const turn = ((quarter % 4) + 4) % 4;
  const pairs = [
    [s, c],
    [c, -s],
    [-s, -c],
    [-c, s],
  ];
  const [sine, cosine] = pairs[turn];
  return [sine + 0, cosine + 0];
}

/** The signed permutation of eulerlib's kernels: R = P M Pᵀ, M about x, y, (z or x). */
function frame(parsed) {
  const [i, j] = parsed.intrinsicAxes;
  const k = 3 - i - j;
  const sign = (((j - i) % 3) + 3) % 3 === 1 ? 1 : -1;
  return { index: [i, j, k], sign: [1, 1, sign] };
}

function zeroMatrix() {
  return [
    [0, 0, 0],
    [0, 0, 0],
    [0, 0, 0],
  ];
}

/** The rotation matrix of three angles (degrees, in the convention's argument order). */
export function eulerToMatrix(angles, conventionName) {
  const convention = getConvention(conventionName);
  const parsed = convention.parsed;
  const [a1, a2, a3] = intrinsicOrder(convention, angles);
  const { index, sign } = frame(parsed);
  const [s1, c1] = sinCosDegrees(a1);
  const [s2, c2] = sinCosDegrees(a2);
  let [s3, c3] = sinCosDegrees(a3);
  let M;
  if (parsed.proper) {
    M = [
      [c2, s2 * s3, s2 * c3],
      [s1 * s2, c1 * c3 - s1 * c2 * s3, -c1 * s3 - s1 * c2 * c3],
      [-c1 * s2, s1 * c3 + c1 * c2 * s3, c1 * c2 * c3 - s1 * s3],
    ];
  } else {
    s3 *= sign[2];
    M = [
      [c2 * c3, -c2 * s3, s2],
      [c1 * s3 + s1 * s2 * c3, c1 * c3 - s1 * s2 * s3, -s1 * c2],
      [s1 * s3 - c1 * s2 * c3, s1 * c3 + c1 * s2 * s3, c1 * c2],
    ];
  }
  const R = zeroMatrix();
  for (let r = 0; r < 3; r++) {
    for (let c = 0; c < 3; c++) {
      R[index[r]][index[c]] = (sign[r] * sign[c] > 0 ? M[r][c] : -M[r][c]) + 0;
    }
  }
  return R;
}

/** eulerlib's GIMBAL_LOCK_TOLERANCE: 2⁻⁴⁹ rad. */
export const GIMBAL_LOCK_TOLERANCE = 2 ** -49;

function relabelled(R, parsed) {
  const { index, sign } = frame(parsed);
  const m = (r, c) => {
    const entry = R[index[r]][index[c]];
    return sign[r] * sign[c] > 0 ? entry : -entry;
  };
  return { m, thirdSign: sign[2] };
}

function middleAngle(m, proper) {
  if (proper) {
    const sine = Math.sqrt(m(0, 1) * m(0, 1) + m(0, 2) * m(0, 2));
    const cosine = m(0, 0);
    return [Math.atan2(sine, cosine), Math.atan2(sine, Math.abs(cosine))];
  }
  const sine = m(0, 2);
  const cosine = Math.sqrt(m(0, 0) * m(0, 0) + m(0, 1) * m(0, 1));
  return [Math.atan2(sine, cosine), Math.atan2(cosine, Math.abs(sine))];
}

/** Distance of the middle angle from the nearest singular value, degrees. */
export function lockDistance(R, conventionName) {
  const { m } = relabelled(R, getConvention(conventionName).parsed);
  return middleAngle(m, getConvention(conventionName).parsed.proper)[1] * DEGREES;
}

/**
 * The angles of a rotation matrix (degrees, argument order), with the convention's choice at
 * gimbal lock: { angles, locked, distance } (distance in degrees).
 */
export function matrixToEuler(R, conventionName) {
  const convention = getConvention(conventionName);
  const parsed = convention.parsed;
  const { m, thirdSign } = relabelled(R, parsed);
  const [middle, distance] = middleAngle(m, parsed.proper);
  const locked = distance <= GIMBAL_LOCK_TOLERANCE;
  let first;
  let third;
  if (parsed.proper) {
    if (zeroesIntrinsicFirst(convention)) {
      first = locked ? 0 : Math.atan2(m(1, 0), -m(2, 0));
      const s1 = Math.sin(first);
      const c1 = Math.cos(first);
      third = Math.atan2(-(c1 * m(1, 2) + s1 * m(2, 2)), c1 * m(1, 1) + s1 * m(2, 1));
    } else {
      third = locked ? 0 : Math.atan2(m(0, 1), m(0, 2));
      const s3 = Math.sin(third);
      const c3 = Math.cos(third);
      first = Math.atan2(c3 * m(2, 1) - s3 * m(2, 2), c3 * m(1, 1) - s3 * m(1, 2));
    }
  } else {
    if (zeroesIntrinsicFirst(convention)) {
      first = locked ? 0 : Math.atan2(-m(1, 2), m(2, 2));
      const s1 = Math.sin(first);
      const c1 = Math.cos(first);
      third = Math.atan2(c1 * m(1, 0) + s1 * m(2, 0), c1 * m(1, 1) + s1 * m(2, 1));
    } else {
      third = locked ? 0 : Math.atan2(-m(0, 1), m(0, 0));
      const s3 = Math.sin(third);
      const c3 = Math.cos(third);
      first = Math.atan2(s3 * m(2, 0) + c3 * m(2, 1), s3 * m(1, 0) + c3 * m(1, 1));
    }
    third *= thirdSign;
  }
  const intrinsic = [first, middle, third].map((angle) => {
    const value = angle + 0;
    return (value === -Math.PI ? Math.PI : value) * DEGREES;
  });
  return {
    angles: intrinsicOrder(convention, intrinsic),
    locked,
    distance: distance * DEGREES,
  };
}

/** The unit quaternion (w, x, y, z) of a rotation matrix, with w > 0 (eulerlib's choice). */
export function matrixToQuaternion(R) {
  const [[r00, r01, r02], [r10, r11, r12], [r20, r21, r22]] = R;
  const squares = [
    1 + r00 + r11 + r22, // 4 w²
    1 + r00 - r11 - r22, // 4 x²
    1 - r00 + r11 - r22, // 4 y²
    1 - r00 - r11 + r22, // 4 z²
  ];
  let k = 0;
  for (let i = 1; i < 4; i++) {
    if (squares[i] > squares[k]) k = i;
  }
  const q = [0, 0, 0, 0];
  const big = Math.sqrt(squares[k]); // 2 |q_k|
  q[k] = 0.5 * big;
  const pair = {
    "0,1": r21 - r12,
    "0,2": r02 - r20,
    "0,3": r10 - r01,
    "1,2": r01 + r10,
    "1,3": r02 + r20,
    "2,3": r12 + r21,
  };
  for (let other = 0; other < 4; other++) {
    if (other !== k) {
      const key = `${Math.min(k, other)},${Math.max(k, other)}`;
      q[other] = (0.5 * pair[key]) / big; // 4 q_k q_other / (4 q_k)
    }
  }
  return canonical(q);
}

/** Of q and −q, the one with w > 0 (at w = 0, the first nonzero of x, y, z positive). */
export function canonical(q) {
  let sign = q[0] < 0 || Object.is(q[0], -0) ? -1 : 1;
  if (q[0] === 0) {
    const first = q.slice(1).find((part) => part !== 0) || 0;
    sign = first < 0 ? -1 : 1;
  }
  return q.map((part) => sign * part + 0);
}

/** The rotation matrix of a quaternion (w, x, y, z) of any nonzero length. */
export function quaternionToMatrix(q) {
  const n = Math.hypot(q[0], q[1], q[2], q[3]);
  const [w, x, y, z] = q.map((part) => part / n);
  return [
    [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
    [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
    [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
  ].map((row) => row.map((entry) => entry + 0));
}

function quaternionProduct(p, q) {
  const [pw, px, py, pz] = p;
  const [qw, qx, qy, qz] = q;
  return [
    pw * qw - px * qx - py * qy - pz * qz,
    pw * qx + px * qw + py * qz - pz * qy,
    pw * qy - px * qz + py * qw + pz * qx,
    pw * qz + px * qy - py * qx + pz * qw,
  ];
}

/** The matrix a fraction t of the way from R0 to R1 on the shortest arc (slerp). */
export function slerp(R0, R1, t) {
  const q0 = matrixToQuaternion(R0);
  const q1 = matrixToQuaternion(R1);
  // the turn from R0 to R1, seen in R0's axes: q0* q1, on the near side
  const turn = canonical(quaternionProduct([q0[0], -q0[1], -q0[2], -q0[3]], q1));
  const vector = Math.hypot(turn[1], turn[2], turn[3]);
  const half = Math.atan2(vector, turn[0]);
  let step = [1, 0, 0, 0];
  if (vector > 0) {
    const scale = Math.sin(t * half) / vector;
    step = [Math.cos(t * half), turn[1] * scale, turn[2] * scale, turn[3] * scale];
  }
  return quaternionToMatrix(quaternionProduct(q0, step));
}

/** R v for a matrix and a vector. */
export function apply(R, v) {
  return R.map((row) => row[0] * v[0] + row[1] * v[1] + row[2] * v[2]);
}

/** The singular middle angle (degrees) nearest to a middle angle in degrees. */
export function pole(conventionName, middle) {
  if (getConvention(conventionName).parsed.proper) return middle < 90 ? 0 : 180;
  return middle > 0 ? 90 : -90;
}

/** The combination of the outer angles a locked matrix still defines, in words. */
export function lockCombination(conventionName, at) {
  const convention = getConvention(conventionName);
  const parsed = convention.parsed;
  let sign;
  if (parsed.proper) sign = at === 0 ? 1 : -1;
  else sign = frame(parsed).sign[2] * (at > 0 ? 1 : -1);
  const [first, , third] = convention.names;
  if (sign > 0) return `${first} + ${third}`;
  return parsed.intrinsic ? `${third} - ${first}` : `${first} - ${third}`;
}

/** One body of the picture: eulerlib_course.explorable.track, computed here. */
export function track(matrix, conventionName, label, rings = null) {
  const convention = getConvention(conventionName);
  const { angles, locked, distance } = matrixToEuler(matrix, conventionName);
  let lock = null;
  if (locked) {
    const at = pole(conventionName, angles[1]);
    const zeroed = convention.lockZeroes === "first" ? 0 : 2;
    lock = {
      pole: at,
      combination: lockCombination(conventionName, at),
      zeroed: convention.names[zeroed],
      carrier: convention.names[2 - zeroed],
    };
  }
  return {
    label,
    seq: typeof conventionName === "object" ? conventionName : convention.name,
    names: [...convention.names],
    matrix: matrix.map((row) => row.map((entry) => entry + 0)),
    angles,
    rings: rings === null ? angles : [...rings],
    locked,
    distance,
    lock,
  };
}

/**
 * The state of an explorable for its settings and controls:
 * eulerlib_course.explorable.compute_state, computed here.
 */
export function computeState(config, controls) {
  if (config.kind === "angles") {
    const { seq, angles } = controls;
    const matrix = eulerToMatrix(angles, seq);
    const state = {
      tracks: [track(matrix, seq, getConvention(seq).label, angles)],
      compare: (config.compare || []).map((other) => ({
        label: getConvention(other).label,
        names: [...getConvention(other).names],
        angles: matrixToEuler(matrix, other).angles,
      })),
      quaternion: null,
    };
    if (config.quaternion) {
      const q = matrixToQuaternion(matrix);
      const shown = controls.flip ? q.map((part) => -part + 0) : q;
      state.quaternion = { q: shown, matrix: quaternionToMatrix(shown) };
    }
    return state;
  }
  const index = Math.round(controls.frame);
  if (config.kind === "paths") {
    const t = config.times[index];
    const { seq, start, end } = config;
    const angles = start.map((a, i) => (1 - t) * a + t * end[i]);
    const R0 = eulerToMatrix(start, seq);
    const R1 = eulerToMatrix(end, seq);
    return {
      tracks: [
        track(eulerToMatrix(angles, seq), seq, "interpolated angles", angles),
        track(slerp(R0, R1, t), seq, "slerp"),
      ],
      compare: [],
      quaternion: null,
      time: t,
      frames: config.times.length,
    };
  }
  return {
    tracks: [track(config.matrices[index], config.seq, config.label || "recording")],
    compare: [],
    quaternion: null,
    time: config.times[index],
    frames: config.times.length,
  };
}
