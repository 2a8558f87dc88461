// The two parts placed at a picked configuration (x, y, theta): the fixed part as it is,
// the moving part rotated by theta about its body origin and then translated by (x, y),
// like `cslice render`. Arcs are true SVG arcs.
import {
  addCurve, boxIsEmpty, cyclesPath, emptyBox, formatNumber, placeCurve, svgElement,
} from './data.js';

const FIXED_FILL = '#c8c8c8';
const MOVING_FILL = 'rgba(31, 119, 180, 0.35)';
const MOVING_STROKE = '#1f77b4';

export class PartsView {
  constructor(svg, caption, data) {
    this.svg = svg;
    this.caption = caption;
    this.data = data;
  }

  // Clears the panel and draws the pair at `pose`; `where` says how the slice classifies it.
  show(pose, whereText) {
    const { x, y, theta } = pose;
    const moving = this.data.moving.loops.map((loop) => loop.map((c) => placeCurve(c, x, y, theta)));
    const fixed = this.data.fixed.loops;
    const box = emptyBox();
    for (const loop of [...moving, ...fixed]) for (const c of loop) addCurve(box, c);
    if (boxIsEmpty(box)) return;
    const size = Math.max(box.x1 - box.x0, box.y1 - box.y0) || 1;
    const pad = 0.08 * size;
    this.svg.setAttribute('viewBox',
      `${box.x0 - pad} ${-box.y1 - pad} ${box.x1 - box.x0 + 2 * pad} ${box.y1 - box.y0 + 2 * pad}`);
    const world = svgElement('g', { transform: 'scale(1,-1)' });
    world.appendChild(this.fixedPath(fixed, box, size));
    world.appendChild(svgElement('path', { class: 'moving', d: cyclesPath(moving),
      fill: MOVING_FILL, 'fill-rule': 'evenodd', stroke: MOVING_STROKE, 'stroke-width': 1.5,
      'vector-effect': 'non-scaling-stroke' }));
    world.appendChild(this.referenceMark(x, y, theta, size));
    this.svg.replaceChildren(world);
    this.caption.textContent = `Parts at (x, y, theta) = (${formatNumber(x, 5)}, ` +
      `${formatNumber(y, 5)}, ${formatNumber(theta, 5)}): ${whereText}`;
  }

  // The fixed part's material: inside its loops, or for an enclosure everything outside
  // them (a frame around the picture, minus the loops, even-odd).
  fixedPath(loops, box, size) {
    let d = cyclesPath(loops);
    if (this.data.fixed.enclosure) {
      const m = 2 * size;
      d = `M${box.x0 - m} ${box.y0 - m}H${box.x1 + m}V${box.y1 + m}H${box.x0 - m}Z` + d;
    }
    return svgElement('path', { class: 'fixed', d, fill: FIXED_FILL, 'fill-rule': 'evenodd',
      stroke: '#555555', 'stroke-width': 1, 'vector-effect': 'non-scaling-stroke' });
  }

  // The body origin at (x, y) and a short line along the body's x axis, turned by theta.
  referenceMark(x, y, theta, size) {
    const g = svgElement('g', { class: 'reference' });
    const len = 0.06 * size;
    g.appendChild(svgElement('line', { x1: x, y1: y, x2: x + len * Math.cos(theta),
      y2: y + len * Math.sin(theta), stroke: '#e4002b', 'stroke-width': 2,
      'vector-effect': 'non-scaling-stroke' }));
    g.appendChild(svgElement('circle', { cx: x, cy: y, r: 0.012 * size, fill: '#e4002b' }));
    return g;
  }
}
