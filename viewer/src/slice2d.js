// The 2D slice at the slider's orientation, drawn like `cslice slice --svg`: blocked space
// grey, free space white, realizable contact curves coloured on top, exact SVG arcs. Wheel
// zooms, dragging pans, double-click resets the view, and a click picks a configuration.
import {
  KIND_COLOURS, UNLABELLED_COLOUR, addCurve, boxIsEmpty, curvePath, cyclesPath, describePair,
  distanceToCurve, emptyBox, formatNumber, labelColour, svgElement,
} from './data.js';

const BLOCKED_FILL = '#c8c8c8';
const FREE_FILL = '#ffffff';
const CLICK_SLOP_PX = 4;  // a press that moves further is a pan, not a click

export class SliceView {
  // `frame`: the world box of every slice together. Each slice is shown fitted to its own
  // contact curves while `fit` is on (the slices of a part that turns can lie far apart);
  // zooming or panning turns it off, so the view then stays put as the slider moves, and a
  // double-click fits again. onPick(x, y) is called on a click; onFit(fit) when fit changes.
  constructor(svg, caption, data, frame, colourOf, onPick, onFit) {
    this.svg = svg;
    this.caption = caption;
    this.data = data;
    this.frame = frame;
    this.colourOf = colourOf;
    this.onPick = onPick;
    this.onFit = onFit;
    this.fit = true;
    const pad = Math.max(frame.x1 - frame.x0, frame.y1 - frame.y0);
    // Far beyond any sensible zoom-out: blocked and unbounded free space are rectangles
    // this large.
    this.far = { x: frame.x0 - 50 * pad, y: frame.y0 - 50 * pad, w: frame.x1 - frame.x0 + 100 * pad,
      h: frame.y1 - frame.y0 + 100 * pad };
    this.world = svgElement('g', { transform: 'scale(1,-1)' });
    svg.appendChild(this.world);
    this.mark = null;
    this.view = this.fitted(frame);
    this.listen();
  }

  // The root's view box showing `box` with a 6% margin (the root's y is the world's negated).
  fitted(box) {
    const size = Math.max(box.x1 - box.x0, box.y1 - box.y0) || this.data.pair.size || 1;
    const pad = 0.06 * size;
    const cx = (box.x0 + box.x1) / 2, cy = (box.y0 + box.y1) / 2;
    const w = Math.max(box.x1 - box.x0, 0.05 * size) + 2 * pad;
    const h = Math.max(box.y1 - box.y0, 0.05 * size) + 2 * pad;
    return { u: cx - w / 2, v: -cy - h / 2, w, h };
  }

  sliceBox(slice) {
    const box = emptyBox();
    for (const piece of slice.pieces) addCurve(box, piece.slice(3));
    for (const d of slice.degenerate) addCurve(box, d.curve);
    if (this.markAt) addCurve(box, [...this.markAt, ...this.markAt]);
    return boxIsEmpty(box) ? this.frame : box;
  }

  setFit(fit) {
    this.fit = fit;
    if (fit && this.slice) this.view = this.fitted(this.sliceBox(this.slice));
    this.applyView();
    this.onFit(fit);
  }

  resetView() {
    this.setFit(true);
  }

  applyView() {
    const { u, v, w, h } = this.view;
    this.svg.setAttribute('viewBox', `${u} ${v} ${w} ${h}`);
    this.updateMark();
  }

  // World units per screen pixel, for sizes that should stay the same on screen.
  worldPerPixel() {
    const ctm = this.svg.getScreenCTM();
    return ctm && ctm.a > 0 ? 1 / ctm.a : this.view.w / 400;
  }

  clientToWorld(clientX, clientY) {
    const p = new DOMPoint(clientX, clientY).matrixTransform(this.world.getScreenCTM().inverse());
    return [p.x, p.y];
  }

  worldToClient(x, y) {
    const p = new DOMPoint(x, y).matrixTransform(this.world.getScreenCTM());
    return [p.x, p.y];
  }

  listen() {
    let press = null;
    this.svg.addEventListener('pointerdown', (e) => {
      press = { x: e.clientX, y: e.clientY, view: { ...this.view }, moved: false };
      this.svg.setPointerCapture(e.pointerId);
    });
    this.svg.addEventListener('pointermove', (e) => {
      if (!press) return;
      const dx = e.clientX - press.x, dy = e.clientY - press.y;
      if (Math.hypot(dx, dy) > CLICK_SLOP_PX) press.moved = true;
      if (!press.moved) return;
      const k = this.worldPerPixel();
      this.view = { ...press.view, u: press.view.u - dx * k, v: press.view.v - dy * k };
      if (this.fit) this.setFit(false);
      this.applyView();
    });
    this.svg.addEventListener('pointerup', (e) => {
      if (press && !press.moved) this.onPick(...this.clientToWorld(e.clientX, e.clientY));
      press = null;
    });
    this.svg.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.zoomAt(e.clientX, e.clientY, Math.exp(e.deltaY * 0.0015));
    }, { passive: false });
    this.svg.addEventListener('dblclick', () => this.resetView());
  }

  zoomAt(clientX, clientY, factor) {
    const [x, y] = this.clientToWorld(clientX, clientY);
    const { u, v, w, h } = this.view;
    const pu = x, pv = -y;  // the root's user space is the world with y negated
    this.view = { u: pu - (pu - u) * factor, v: pv - (pv - v) * factor, w: w * factor, h: h * factor };
    if (this.fit) this.setFit(false);
    this.applyView();
  }

  // Draws slice `index` of the data: regions, contact curves, degenerate contacts.
  show(index) {
    this.index = index;
    this.slice = this.data.slices[index];
    this.world.replaceChildren();
    this.regions = this.drawRegions(this.slice);
    this.drawDegenerateCurves(this.slice);
    this.pieces = this.drawPieces(this.slice);
    this.mark = null;
    if (this.fit) this.view = this.fitted(this.sliceBox(this.slice));
    this.applyView();
    this.drawDegeneratePoints(this.slice);
    this.describe();
  }

  rect(fill) {
    const { x, y, w, h } = this.far;
    return svgElement('rect', { x, y, width: w, height: h, fill });
  }

  // Everything starts blocked. An unbounded component frees everything but the blocked
  // islands its cycles enclose; bounded components (even-odd: outer cycle minus holes) come
  // last, since they can lie inside such an island. Returns the paths, for locating points.
  drawRegions(slice) {
    const layer = svgElement('g', { class: 'regions' });
    layer.appendChild(this.rect(BLOCKED_FILL));
    const regions = [];
    slice.components.forEach((c, i) => {
      if (c.bounded) return;
      layer.appendChild(this.rect(FREE_FILL));
      const islands = svgElement('path', { d: cyclesPath(c.cycles), fill: BLOCKED_FILL,
        'fill-rule': 'evenodd' });
      layer.appendChild(islands);
      regions.push({ component: i, path: islands, inside: false });
    });
    slice.components.forEach((c, i) => {
      if (!c.bounded) return;
      const free = svgElement('path', { d: cyclesPath(c.cycles), fill: FREE_FILL,
        'fill-rule': 'evenodd' });
      layer.appendChild(free);
      regions.push({ component: i, path: free, inside: true });
    });
    this.world.appendChild(layer);
    return regions;
  }

  drawPieces(slice) {
    const layer = svgElement('g', { class: 'pieces', fill: 'none', 'stroke-width': 2.2,
      'stroke-linecap': 'round', 'vector-effect': 'non-scaling-stroke' });
    for (const piece of slice.pieces) {
      const [kind, moving, fixed] = piece;
      layer.appendChild(svgElement('path', { d: curvePath(piece.slice(3)),
        stroke: this.colourOf(kind, moving, fixed), 'vector-effect': 'non-scaling-stroke' }));
    }
    this.world.appendChild(layer);
    return slice.pieces;
  }

  // Free space shrunk to a curve (a sliding fit): thick and black under the coloured piece.
  drawDegenerateCurves(slice) {
    for (const d of slice.degenerate) {
      if (d.point) continue;
      this.world.appendChild(svgElement('path', { d: curvePath(d.curve), fill: 'none',
        stroke: '#000000', 'stroke-width': 6, 'vector-effect': 'non-scaling-stroke' }));
    }
  }

  // Free space shrunk to a point (a perfect fit): a black dot, sized in pixels.
  drawDegeneratePoints(slice) {
    const r = 4 * this.worldPerPixel();
    for (const d of slice.degenerate) {
      if (!d.point) continue;
      this.world.appendChild(svgElement('circle', { cx: d.curve[0], cy: d.curve[1], r,
        fill: '#000000' }));
    }
  }

  // Free or blocked from the stored slice's regions (the browser's own exact fill test on
  // the drawn paths); contact when within the pair's contact tolerance of a realizable
  // contact curve, the accuracy the pair asks for (include/cslice/tolerance.hpp).
  locate(x, y) {
    const point = new DOMPoint(x, y);
    let component = -1;
    for (const r of this.regions) {
      if (r.path.isPointInFill(point) === r.inside) component = r.component;
    }
    let nearest = null;
    for (const piece of this.pieces) {
      const d = distanceToCurve(x, y, piece.slice(3));
      if (!nearest || d < nearest.distance) nearest = { distance: d, piece };
    }
    const contact = nearest && nearest.distance <= this.data.pair.contactTolerance;
    const state = contact ? 'contact' : component >= 0 ? 'free' : 'blocked';
    return { state, component, nearest };
  }

  // Marks (x, y) with a dot and returns its classification.
  pick(x, y) {
    this.markAt = [x, y];
    if (!this.mark) {
      this.mark = svgElement('circle', { class: 'mark', fill: '#e4002b', stroke: '#ffffff',
        'stroke-width': 1.5, 'vector-effect': 'non-scaling-stroke' });
      this.world.appendChild(this.mark);
    }
    this.updateMark();
    return this.locate(x, y);
  }

  updateMark() {
    if (!this.mark) return;
    this.mark.setAttribute('cx', this.markAt[0]);
    this.mark.setAttribute('cy', this.markAt[1]);
    this.mark.setAttribute('r', 5 * this.worldPerPixel());
  }

  describe() {
    const s = this.slice;
    const bounded = s.components.filter((c) => c.bounded).length;
    const free = `${s.components.length} free component${s.components.length === 1 ? '' : 's'}` +
      (s.components.length > 0 ? ` (${bounded} bounded)` : '');
    this.caption.textContent = `Slice at theta = ${formatNumber(s.theta, 6)}: ${free}, ` +
      `${s.pieces.length} contact curve pieces. Click to place the parts; wheel zooms, drag ` +
      'pans, double-click fits the slice.';
  }
}

// How a picked configuration reads: "free (slice component 1, 3D component 0)", with the
// nearest contact curve and its feature pair.
export function describeLocation(data, slice, where) {
  const units = data.pair.units;
  let text = where.state;
  if (where.state === 'free') {
    const c = slice.components[where.component];
    text += ` (slice component ${where.component}` +
      (c.component3d >= 0 ? `, 3D component ${c.component3d})` : ')');
  }
  if (where.nearest) {
    const [, moving, fixed] = where.nearest.piece;
    text += `; nearest contact curve ${formatNumber(where.nearest.distance, 3)} ${units} away: ` +
      describePair(data, moving, fixed);
  }
  return text;
}

export function kindColour(kind) {
  return KIND_COLOURS[kind] ?? UNLABELLED_COLOUR;
}

export { labelColour };
