// Browser test of `cslice view` (docs/viewer.md), run by ctest: for each example, computes
// its space, writes the page, opens it from file:// in headless Chromium (viewer/tools/
// chromium.cjs) and checks, as a person would see it, that
//   - nothing fails: no page error, no console error, no request leaves the file;
//   - the WebGL view draws the surface (a screenshot with many colours, not blank);
//   - moving the slider redraws the 2D slice and moves the theta plane in 3D;
//   - clicking the slice draws the two parts placed there, and the page's free/blocked
//     answer agrees with `cslice classify` (the direct, exact test) at the clicked points;
//   - switching the colouring recolours the surface.
// Also: bad input to `cslice view` is exit status 2 with no page written.
// Usage: node view_test.cjs --cslice PATH --source DIR --work DIR [--example NAME]...
'use strict';

const assert = require('assert');
const { spawnSync } = require('child_process');
const fs = require('fs');
const path = require('path');

function parseArgs(argv) {
  const args = { examples: [] };
  for (let i = 0; i < argv.length; i += 2) {
    const [key, value] = [argv[i], argv[i + 1]];
    if (key === '--example') args.examples.push(value);
    else args[key.replace(/^--/, '')] = value;
  }
  for (const key of ['cslice', 'source', 'work']) {
    if (!args[key]) throw new Error(`missing --${key}`);
  }
  if (args.examples.length === 0) args.examples = ['cam', 'knee', 'fixture', 'fastener'];
  return args;
}

const args = parseArgs(process.argv.slice(2));
const { launch } = require(path.join(args.source, 'viewer/tools/chromium.cjs'));

function run(command, argv, input) {
  return spawnSync(command, argv, { encoding: 'utf8', input, maxBuffer: 64 << 20 });
}

let passed = 0, failed = 0;
async function check(name, body) {
  const start = Date.now();
  try {
    await body();
    passed++;
    console.log(`ok    ${name} (${Date.now() - start} ms)`);
  } catch (error) {
    failed++;
    console.log(`FAIL  ${name}: ${error.stack || error}`);
  }
}

// ---- Command line ----------------------------------------------------------------------

function writeView(example) {
  const space = path.join(args.work, `${example}-space.json`);
  const html = path.join(args.work, `${example}.html`);
  const pair = path.join(args.source, 'examples', `${example}.json`);
  let r = run(args.cslice, ['compute', pair, '-o', space]);
  assert.strictEqual(r.status, 0, `cslice compute: ${r.stderr}`);
  r = run(args.cslice, ['view', space, '-o', html]);
  assert.strictEqual(r.status, 0, `cslice view: ${r.stderr}`);
  const size = fs.statSync(html).size;
  assert(size < 5e6, `${html} is ${size} bytes`);
  return { html, pair, size };
}

function checkBadInput() {
  const out = path.join(args.work, 'bad.html');
  fs.rmSync(out, { force: true });
  const cases = [
    [path.join(args.work, 'no-such-space.json')],
    [path.join(args.source, 'examples', 'cam.json')],  // a pair file, not a space file
  ];
  for (const input of cases) {
    const r = run(args.cslice, ['view', ...input, '-o', out]);
    assert.strictEqual(r.status, 2, `exit status for ${input}: ${r.status} (${r.stderr})`);
    assert(r.stderr.startsWith('cslice: '), `no message for ${input}`);
    assert(!fs.existsSync(out), `a page was written for ${input}`);
  }
}

// ---- The page --------------------------------------------------------------------------

// Opens the page, recording every error and every request for something else than the page.
async function openPage(context, html) {
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console error: ${m.text()}`);
  });
  const url = `file://${html}`;
  page.on('request', (r) => {
    if (r.url() !== url && !r.url().startsWith('data:')) problems.push(`request: ${r.url()}`);
  });
  await page.goto(url);
  await page.waitForFunction(() => document.body.dataset.ready === '1', null, { timeout: 30000 });
  return { page, problems };
}

// Distinct colours and the share of non-white pixels of a PNG, decoded by the browser itself.
async function pixelStats(context, png) {
  const probe = await context.newPage();
  try {
    return await probe.evaluate(async (base64) => {
      const image = new Image();
      image.src = `data:image/png;base64,${base64}`;
      await image.decode();
      const canvas = document.createElement('canvas');
      [canvas.width, canvas.height] = [image.width, image.height];
      const g = canvas.getContext('2d');
      g.drawImage(image, 0, 0);
      const { data } = g.getImageData(0, 0, image.width, image.height);
      const colours = new Set();
      let inked = 0;
      for (let i = 0; i < data.length; i += 4) {
        colours.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
        if (data[i] < 235 || data[i + 1] < 235 || data[i + 2] < 235) inked++;
      }
      return { colours: colours.size, inked: inked / (data.length / 4) };
    }, png.toString('base64'));
  } finally {
    await probe.close();
  }
}

const surfaceShot = (page) => page.locator('#surface canvas').screenshot();
const sliceContent = (page) => page.locator('#slice-svg').innerHTML();

async function checkSurface(context, page) {
  const stats = await pixelStats(context, await surfaceShot(page));
  assert(stats.colours > 200, `the 3D view has only ${stats.colours} colours`);
  assert(stats.inked > 0.03, `the 3D view is ${(100 * (1 - stats.inked)).toFixed(1)}% blank`);
}

// Moves the slider with the keyboard, a few slices on.
async function checkSlider(page) {
  const before = { slice: await sliceContent(page), text: await page.locator('#theta-text').innerText(),
    surface: await surfaceShot(page) };
  await page.locator('#theta').focus();
  for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowRight');
  const after = { slice: await sliceContent(page), text: await page.locator('#theta-text').innerText(),
    surface: await surfaceShot(page) };
  assert.notStrictEqual(after.text, before.text, 'the theta readout did not change');
  assert.notStrictEqual(after.slice, before.slice, 'the 2D slice did not change');
  assert(!after.surface.equals(before.surface), 'the 3D view did not change');
}

// Clicks at world point (x, y) of the shown slice; returns the page's answer and pose.
async function clickAt(page, x, y) {
  const [cx, cy] = await page.evaluate(([px, py]) => window.csliceViewer.slice.worldToClient(px, py), [x, y]);
  await page.mouse.click(cx, cy);
  return page.evaluate(() => {
    const v = window.csliceViewer;
    return { state: v.lastPick.state, distance: v.lastPick.nearest?.distance ?? Infinity,
      pose: [...v.picked, v.data.slices[v.index].theta] };
  });
}

// The free components' interior samples that are on screen, then a grid over the slice's
// view: the parts must be drawn at a free point, and each clicked point's answer must match
// `cslice classify`, except within a band around contact where the page's rounded numbers
// (7 digits) may put it on the other side.
async function checkClicks(page, pair) {
  const info = await page.evaluate(() => {
    const v = window.csliceViewer;
    const r = v.slice.svg.getBoundingClientRect();
    const onScreen = ([x, y]) => {
      const [cx, cy] = v.slice.worldToClient(x, y);
      return cx > r.left && cx < r.right && cy > r.top && cy < r.bottom;
    };
    const samples = v.data.slices[v.index].components.map((c) => c.sample).filter(onScreen);
    return { samples, size: v.data.pair.size, box: [r.x, r.y, r.width, r.height] };
  });
  const picks = [];
  for (const sample of info.samples) {
    picks.push(await clickAt(page, ...sample));
    assert.strictEqual(picks[picks.length - 1].state, 'free', `the sample ${sample} is not free`);
  }
  const [bx, by, bw, bh] = info.box;
  for (let i = 1; i <= 5; i++) {
    for (let j = 1; j <= 5; j++) {
      const world = await page.evaluate(([cx, cy]) => window.csliceViewer.slice.clientToWorld(cx, cy),
        [bx + (bw * i) / 6, by + (bh * j) / 6]);
      picks.push(await clickAt(page, ...world));
    }
  }
  const free = picks.find((p) => p.state === 'free');
  assert(free, 'no clicked point is free');
  await clickAt(page, free.pose[0], free.pose[1]);
  await checkPlacedParts(page);
  const clear = picks.filter((p) => p.distance > 1e-4 * info.size);
  const input = clear.map((p) => p.pose.join(' ')).join('\n');
  const r = run(args.cslice, ['classify', pair], input);
  assert.strictEqual(r.status, 0, `cslice classify: ${r.stderr}`);
  const expected = r.stdout.trim().split('\n').map((line) => line.trim().split(/\s+/).pop());
  assert.strictEqual(expected.length, clear.length, `cslice classify said: ${r.stdout}`);
  clear.forEach((p, k) => {
    assert.strictEqual(p.state, expected[k], `at ${p.pose}: page ${p.state}, classify ${expected[k]}`);
  });
  assert(clear.length >= 10, `too few clicks clear of contact: ${clear.length}`);
  const count = (state) => clear.filter((p) => p.state === state).length;
  console.log(`      ${clear.length} clicks checked: ${count('free')} free, ` +
    `${count('blocked')} blocked, ${count('contact')} contact`);
}

async function checkPlacedParts(page) {
  const moving = await page.locator('#parts-svg path.moving').getAttribute('d');
  const fixed = await page.locator('#parts-svg path.fixed').getAttribute('d');
  assert(moving && moving.length > 20, 'the moving part is not drawn');
  assert(fixed && fixed.length > 20, 'the fixed part is not drawn');
  const caption = await page.locator('#parts-caption').innerText();
  assert(/\bfree\b/.test(caption), `caption: ${caption}`);
  const box = await page.locator('#parts-svg path.moving').boundingBox();
  assert(box && box.width > 5 && box.height > 5, 'the moving part has no size on screen');
}

async function checkColouring(page) {
  const before = await surfaceShot(page);
  await page.locator('#colour').selectOption('label');
  const after = await surfaceShot(page);
  assert(!after.equals(before), 'colouring by feature pair changed nothing');
}

async function checkExample(context, example) {
  let view = null;
  await check(`${example}: cslice view writes the page`, () => {
    view = writeView(example);
    console.log(`      ${(view.size / 1e6).toFixed(2)} MB`);
  });
  if (!view) return;
  let opened = null;
  await check(`${example}: the page opens`, async () => {
    opened = await openPage(context, view.html);
  });
  if (!opened) return;
  const { page, problems } = opened;
  try {
    await check(`${example}: 3D surface drawn`, () => checkSurface(context, page));
    await check(`${example}: slider changes the slice`, () => checkSlider(page));
    await check(`${example}: clicks place the parts, agreeing with cslice classify`,
      () => checkClicks(page, view.pair));
    await check(`${example}: colouring by feature pair`, () => checkColouring(page));
    await check(`${example}: no errors and no requests`, async () => {
      assert.deepStrictEqual(problems, []);
    });
  } finally {
    await page.close();
  }
}

async function main() {
  const start = Date.now();
  fs.mkdirSync(args.work, { recursive: true });
  await check('cslice view: bad input is exit status 2 and no page', checkBadInput);
  let browser = null;
  await check('headless Chromium starts', async () => {
    browser = await launch();
  });
  if (browser) {
    try {
      for (const example of args.examples) await checkExample(browser.context, example);
    } finally {
      await browser.close();
    }
  }
  console.log(`${passed} passed, ${failed} failed (${((Date.now() - start) / 1000).toFixed(1)} s)`);
  process.exit(failed === 0 ? 0 : 1);
}

main().catch((error) => {
  console.log(`FAIL  ${error.stack || error}`);
  process.exit(1);
});
