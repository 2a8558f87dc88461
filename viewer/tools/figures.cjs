// The README's pictures of configuration spaces (the paper's Figures 2, 3, 5 and 7): for each
// example, `cslice compute` and `cslice view`, then a screenshot of the page's 3D view alone
// (#layout=3d) from a fixed camera, in headless Chromium. scripts/make-figures.sh runs it.
// Usage: node figures.cjs --cslice PATH --source DIR --work DIR --out DIR
'use strict';

const { spawnSync } = require('child_process');
const fs = require('fs');
const path = require('path');
const { launch } = require('./chromium.cjs');

// Per example: the slice shown as the theta plane (the README's telling configurations) and
// a camera that shows the surface's shape with the theta axis in view.
const FIGURES = [
  { example: 'knee', theta: 0.5, az: -55, el: 22, zoom: 0.9 },
  { example: 'cam', theta: 0.3, az: -55, el: 28, zoom: 0.9 },
  { example: 'fixture', theta: 0, az: -55, el: 28, zoom: 0.9 },
  { example: 'fastener', theta: 1.5708, az: -55, el: 24, zoom: 0.9 },
];
const SIZE = { width: 820, height: 660 };

function parseArgs(argv) {
  const args = {};
  for (let i = 0; i < argv.length; i += 2) args[argv[i].replace(/^--/, '')] = argv[i + 1];
  for (const key of ['cslice', 'source', 'work', 'out']) {
    if (!args[key]) throw new Error(`missing --${key}`);
  }
  return args;
}

function cslice(args, argv) {
  const r = spawnSync(args.cslice, argv, { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`cslice ${argv.join(' ')}: ${r.stderr}`);
}

async function figure(context, args, { example, theta, az, el, zoom }) {
  const space = path.join(args.work, `${example}-space.json`);
  const html = path.join(args.work, `${example}.html`);
  cslice(args, ['compute', path.join(args.source, 'examples', `${example}.json`), '-o', space]);
  cslice(args, ['view', space, '-o', html]);
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  await page.goto(`file://${html}#layout=3d&theta=${theta}&az=${az}&el=${el}&zoom=${zoom}`);
  await page.waitForFunction(() => document.body.dataset.ready === '1', null, { timeout: 60000 });
  if (errors.length > 0) throw new Error(`${html}: ${errors.join('; ')}`);
  const png = path.join(args.out, `space-${example}.png`);
  await page.screenshot({ path: png });
  await page.close();
  console.log(`wrote ${png} (${Math.round(fs.statSync(png).size / 1024)} KB)`);
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  fs.mkdirSync(args.work, { recursive: true });
  fs.mkdirSync(args.out, { recursive: true });
  const browser = await launch(SIZE);
  try {
    for (const f of FIGURES) await figure(browser.context, args, f);
  } finally {
    await browser.close();
  }
}

main().catch((error) => {
  console.error(`figures.cjs: ${error.stack || error}`);
  process.exit(1);
});
