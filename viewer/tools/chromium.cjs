// Headless Chromium for the viewer's browser test (tests/viewer) and the README's figures
// (viewer/tools/figures.cjs): Debian's /usr/bin/chromium driven by playwright-core, which
// never downloads a browser of its own. CommonJS, so NODE_PATH (set by CMake and the scripts
// to the build directory's node_modules) finds playwright-core.
'use strict';

const fs = require('fs');
const os = require('os');
const path = require('path');
const { chromium } = require('playwright-core');

const CHROMIUM = process.env.CSLICE_CHROMIUM || '/usr/bin/chromium';

// No network of its own (updates, sync, field trials), a fresh profile every time. WebGL
// still works with --disable-gpu: Chromium falls back to SwiftShader, its software renderer,
// which --enable-unsafe-swiftshader allows for WebGL and --use-angle=swiftshader selects.
const ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--hide-scrollbars',
];

// Returns { context, close }: a browser context with a fresh --user-data-dir, removed by
// close(). Throws when Chromium is missing: callers must fail, not skip.
async function launch({ width = 1280, height = 720 } = {}) {
  if (!fs.existsSync(CHROMIUM)) {
    throw new Error(`${CHROMIUM} not found: install Debian's chromium package ` +
      '(bash scripts/install-deps.sh --browser)');
  }
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'cslice-chromium-'));
  // launchPersistentContext is how playwright takes a given --user-data-dir.
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    args: ARGS,
    viewport: { width, height },
    deviceScaleFactor: 1,
    offline: true,
  });
  const close = async () => {
    await context.close();
    fs.rmSync(profile, { recursive: true, force: true });
  };
  return { context, close };
}

module.exports = { launch, CHROMIUM };
