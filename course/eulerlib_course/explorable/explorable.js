// The explorable: an aircraft, its frame, the fixed frame and the three gimbal rings, turned
// with the mouse, a finger or the arrow keys, with the controls and the numbers below.
//
// anywidget's pattern: `render({ model, el })` draws into `el` and reads and writes `model`.
// In JupyterLab the model is the widget's, and the kernel computes `state` with eulerlib; on
// the website `mount(el, settings)` gives it a stand-in model that computes `state` with
// rotations.js. The view never computes a number it shows; it only draws the state.
import { ALL_SEQUENCES, PRESET_NAMES, computeState, getConvention, sinCosDegrees } from "./rotations.js";

const STYLE = `
.eulexp { font: 14px/1.4 system-ui, sans-serif; color: #1b1b1b; max-width: 100%; }
.eulexp * { box-sizing: border-box; }
.eulexp .eulexp-panels { display: flex; flex-wrap: wrap; gap: 8px; }
.eulexp figure { margin: 0; flex: 1 1 260px; min-width: 0; max-width: 460px; }
.eulexp figcaption { font-weight: 600; text-align: center; }
.eulexp svg { width: 100%; height: auto; aspect-ratio: 1; background: #fafafa; border: 1px solid #ccc;
  border-radius: 6px; touch-action: none; cursor: grab; display: block; }
.eulexp svg:focus-visible { outline: 3px solid #1565c0; outline-offset: 2px; }
.eulexp svg.eulexp-dragging { cursor: grabbing; }
.eulexp .eulexp-controls { display: grid; gap: 6px; margin: 10px 0; }
.eulexp .eulexp-row { display: grid; grid-template-columns: minmax(5em, auto) 1fr 6.5em; gap: 8px;
  align-items: center; }
.eulexp input[type=range] { width: 100%; min-height: 28px; margin: 0; }
.eulexp input[type=number], .eulexp select, .eulexp button { font: inherit; min-height: 32px; }
.eulexp input[type=number] { width: 100%; }
.eulexp .eulexp-buttons { display: flex; flex-wrap: wrap; gap: 6px; }
.eulexp .eulexp-numbers { display: flex; flex-wrap: wrap; gap: 12px; }
.eulexp .eulexp-numbers > div { flex: 1 1 240px; min-width: 0; }
.eulexp pre { margin: 2px 0; font-size: 13px; white-space: pre; overflow-x: auto; }
.eulexp .eulexp-locked { color: #b00020; font-weight: 600; }
.eulexp .eulexp-summary { background: #f1f4f8; padding: 6px 8px; border-radius: 4px; }
@media (max-width: 480px) { .eulexp .eulexp-row { grid-template-columns: 1fr 5.5em; }
  .eulexp .eulexp-row input[type=range] { grid-column: 1 / -1; grid-row: 2; } }
`;

const AXIS_COLORS = ["#d62728", "#2ca02c", "#1f77b4"];
const RING_COLORS = ["#9467bd", "#ff7f0e", "#17becf"];
const RING_RADII = [1.45, 1.3, 1.15];
const SVG = "http://www.w3.org/2000/svg";
let counter = 0;

/** A number of degrees as the page shows it: at most four decimals, no "-0". */
export function formatDegrees(value) {
  const rounded = Math.round(value * 1e4) / 1e4 + 0;
  return `${Object.is(rounded, -0) ? 0 : rounded}°`;
}

function formatDistance(value) {
  if (value === 0) return "0°";
  return value < 0.01 ? `${value.toExponential(2)}°` : formatDegrees(value);
}

function formatEntry(value) {
  const text = value.toFixed(4);
  return text === "-0.0000" ? " 0.0000" : value < 0 ? text : ` ${text}`;
}

function matrixText(matrix) {
  return matrix.map((row) => `[${row.map(formatEntry).join(" ")}]`).join("\n");
}

function listing(names, values) {
  return names.map((name, i) => `${name} ${formatDegrees(values[i])}`).join(", ");
}

/** The state in one paragraph, for the live region a screen reader reads. */
export function summary(config, controls, state) {
  const parts = [];
  if (state.time !== undefined) parts.push(`Time ${Math.round(state.time * 1e4) / 1e4}.`);
  for (const body of state.tracks) {
    const convention = getConvention(body.seq);
    const named = body.label === convention.label ? "" : ` (${convention.label})`;
    let sentence = `${body.label}: ${listing(body.names, body.angles)}${named}; `;
    sentence += body.locked
      ? `gimbal lock: only ${body.lock.combination} is defined, ${body.lock.zeroed} set to 0.`
      : `${formatDistance(body.distance)} from gimbal lock.`;
    parts.push(sentence);
  }
  if (config.kind === "angles") {
    parts.unshift(`Set: ${listing(getConvention(controls.seq).names, controls.angles)}.`);
  }
  for (const other of state.compare || []) {
    parts.push(`In ${other.label}: ${listing(other.names, other.angles)}.`);
  }
  if (state.quaternion) {
    const q = state.quaternion.q.map((v) => Math.round(v * 1e4) / 1e4 + 0).join(", ");
    parts.push(`Quaternion (w, x, y, z) ${q}, the same matrix.`);
  }
  return parts.join(" ");
}

function element(tag, attributes = {}, parent = null, text = null) {
  const node = tag.startsWith("svg:")
    ? document.createElementNS(SVG, tag.slice(4))
    : document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (text !== null) node.textContent = text;
  if (parent) parent.appendChild(node);
  return node;
}

function matMul(A, B) {
  return A.map((row) => [0, 1, 2].map((c) => row[0] * B[0][c] + row[1] * B[1][c] + row[2] * B[2][c]));
}

function column(R, c) {
  return [R[0][c], R[1][c], R[2][c]];
}

function elementary(axis, degrees) {
  const [s, c] = sinCosDegrees(degrees);
  const R = [
    [1, 0, 0],
    [0, 1, 0],
    [0, 0, 1],
  ];
  const [p, q] = [(axis + 1) % 3, (axis + 2) % 3];
  R[p][p] = c;
  R[q][q] = c;
  R[q][p] = s;
  R[p][q] = -s;
  return R;
}

/** Outer, middle and inner ring: two unit vectors spanning each plane, as eulerlib draws them. */
function ringPlanes(seq, angles) {
  const parsed = getConvention(seq).parsed;
  const values = parsed.intrinsic ? angles : [...angles].reverse();
  const [a0, a1, a2] = parsed.intrinsicAxes;
  let R = [
    [1, 0, 0],
    [0, 1, 0],
    [0, 0, 1],
  ];
  const frames = [a0, a1, a2].map((axis, k) => (R = matMul(R, elementary(axis, values[k]))));
  const inPlane = [
    [a0, a1],
    [a1, a2],
    [a2, 3 - a1 - a2],
  ];
  return {
    planes: inPlane.map(([p, q], ring) => [column(frames[ring], p), column(frames[ring], q)]),
    firstAxis: column(frames[0], a0),
    thirdAxis: column(frames[2], a2),
  };
}

// The aircraft in body coordinates (forward, side, up): nose along +forward, fin up.
const F = (f, s, u) => [f, s, u];
const NOSE = F(1, 0, 0);
const TAIL = F(-0.95, 0, 0.06);
const MID = [F(0.25, 0.12, 0), F(0.25, 0, 0.13), F(0.25, -0.12, 0), F(0.25, 0, -0.1)];
const AFT = [F(-0.55, 0.06, 0.02), F(-0.55, 0, 0.09), F(-0.55, -0.06, 0.02), F(-0.55, 0, -0.04)];
const AIRCRAFT = [
  ...[0, 1, 2, 3].map((k) => [NOSE, MID[k], MID[(k + 1) % 4]]),
  ...[0, 1, 2, 3].map((k) => [MID[k], AFT[k], AFT[(k + 1) % 4], MID[(k + 1) % 4]]),
  ...[0, 1, 2, 3].map((k) => [AFT[k], TAIL, AFT[(k + 1) % 4]]),
  [F(0.2, 0, 0), F(-0.2, 0.9, 0), F(-0.42, 0.9, 0), F(-0.3, 0, 0), F(-0.42, -0.9, 0), F(-0.2, -0.9, 0)],
  [F(-0.68, 0, 0.02), F(-0.86, 0.36, 0.02), F(-0.96, 0.36, 0.02), F(-0.92, 0, 0.02),
    F(-0.96, -0.36, 0.02), F(-0.86, -0.36, 0.02)],
  [F(-0.62, 0, 0.06), F(-0.9, 0, 0.42), F(-1.0, 0, 0.42), F(-0.95, 0, 0.06)],
];

/** Body coordinates (forward, side, up) into the convention's axes (x forward). */
function bodyPoint(point, up) {
  const [f, s, u] = point;
  if (up === "y") return [f, u, s];
  if (up === "-z") return [f, s, -u];
  return [f, s, u];
}

const UP_AXES = { rose: "z", ros: "z", aerospace: "-z", baker: "y" };

/** The camera's basis for an azimuth and elevation (degrees) about the convention's up axis. */
function camera(view, up) {
  const axes = {
    z: [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
    y: [[0, 0, 1], [1, 0, 0], [0, 1, 0]],
    "-z": [[1, 0, 0], [0, -1, 0], [0, 0, -1]],
  }[up];
  const az = (view.azimuth * Math.PI) / 180;
  const el = (view.elevation * Math.PI) / 180;
  const mix = (a, b, c) => [0, 1, 2].map((i) => a * axes[0][i] + b * axes[1][i] + c * axes[2][i]);
  return {
    toward: mix(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el)),
    right: mix(-Math.sin(az), Math.cos(az), 0),
    up: mix(-Math.sin(el) * Math.cos(az), -Math.sin(el) * Math.sin(az), Math.cos(el)),
  };
}

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

function draw(svg, body, trail, view) {
  const up = UP_AXES[body.seq] || "z";
  const cam = camera(view, up);
  const scale = 100 / 1.7;
  const project = (p) => [dot(p, cam.right) * scale, -dot(p, cam.up) * scale, dot(p, cam.toward)];
  const items = []; // [depth, tag, attributes, text]
  const line = (a, b, attributes) => {
    const [x1, y1, d1] = project(a);
    const [x2, y2, d2] = project(b);
    items.push([(d1 + d2) / 2, "line", { x1, y1, x2, y2, ...attributes }]);
  };
  const label = (p, text, color) => {
    const [x, y, d] = project(p);
    items.push([d + 0.05, "text", { x, y, fill: color, "font-size": 11, "text-anchor": "middle",
      "dominant-baseline": "middle", "font-weight": 600 }, text]);
  };
  // the fixed frame, dashed
  for (let i = 0; i < 3; i++) {
    const e = [0, 0, 0];
    e[i] = 1.25;
    line([0, 0, 0], e, { stroke: AXIS_COLORS[i], "stroke-width": 1.3, "stroke-dasharray": "5 4",
      opacity: 0.6 });
    label(e.map((v) => v * 1.1), "xyz"[i], AXIS_COLORS[i]);
  }
  // the gimbal rings and the axes of the first and third angle
  const rings = ringPlanes(body.seq, body.rings);
  rings.planes.forEach(([u, v], ring) => {
    const r = RING_RADII[ring];
    let previous = null;
    for (let k = 0; k <= 72; k++) {
      const t = (k / 72) * 2 * Math.PI;
      const p = [0, 1, 2].map((i) => r * (Math.cos(t) * u[i] + Math.sin(t) * v[i]));
      if (previous) line(previous, p, { stroke: RING_COLORS[ring], "stroke-width": 4.2,
        "stroke-linecap": "round", class: `eulexp-ring eulexp-ring-${ring}` });
      previous = p;
    }
  });
  const pivotColor = body.locked ? "#b00020" : "#555";
  for (const axis of [rings.firstAxis, rings.thirdAxis]) {
    line(axis.map((v) => -1.6 * v), axis.map((v) => 1.6 * v), { stroke: pivotColor,
      "stroke-width": 1.5, "stroke-dasharray": "2 3" });
  }
  // the path of the nose
  if (trail) {
    for (let k = 1; k < trail.length; k++) {
      line(trail[k - 1], trail[k], { stroke: "#6d4c41", "stroke-width": 1.6, opacity: 0.8 });
    }
  }
  // the aircraft, shaded by how much each face looks toward a light above the camera
  const R = body.matrix;
  const turn = (p) => R.map((row) => dot(row, bodyPoint(p, up)));
  const light = cam.toward.map((v, i) => 0.7 * v + 0.5 * cam.up[i]);
  for (const face of AIRCRAFT) {
    const world = face.map(turn);
    const a = world[1].map((v, i) => v - world[0][i]);
    const b = world[2].map((v, i) => v - world[0][i]);
    const n = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const length = Math.hypot(...n) || 1;
    const shade = Math.round(150 + 90 * Math.abs(dot(n, light)) / length);
    const points = world.map(project);
    const depth = points.reduce((sum, p) => sum + p[2], 0) / points.length;
    items.push([depth, "polygon", { points: points.map((p) => `${p[0]},${p[1]}`).join(" "),
      fill: `rgb(${shade},${shade},${Math.min(255, shade + 12)})`, stroke: "#333",
      "stroke-width": 0.6, "stroke-linejoin": "round", class: "eulexp-body" }]);
  }
  // the body frame, solid
  for (let i = 0; i < 3; i++) {
    const tip = column(R, i).map((v) => 1.2 * v);
    line([0, 0, 0], tip, { stroke: AXIS_COLORS[i], "stroke-width": 2.4 });
    label(tip.map((v) => v * 1.12), `${"xyz"[i]}'`, AXIS_COLORS[i]);
  }
  items.sort((p, q) => p[0] - q[0]);
  const group = element("svg:g");
  for (const [, tag, attributes, text] of items) {
    const node = element(`svg:${tag}`, attributes, group);
    if (text !== undefined) node.textContent = text;
  }
  svg.replaceChildren(group);
}

function rangeRow(parent, id, name, min, max, step, value, onInput) {
  const row = element("div", { class: "eulexp-row" }, parent);
  const text = element("label", { for: `${id}-number` }, row, name);
  const range = element("input", { type: "range", id: `${id}-range`, min, max, step,
    "aria-label": name }, row);
  const number = element("input", { type: "number", id: `${id}-number`, min, max, step: "any" }, row);
  range.value = value;
  number.value = value;
  range.addEventListener("input", () => onInput(Number(range.value), range));
  number.addEventListener("change", () => {
    const value = Number(number.value);
    if (number.value !== "" && Number.isFinite(value)) onInput(value, number);
  });
  return { row, text, range, number };
}

/** Draw an explorable into `el`, driven by `model`; returns a function that removes it. */
function render({ model, el }) {
  const id = `eulexp-${++counter}`;
  const config = model.get("config");
  const reducedMotion = window.matchMedia?.("(prefers-reduced-motion: reduce)").matches ?? false;
  const root = element("div", { class: "eulexp", id }, null);
  element("style", {}, root, STYLE);
  const panels = element("div", { class: "eulexp-panels" }, root);
  const view = { azimuth: 35, elevation: 22 };
  const figures = [];
  const controls = element("div", { class: "eulexp-controls", role: "group",
    "aria-label": "controls" }, root);
  const numbers = element("div", { class: "eulexp-numbers" }, root);
  const live = element("p", { class: "eulexp-summary", "aria-live": "polite", role: "status" }, root);
  el.appendChild(root);
  // keys pressed in the explorable are its own: JupyterLab's shortcuts (arrows move between
  // cells in command mode) never see them
  root.dataset.lmSuppressShortcuts = "true";
  root.addEventListener("keydown", (event) => event.stopPropagation());

  const controlValues = () => ({
    seq: model.get("seq"),
    angles: model.get("angles"),
    flip: model.get("flip"),
    frame: model.get("frame"),
  });
  const send = (name, value) => {
    model.set(name, value);
    model.save_changes();
  };

  let angleRows = [];
  if (config.kind === "angles") {
    const names = getConvention(model.get("seq")).names;
    angleRows = [0, 1, 2].map((i) =>
      rangeRow(controls, `${id}-angle${i}`, names[i], -180, 180, 1, model.get("angles")[i],
        (value, source) => {
          const angles = [...model.get("angles")];
          angles[i] = value;
          if (source.type === "range") angleRows[i].number.value = value;
          else angleRows[i].range.value = value;
          send("angles", angles);
        }),
    );
    const row = element("div", { class: "eulexp-row" }, controls);
    element("label", { for: `${id}-seq` }, row, "convention");
    const select = element("select", { id: `${id}-seq` }, row);
    for (const [title, names] of [["presets", PRESET_NAMES], ["the 24 sequences", ALL_SEQUENCES]]) {
      const group = element("optgroup", { label: title }, select);
      for (const name of names) element("option", { value: name }, group, getConvention(name).label);
    }
    select.value = model.get("seq");
    select.addEventListener("change", () => send("seq", select.value));
    if (config.quaternion) {
      const box = element("label", {}, controls);
      const check = element("input", { type: "checkbox" }, box);
      box.append(" show −q instead of q");
      check.checked = model.get("flip");
      check.addEventListener("change", () => send("flip", check.checked));
    }
  } else {
    const last = config.times.length - 1;
    const time = rangeRow(controls, `${id}-time`, "moment", 0, last, 1, model.get("frame"),
      (value) => send("frame", Math.max(0, Math.min(last, Math.round(value)))));
    angleRows = [time];
    const buttons = element("div", { class: "eulexp-buttons" }, controls);
    const step = (by) => send("frame", Math.max(0, Math.min(last, model.get("frame") + by)));
    element("button", { type: "button" }, buttons, "◀ step back").addEventListener("click", () => step(-1));
    element("button", { type: "button" }, buttons, "step on ▶").addEventListener("click", () => step(1));
    if (!reducedMotion) {
      const play = element("button", { type: "button", "aria-pressed": "false" }, buttons, "play");
      let timer = null;
      const stop = () => {
        clearInterval(timer);
        timer = null;
        play.textContent = "play";
        play.setAttribute("aria-pressed", "false");
      };
      play.addEventListener("click", () => {
        if (timer) return stop();
        if (model.get("frame") >= last) send("frame", 0);
        play.textContent = "pause";
        play.setAttribute("aria-pressed", "true");
        const every = Math.max(1, Math.round(last / 120));
        timer = setInterval(() => (model.get("frame") >= last ? stop() : step(every)), 60);
      });
      root.stopPlaying = stop;
    }
  }
  const reset = element("button", { type: "button" }, element("div", { class: "eulexp-buttons" }, controls),
    "reset the view");
  reset.addEventListener("click", () => {
    view.azimuth = 35;
    view.elevation = 22;
    redraw();
  });

  function ensureFigures(count) {
    while (figures.length < count) {
      const k = figures.length;
      const figure = element("figure", {}, panels);
      const caption = element("figcaption", { id: `${id}-caption${k}` }, figure);
      const svg = element("svg:svg", { viewBox: "-100 -100 200 200", tabindex: "0", role: "img",
        "aria-describedby": `${id}-caption${k}` }, figure);
      orbit(svg);
      figures.push({ svg, caption });
    }
  }

  function orbit(svg) {
    let last = null;
    svg.addEventListener("pointerdown", (event) => {
      last = [event.clientX, event.clientY];
      svg.setPointerCapture?.(event.pointerId);
      svg.classList.add("eulexp-dragging");
    });
    svg.addEventListener("pointermove", (event) => {
      if (!last) return;
      const size = svg.getBoundingClientRect().width || 300;
      view.azimuth -= ((event.clientX - last[0]) / size) * 270;
      view.elevation = Math.max(-89, Math.min(89, view.elevation + ((event.clientY - last[1]) / size) * 270));
      last = [event.clientX, event.clientY];
      redraw();
    });
    const end = () => {
      last = null;
      svg.classList.remove("eulexp-dragging");
    };
    svg.addEventListener("pointerup", end);
    svg.addEventListener("pointercancel", end);
    svg.addEventListener("keydown", (event) => {
      const turns = { ArrowLeft: [5, 0], ArrowRight: [-5, 0], ArrowUp: [0, 5], ArrowDown: [0, -5] };
      const turn = turns[event.key];
      if (!turn) return;
      event.preventDefault();
      view.azimuth += turn[0];
      view.elevation = Math.max(-89, Math.min(89, view.elevation + turn[1]));
      redraw();
    });
  }

  function redraw() {
    const state = model.get("state");
    ensureFigures(state.tracks.length);
    state.tracks.forEach((body, k) => {
      const { svg, caption } = figures[k];
      caption.textContent = body.label;
      svg.setAttribute("aria-label", `${body.label}, seen from azimuth ${Math.round(view.azimuth)}°, ` +
        `elevation ${Math.round(view.elevation)}°; drag or use the arrow keys to turn the view`);
      svg.dataset.azimuth = String(view.azimuth);
      svg.dataset.elevation = String(view.elevation);
      draw(svg, body, config.trails ? config.trails[k] : null, view);
    });
  }

  function update() {
    const state = model.get("state");
    const values = controlValues();
    if (config.kind === "angles") {
      const names = getConvention(values.seq).names;
      angleRows.forEach((row, i) => {
        row.text.textContent = names[i];
        row.range.setAttribute("aria-label", names[i]);
        if (document.activeElement !== row.number) row.number.value = values.angles[i];
        if (document.activeElement !== row.range) row.range.value = values.angles[i];
      });
    } else {
      angleRows[0].range.value = values.frame;
      angleRows[0].number.value = values.frame;
    }
    numbers.replaceChildren();
    state.tracks.forEach((body, k) => {
      const box = element("div", { class: "eulexp-track", "data-track": k }, numbers);
      element("strong", {}, box, body.label);
      element("pre", { class: "eulexp-matrix" }, box, `R =\n${matrixText(body.matrix)}`);
      element("div", { class: "eulexp-recovered" }, box, `read back: ${listing(body.names, body.angles)}`);
      element("div", { class: "eulexp-distance" }, box,
        `distance to gimbal lock: ${formatDistance(body.distance)}`);
      const lock = element("div", { class: body.locked ? "eulexp-lock eulexp-locked" : "eulexp-lock" }, box,
        body.locked
          ? `LOCKED: only ${body.lock.combination} is defined at ${body.names[1]} ${body.lock.pole}°; ` +
              `${body.lock.zeroed} set to 0, ${body.lock.carrier} carries the whole turn`
          : "not locked");
      lock.dataset.locked = String(body.locked);
    });
    if (state.compare && state.compare.length) {
      const box = element("div", { class: "eulexp-compare" }, numbers);
      element("strong", {}, box, "the same rotation in");
      for (const other of state.compare) element("div", {}, box, `${other.label}: ${listing(other.names, other.angles)}`);
    }
    if (state.quaternion) {
      const box = element("div", { class: "eulexp-quaternion" }, numbers);
      const q = state.quaternion.q.map(formatEntry).join(" ");
      element("strong", {}, box, values.flip ? "−q (w, x, y, z)" : "q (w, x, y, z)");
      element("pre", {}, box, `[${q}]\nR(${values.flip ? "−q" : "q"}) =\n${matrixText(state.quaternion.matrix)}`);
    }
    live.textContent = summary(config, values, state);
    redraw();
  }

  model.on("change:state", update);
  update();
  return () => {
    model.off("change:state", update);
    root.stopPlaying?.();
    root.remove();
  };
}

/**
 * A model for a page with no kernel: it holds the settings and the controls and computes the
 * state with rotations.js whenever a control changes.
 */
export function standInModel(settings) {
  const values = { config: settings.config, ...settings.controls };
  values.state = computeState(values.config, values);
  const listeners = new Map();
  let changed = false;
  return {
    get: (name) => values[name],
    set(name, value) {
      values[name] = value;
      changed = true;
    },
    save_changes() {
      if (!changed) return;
      changed = false;
      values.state = computeState(values.config, values);
      for (const callback of listeners.get("change:state") || []) callback();
    },
    on(event, callback) {
      listeners.set(event, [...(listeners.get(event) || []), callback]);
    },
    off(event, callback) {
      listeners.set(event, (listeners.get(event) || []).filter((c) => c !== callback));
    },
  };
}

/** Make a live explorable in `el` from the settings its stored output carries. */
export function mount(el, settings) {
  return render({ model: standInModel(settings), el });
}

export default { render };
