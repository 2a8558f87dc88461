// The page of `cslice view`: wires the embedded data to the 3D surface, the 2D slice and
// the placed parts, with a theta slider over the stored slices. The URL's hash sets the
// initial state, so screenshots are reproducible (docs/viewer.md):
//   #theta=0.3&az=-55&el=28&zoom=1&colour=kind|label&plane=0|1&at=x,y&layout=3d
import {
  KIND_COLOURS, UNLABELLED_COLOUR, addCurve, addPoint, boxIsEmpty, emptyBox, formatNumber,
  labelColour, loadData,
} from './data.js';
import { PartsView } from './parts2d.js';
import { SliceView, describeLocation } from './slice2d.js';
import { DEFAULT_CAMERA, SurfaceView } from './surface.js';

const $ = (id) => document.getElementById(id);

function hashNumber(params, name, fallback) {
  const v = Number.parseFloat(params.get(name));
  return Number.isFinite(v) ? v : fallback;
}

// The (x, y) box every view shows: every contact curve of every slice and every vertex of
// the surface, so the framing stays put while the slider moves.
function frameOf(data) {
  const box = emptyBox();
  for (const slice of data.slices) {
    for (const piece of slice.pieces) addCurve(box, piece.slice(3));
    for (const d of slice.degenerate) addCurve(box, d.curve);
  }
  const p = data.mesh.positions;
  for (let i = 0; i < p.length; i += 3) addPoint(box, p[i], p[i + 1]);
  if (boxIsEmpty(box)) for (const loop of data.fixed.loops) for (const c of loop) addCurve(box, c);
  if (boxIsEmpty(box)) addPoint(box, 0, 0);
  if (box.x1 - box.x0 === 0 && box.y1 - box.y0 === 0) {
    const r = data.pair.size || 1;
    return { x0: box.x0 - r, y0: box.y0 - r, x1: box.x1 + r, y1: box.y1 + r };
  }
  return box;
}

// The stored slice nearest theta, the turn wrapping at +-pi.
function nearestSlice(data, theta) {
  let best = 0, bestDistance = Infinity;
  data.slices.forEach((s, i) => {
    const d = Math.abs(Math.atan2(Math.sin(s.theta - theta), Math.cos(s.theta - theta)));
    if (d < bestDistance) [best, bestDistance] = [i, d];
  });
  return best;
}

// Colours by contact kind or by feature pair, the same in 2D and 3D.
class Colours {
  constructor(data) {
    this.data = data;
    this.mode = 'kind';
    this.labelIndex = new Map(data.mesh.labelTable.map(([m, f], i) => [`${m},${f}`, i]));
  }

  ofLabel(i) {
    if (this.mode === 'label') return labelColour(i);
    return KIND_COLOURS[this.data.mesh.labelKinds[i]] ?? UNLABELLED_COLOUR;
  }

  ofPiece(kind, moving, fixed) {
    if (this.mode === 'kind') return KIND_COLOURS[kind] ?? UNLABELLED_COLOUR;
    const key = `${moving},${fixed}`;
    // A pair on no stored triangle still gets its own colour, past the mesh's table.
    if (!this.labelIndex.has(key)) this.labelIndex.set(key, this.labelIndex.size);
    return labelColour(this.labelIndex.get(key));
  }

  legend() {
    if (this.mode === 'label') {
      return `<div>one colour per feature pair (${this.data.mesh.labelTable.length} on the ` +
        'surface)</div>';
    }
    const present = new Set(this.data.mesh.labelKinds);
    for (const s of this.data.slices) for (const p of s.pieces) present.add(p[0]);
    return this.data.kinds.filter((_, k) => present.has(k)).map((name) => {
      const k = this.data.kinds.indexOf(name);
      return `<div><span style="background:${KIND_COLOURS[k]}"></span>${name.replace('_', ' on ')}</div>`;
    }).join('');
  }
}

class Viewer {
  constructor(data, params) {
    this.data = data;
    this.colours = new Colours(data);
    this.colours.mode = params.get('colour') === 'label' ? 'label' : 'kind';
    this.picked = null;
    const frame = frameOf(data);
    this.slice = new SliceView($('slice-svg'), $('slice-caption'), data, frame,
      (k, m, f) => this.colours.ofPiece(k, m, f), (x, y) => this.pick(x, y),
      (fit) => { $('fit-slice').checked = fit; });
    this.parts = new PartsView($('parts-svg'), $('parts-caption'), data);
    this.surface = this.makeSurface(frame, params);
    this.describe();
  }

  makeSurface(frame, params) {
    const camera = { az: hashNumber(params, 'az', DEFAULT_CAMERA.az),
      el: hashNumber(params, 'el', DEFAULT_CAMERA.el),
      zoom: hashNumber(params, 'zoom', DEFAULT_CAMERA.zoom) };
    try {
      return new SurfaceView($('surface'), this.data, frame, camera);
    } catch (error) {
      // Without WebGL the 2D views still work; the failure is reported, not hidden.
      $('surface-caption').textContent = `The 3D view needs WebGL: ${error.message}`;
      console.error('cslice view: no 3D view:', error);
      return null;
    }
  }

  describe() {
    const d = this.data;
    const name = d.pair.name || 'pair';
    $('title').textContent = `cslice view: ${name}`;
    $('summary').textContent = `${d.slices.length} slices, ${d.criticals.length} critical ` +
      `orientations, ${d.components3d} 3D free component${d.components3d === 1 ? '' : 's'}, ` +
      `contact surface of ${d.mesh.triangleCount} triangles. Units: ${d.pair.units}.`;
  }

  // The 3D view's caption names the slice the plane shows (the README's figures have no
  // other text).
  describeSurface(slice) {
    if (!this.surface) return;
    const name = this.data.pair.name || 'pair';
    const plane = $('show-plane').checked
      ? `; the plane is the slice at \u03b8 = ${formatNumber(slice.theta, 4)}` : '';
    const hint = document.body.classList.contains('only3d') ? '' : '. Drag to turn, wheel to zoom.';
    $('surface-caption').textContent = `${name}: the contact surface in (x, y, \u03b8), ` +
      `\u03b8 up${plane}${hint}`;
  }

  setColourMode(mode) {
    this.colours.mode = mode;
    $('legend').innerHTML = this.colours.legend();
    if (this.surface) this.surface.setColours((i) => this.colours.ofLabel(i));
    this.showSlice(this.index);
  }

  showSlice(index) {
    this.index = index;
    const s = this.data.slices[index];
    $('theta').value = String(index);
    $('theta-text').textContent = `= ${formatNumber(s.theta, 6)} rad ` +
      `(${formatNumber((s.theta * 180) / Math.PI, 4)}\u00b0), ${s.kind} slice of interval ` +
      `${s.interval}, ${index + 1} of ${this.data.slices.length}`;
    this.slice.show(index);
    if (this.surface) this.surface.setTheta(s);
    this.describeSurface(s);
    if (this.picked) this.pick(...this.picked);
  }

  // Places the parts at (x, y) and the shown slice's theta, classified by that slice.
  pick(x, y) {
    this.picked = [x, y];
    const s = this.data.slices[this.index];
    const where = this.slice.pick(x, y);
    this.parts.show({ x, y, theta: s.theta }, describeLocation(this.data, s, where));
    this.lastPick = where;
    return where;
  }
}

function start() {
  const params = new URLSearchParams(window.location.hash.slice(1));
  if (params.get('layout') === '3d') document.body.classList.add('only3d');
  const data = loadData();
  const viewer = new Viewer(data, params);
  const slider = $('theta');
  slider.max = String(data.slices.length - 1);
  slider.addEventListener('input', () => viewer.showSlice(Number(slider.value)));
  $('colour').value = viewer.colours.mode;
  $('colour').addEventListener('change', (e) => viewer.setColourMode(e.target.value));
  $('show-plane').checked = params.get('plane') !== '0';
  $('show-plane').addEventListener('change', (e) => {
    viewer.surface?.setPlaneVisible(e.target.checked);
    viewer.describeSurface(data.slices[viewer.index]);
  });
  viewer.surface?.setPlaneVisible($('show-plane').checked);
  $('fit-slice').addEventListener('change', (e) => viewer.slice.setFit(e.target.checked));
  viewer.index = nearestSlice(data, hashNumber(params, 'theta', 0));
  viewer.setColourMode(viewer.colours.mode);
  const at = (params.get('at') || '').split(',').map(Number.parseFloat);
  if (at.length === 2 && at.every(Number.isFinite)) viewer.pick(at[0], at[1]);
  // For scripts (tests, figures): the viewer, and a flag that the first frame is drawn.
  window.csliceViewer = viewer;
  document.body.dataset.ready = '1';
}

try {
  start();
} catch (error) {
  $('error').style.display = 'inline';
  $('error').textContent = `cslice view failed: ${error.message}`;
  throw error;
}
