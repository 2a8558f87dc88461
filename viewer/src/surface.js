// The contact surface in 3D with three.js: (x, y) across, theta up, the triangles of
// `cslice mesh` coloured per triangle by contact kind or feature pair, a frame with tick labels,
// and the slider's orientation as a translucent plane carrying that slice's contact curves.
import {
  AmbientLight, BufferAttribute, BufferGeometry, CanvasTexture, Color, DirectionalLight,
  DoubleSide, Float32BufferAttribute, Group, LineBasicMaterial, LineSegments, Mesh,
  MeshBasicMaterial, MeshLambertMaterial, PerspectiveCamera, PlaneGeometry, Scene, Sprite,
  SpriteMaterial, Vector3, WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { sampleCurve } from './data.js';

const DEG = Math.PI / 180;
const FRAME_COLOUR = 0x888888;
const PLANE_COLOUR = 0x3060c0;

// Where the camera starts: azimuth and elevation in degrees, distance as a multiple of the
// one that fits the frame. Overridden by the page's #az=, #el=, #zoom= (main.js).
export const DEFAULT_CAMERA = { az: -55, el: 28, zoom: 1 };

export class SurfaceView {
  // `frame`: the (x, y) box shown; theta runs over [-pi, pi] scaled to the box's larger side
  // so the space looks like a cube rather than a thin slab or a tall column.
  constructor(container, data, frame, camera) {
    this.container = container;
    this.data = data;
    this.renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(0xffffff, 1);
    container.appendChild(this.renderer.domElement);
    this.scene = new Scene();
    this.side = Math.max(frame.x1 - frame.x0, frame.y1 - frame.y0) || 1;
    this.frame = frame;
    this.zScale = this.side / (2 * Math.PI);
    // World (x, y, theta) to scene: centred on the frame's middle and theta = 0.
    this.space = new Group();
    this.space.position.set(-(frame.x0 + frame.x1) / 2, -(frame.y0 + frame.y1) / 2, 0);
    this.space.scale.set(1, 1, this.zScale);
    this.scene.add(this.space);
    this.addSurface();
    this.addFrame();
    this.addPlane();
    this.addLights();
    this.setCamera(camera);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.render());
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  // Smooth normals from the shared vertices, then every triangle gets corners of its own so
  // that it can take the one colour of its feature pair (mesh.faceLabels, chosen by
  // cmd_view.cpp): blended vertex colours would smear the boundaries between patches.
  addSurface() {
    const mesh = this.data.mesh;
    const indexed = new BufferGeometry();
    indexed.setAttribute('position', new BufferAttribute(mesh.positions, 3));
    indexed.setIndex(new BufferAttribute(mesh.triangles, 1));
    indexed.computeVertexNormals();
    const geometry = indexed.toNonIndexed();
    indexed.dispose();
    geometry.setAttribute('color', new Float32BufferAttribute(new Float32Array(9 * mesh.triangleCount), 3));
    const material = new MeshLambertMaterial({ vertexColors: true, side: DoubleSide });
    this.surface = new Mesh(geometry, material);
    this.space.add(this.surface);
  }

  // colourOfLabel(index into mesh.labelTable) gives a CSS colour.
  setColours(colourOfLabel) {
    const table = this.data.mesh.labelTable.map((_, i) => new Color(colourOfLabel(i)));
    const colours = this.surface.geometry.getAttribute('color');
    this.data.mesh.faceLabels.forEach((label, t) => {
      const c = table[label];
      for (let k = 0; k < 3; k++) colours.setXYZ(3 * t + k, c.r, c.g, c.b);
    });
    colours.needsUpdate = true;
    this.render();
  }

  // The edges of the box [x0, x1] x [y0, y1] x [-pi, pi], with ticks and labels on three
  // of its edges: x along the front left, y along the front right, theta up the left corner
  // (as the default camera sees the box: from the x1, y0 side).
  addFrame() {
    const { x0, y0, x1, y1 } = this.frame;
    const z0 = -Math.PI, z1 = Math.PI;
    const corners = [];
    for (const [ax, ay, az, bx, by, bz] of [
      [x0, y0, z0, x1, y0, z0], [x1, y0, z0, x1, y1, z0], [x1, y1, z0, x0, y1, z0],
      [x0, y1, z0, x0, y0, z0], [x0, y0, z1, x1, y0, z1], [x1, y0, z1, x1, y1, z1],
      [x1, y1, z1, x0, y1, z1], [x0, y1, z1, x0, y0, z1], [x0, y0, z0, x0, y0, z1],
      [x1, y0, z0, x1, y0, z1], [x1, y1, z0, x1, y1, z1], [x0, y1, z0, x0, y1, z1]]) {
      corners.push(ax, ay, az, bx, by, bz);
    }
    this.space.add(this.lines(corners, FRAME_COLOUR));
    const tick = 0.02 * this.side;
    const h = 0.05 * this.side;  // label height in scene units
    for (const [value, name] of [[-Math.PI, '-\u03c0'], [-Math.PI / 2, '-\u03c0/2'], [0, '0'],
      [Math.PI / 2, '\u03c0/2'], [Math.PI, '\u03c0']]) {
      this.space.add(this.lines([x0, y0, value, x0 - tick, y0 - tick, value], 0x000000));
      this.label(name, [x0 - 3 * tick, y0 - 3 * tick, value], h);
    }
    this.label('\u03b8', [x0 - 3 * tick, y0 - 3 * tick, Math.PI + 0.5], 1.3 * h);
    // Not next to the theta axis's corner, where its -pi label is.
    for (const x of niceTicks(x0, x1)) {
      if (x - x0 > 0.1 * this.side) this.label(tickText(x), [x, y0 - 3 * tick, z0], h);
    }
    for (const y of niceTicks(y0, y1)) this.label(tickText(y), [x1 + 3 * tick, y, z0], h);
    this.label('x', [(x0 + x1) / 2, y0 - 8 * tick, z0], 1.3 * h);
    this.label('y', [x1 + 8 * tick, (y0 + y1) / 2, z0], 1.3 * h);
  }

  lines(coordinates, colour) {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(coordinates, 3));
    return new LineSegments(geometry, new LineBasicMaterial({ color: colour }));
  }

  // Text that always faces the camera, drawn over the surface so it stays readable.
  label(text, [x, y, theta], height) {
    const canvas = document.createElement('canvas');
    const font = 'bold 64px sans-serif';
    const context = canvas.getContext('2d');
    context.font = font;
    canvas.width = Math.ceil(context.measureText(text).width) + 16;
    canvas.height = 80;
    context.font = font;
    context.fillStyle = '#222222';
    context.textAlign = 'center';
    context.textBaseline = 'middle';
    context.fillText(text, canvas.width / 2, canvas.height / 2);
    const sprite = new Sprite(new SpriteMaterial({ map: new CanvasTexture(canvas),
      depthTest: false, transparent: true }));
    sprite.renderOrder = 10;
    sprite.scale.set((height * canvas.width) / canvas.height, height, 1);
    // Sprites go in the scene, not the scaled group, so the group's theta scaling does not
    // stretch them.
    sprite.position.copy(this.toScene(x, y, theta));
    this.scene.add(sprite);
  }

  toScene(x, y, theta) {
    this.space.updateMatrix();
    return new Vector3(x, y, theta).applyMatrix4(this.space.matrix);
  }

  // The slider's orientation: a translucent plane over the frame and, on it, the stored
  // slice's contact curves (arcs sampled: WebGL draws no arcs).
  addPlane() {
    const { x0, y0, x1, y1 } = this.frame;
    this.plane = new Group();
    const quad = new Mesh(new PlaneGeometry(x1 - x0, y1 - y0),
      new MeshBasicMaterial({ color: PLANE_COLOUR, transparent: true, opacity: 0.18,
        side: DoubleSide, depthWrite: false }));
    quad.position.set((x0 + x1) / 2, (y0 + y1) / 2, 0);
    this.plane.add(quad);
    this.plane.add(this.lines([x0, y0, 0, x1, y0, 0, x1, y0, 0, x1, y1, 0, x1, y1, 0, x0, y1, 0,
      x0, y1, 0, x0, y0, 0], PLANE_COLOUR));
    this.curves = null;
    this.space.add(this.plane);
  }

  setTheta(slice) {
    // The plane lives in the scaled group: its z is theta itself.
    this.plane.position.z = slice.theta;
    if (this.curves) {
      this.plane.remove(this.curves);
      this.curves.geometry.dispose();
    }
    const coordinates = [];
    for (const piece of slice.pieces) {
      const points = sampleCurve(piece.slice(3));
      for (let i = 0; i + 1 < points.length; i++) {
        coordinates.push(points[i][0], points[i][1], 0, points[i + 1][0], points[i + 1][1], 0);
      }
    }
    this.curves = this.lines(coordinates, 0x000000);
    this.plane.add(this.curves);
    this.render();
  }

  setPlaneVisible(visible) {
    this.plane.visible = visible;
    this.render();
  }

  addLights() {
    this.scene.add(new AmbientLight(0xffffff, 1.1));
    this.light = new DirectionalLight(0xffffff, 2.2);
  }

  // Camera from azimuth and elevation (degrees) about the frame's centre, theta up.
  setCamera({ az, el, zoom }) {
    const radius = 0.5 * Math.hypot(this.frame.x1 - this.frame.x0, this.frame.y1 - this.frame.y0,
      2 * Math.PI * this.zScale);
    const fov = 35;
    this.camera = new PerspectiveCamera(fov, 1, radius / 100, radius * 100);
    this.camera.up.set(0, 0, 1);
    const distance = (zoom * 1.15 * radius) / Math.sin((fov / 2) * DEG);
    this.camera.position.set(distance * Math.cos(el * DEG) * Math.cos(az * DEG),
      distance * Math.cos(el * DEG) * Math.sin(az * DEG), distance * Math.sin(el * DEG));
    this.camera.lookAt(0, 0, 0);
    // The light rides with the camera, so whatever faces the viewer is lit.
    this.light.position.set(0.3, 0.6, 1);
    this.camera.add(this.light);
    this.scene.add(this.camera);
  }

  resize() {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render() {
    this.renderer.render(this.scene, this.camera);
    this.rendered = (this.rendered || 0) + 1;
  }
}

// Two to five round values inside [lo, hi].
function niceTicks(lo, hi) {
  const span = hi - lo;
  if (!(span > 0)) return [lo];
  const raw = span / 3;
  const power = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw) || raw;
  const ticks = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) ticks.push(v);
  return ticks;
}

function tickText(v) {
  return String(Number(v.toPrecision(6)));
}
