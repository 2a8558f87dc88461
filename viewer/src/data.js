// The data `cslice view` embeds (src/cli/cmd_view.cpp writes it; docs/viewer.md lists the
// fields), decoded, and the plane geometry the views share. A curve is a flat array: a
// segment [x0, y0, x1, y1], an arc [x0, y0, x1, y1, cx, cy, sweep] (sweep signed, radians,
// counterclockwise positive; a full circle has equal ends and sweep +-2pi).

// One colour per contact kind, in ContactKind order: the colours of `cslice slice --svg`.
export const KIND_COLOURS = [
  '#1f77b4', '#ff7f0e', '#2ca02c', '#9467bd', '#d62728', '#8c564b', '#e377c2',
];
export const UNLABELLED_COLOUR = '#777777';

function base64Bytes(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

// The mesh arrays are little-endian typed arrays in base64 (cmd_view.cpp, mesh_json).
function decodeMesh(mesh) {
  const Index = mesh.indexType === 'uint32' ? Uint32Array : Uint16Array;
  const decoded = {
    ...mesh,
    positions: new Float32Array(base64Bytes(mesh.positions).buffer),
    triangles: new Index(base64Bytes(mesh.triangles).buffer),
    faceLabels: new Uint16Array(base64Bytes(mesh.faceLabels).buffer),
  };
  if (decoded.positions.length !== 3 * mesh.vertexCount ||
      decoded.triangles.length !== 3 * mesh.triangleCount ||
      decoded.faceLabels.length !== mesh.triangleCount) {
    throw new Error('the embedded mesh arrays do not match their counts');
  }
  return decoded;
}

// The contact kind of a feature pair, as an index into data.kinds ("vertex_segment", ...:
// moving feature kind first), or -1 for the label {-1, -1} of a cone apex.
function kindOfPair(data, moving, fixed) {
  const m = data.moving.features[moving];
  const f = data.fixed.features[fixed];
  if (!m || !f) return -1;
  return data.kinds.indexOf(`${m[0]}_${f[0]}`);
}

export function loadData() {
  const element = document.getElementById('cslice-data');
  const data = JSON.parse(element.textContent);
  if (data.format !== 'cslice-view' || data.version !== 1) {
    throw new Error(`unexpected embedded data: ${data.format} version ${data.version}`);
  }
  data.mesh = decodeMesh(data.mesh);
  data.mesh.labelKinds = data.mesh.labelTable.map(([m, f]) => kindOfPair(data, m, f));
  return data;
}

// "moving vertex 3 of loop 0 on fixed segment 1 of loop 2".
export function describePair(data, moving, fixed) {
  const m = data.moving.features[moving];
  const f = data.fixed.features[fixed];
  return `moving ${m ? m[1] : moving} on fixed ${f ? f[1] : fixed}`;
}

// A colour per feature pair, spread round the hue circle by the golden ratio so that
// neighbouring labels differ.
export function labelColour(index) {
  const hue = (index * 0.618033988749895) % 1;
  return `hsl(${Math.round(hue * 360)}, 65%, 50%)`;
}

// ---- Curves ------------------------------------------------------------------------------

export const isArc = (c) => c.length >= 7;

export function arcOf(c) {
  const [x0, y0, , , cx, cy, sweep] = c;
  return { cx, cy, r: Math.hypot(x0 - cx, y0 - cy), a0: Math.atan2(y0 - cy, x0 - cx), sweep };
}

const isFullCircle = (c) => isArc(c) && Math.abs(c[6]) >= 2 * Math.PI - 1e-9;

// Whether angle a lies on the arc that starts at a0 and turns by sweep.
function onArc(a, a0, sweep) {
  const turn = 2 * Math.PI;
  let d = sweep >= 0 ? a - a0 : a0 - a;
  d = ((d % turn) + turn) % turn;
  return d <= Math.abs(sweep);
}

export function emptyBox() {
  return { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity };
}

export function addPoint(box, x, y) {
  box.x0 = Math.min(box.x0, x);
  box.y0 = Math.min(box.y0, y);
  box.x1 = Math.max(box.x1, x);
  box.y1 = Math.max(box.y1, y);
}

// The curve's bounding box added to `box`: its ends, and for an arc the axis-extreme points
// it passes.
export function addCurve(box, c) {
  addPoint(box, c[0], c[1]);
  addPoint(box, c[2], c[3]);
  if (!isArc(c)) return;
  const { cx, cy, r, a0, sweep } = arcOf(c);
  for (let k = 0; k < 4; k++) {
    const a = (k * Math.PI) / 2;
    if (onArc(a, a0, sweep)) addPoint(box, cx + r * Math.cos(a), cy + r * Math.sin(a));
  }
}

export const boxIsEmpty = (b) => !(b.x0 <= b.x1 && b.y0 <= b.y1);

// Points along the curve, at most `step` radians apart on arcs: for WebGL, which has no arcs.
export function sampleCurve(c, step = 0.05) {
  if (!isArc(c)) return [[c[0], c[1]], [c[2], c[3]]];
  const { cx, cy, r, a0, sweep } = arcOf(c);
  const n = Math.max(2, Math.ceil(Math.abs(sweep) / step));
  const points = [];
  for (let i = 0; i <= n; i++) {
    const a = a0 + (sweep * i) / n;
    points.push([cx + r * Math.cos(a), cy + r * Math.sin(a)]);
  }
  return points;
}

function distanceToSegment(px, py, x0, y0, x1, y1) {
  const dx = x1 - x0, dy = y1 - y0;
  const len2 = dx * dx + dy * dy;
  const t = len2 > 0 ? Math.max(0, Math.min(1, ((px - x0) * dx + (py - y0) * dy) / len2)) : 0;
  return Math.hypot(px - (x0 + t * dx), py - (y0 + t * dy));
}

export function distanceToCurve(px, py, c) {
  if (!isArc(c)) return distanceToSegment(px, py, c[0], c[1], c[2], c[3]);
  const { cx, cy, r, a0, sweep } = arcOf(c);
  if (onArc(Math.atan2(py - cy, px - cx), a0, sweep)) return Math.abs(Math.hypot(px - cx, py - cy) - r);
  return Math.min(Math.hypot(px - c[0], py - c[1]), Math.hypot(px - c[2], py - c[3]));
}

// ---- SVG paths in world coordinates ------------------------------------------------------
// The views draw inside a group flipped by scale(1, -1), so paths use world coordinates with
// y up, and SVG's sweep flag 1 (increasing angle in user space) is a counterclockwise arc.

const fmt = (v) => String(v);

function arcCommand(r, large, ccw, x, y) {
  return `A${fmt(r)} ${fmt(r)} 0 ${large ? 1 : 0} ${ccw ? 1 : 0} ${fmt(x)} ${fmt(y)}`;
}

// Commands that trace `c` from its start, where the pen already is: true SVG arcs. An arc
// whose ends coincide draws nothing in SVG, so a full circle goes as two halves.
export function curveCommands(c) {
  if (!isArc(c)) return `L${fmt(c[2])} ${fmt(c[3])}`;
  const { cx, cy, r, a0, sweep } = arcOf(c);
  const ccw = sweep > 0;
  if (isFullCircle(c)) {
    const mid = a0 + sweep / 2;
    return arcCommand(r, false, ccw, cx + r * Math.cos(mid), cy + r * Math.sin(mid)) +
      arcCommand(r, false, ccw, c[2], c[3]);
  }
  return arcCommand(r, Math.abs(sweep) > Math.PI, ccw, c[2], c[3]);
}

export function curvePath(c) {
  return `M${fmt(c[0])} ${fmt(c[1])}${curveCommands(c)}`;
}

// One closed subpath per cycle; a gap between consecutive curves (rounding of the embedded
// numbers) is bridged by a line so the fill stays closed.
export function cyclesPath(cycles) {
  let d = '';
  for (const cycle of cycles) {
    if (cycle.length === 0) continue;
    let [px, py] = cycle[0];
    d += `M${fmt(px)} ${fmt(py)}`;
    for (const c of cycle) {
      if (c[0] !== px || c[1] !== py) d += `L${fmt(c[0])} ${fmt(c[1])}`;
      d += curveCommands(c);
      [px, py] = [c[2], c[3]];
    }
    d += 'Z';
  }
  return d;
}

// The curve rotated by theta about the origin, then translated by (x, y): how a moving part
// is placed at configuration (x, y, theta).
export function placeCurve(c, x, y, theta) {
  const cos = Math.cos(theta), sin = Math.sin(theta);
  const out = [];
  for (let i = 0; i + 1 < Math.min(c.length, 6); i += 2) {
    out.push(cos * c[i] - sin * c[i + 1] + x, sin * c[i] + cos * c[i + 1] + y);
  }
  if (isArc(c)) out.push(c[6]);
  return out;
}

export const SVG_NS = 'http://www.w3.org/2000/svg';

export function svgElement(name, attributes = {}) {
  const element = document.createElementNS(SVG_NS, name);
  for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, String(value));
  return element;
}

export function formatNumber(v, digits = 4) {
  if (!Number.isFinite(v)) return String(v);
  return Number(v.toPrecision(digits)).toString();
}
