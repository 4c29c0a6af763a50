// Opens a medialaxis page in headless Chromium (Debian's, driven by playwright-core),
// offline, plays with its controls and takes a screenshot of its view; prints one JSON
// report on stdout. The checks on the report are test_web_page.py's.
//   node open-page.js NODE_MODULES CHROMIUM PAGE.html SHOT.png [--serve] [--plain] [--page-shot FILE]
// --serve opens the page from a web server on 127.0.0.1 (this script's) instead of a
// file; --plain only loads and shoots (for the figures), with no interaction;
// --page-shot also takes the whole page, controls included (docs/images/web-page.png).
'use strict';
const fs = require('fs');
const http = require('http');
const os = require('os');
const path = require('path');

const [modules, chromiumPath, pagePath, shotPath, ...options] = process.argv.slice(2);
const { chromium } = require(path.join(modules, 'playwright-core'));

// What WebGL needs without a GPU: SwiftShader through ANGLE (checked with Chromium 156).
const ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--use-angle=swiftshader', '--enable-unsafe-swiftshader'];

function serve(file) {
  return new Promise((resolve) => {
    const server = http.createServer((request, response) => {
      if (request.url === '/' + path.basename(file)) {
        response.writeHead(200, { 'Content-Type': 'text/html; charset=utf-8' });
        response.end(fs.readFileSync(file));
      } else {
        response.writeHead(404);
        response.end();
      }
    });
    server.listen(0, '127.0.0.1', () => resolve(server));
  });
}

async function main() {
  const report = { page: pagePath, bytes: fs.statSync(pagePath).size, consoleErrors: [], pageErrors: [], requests: [], checks: {} };
  const userData = fs.mkdtempSync(path.join(os.tmpdir(), 'medial-chromium-'));
  let server = null;
  let url = 'file://' + path.resolve(pagePath);
  if (options.includes('--serve')) {
    server = await serve(path.resolve(pagePath));
    url = `http://127.0.0.1:${server.address().port}/${path.basename(pagePath)}`;
  }
  const context = await chromium.launchPersistentContext(userData, {
    executablePath: chromiumPath, headless: true, args: ARGS, viewport: { width: 1000, height: 640 }, deviceScaleFactor: 1,
  });
  try {
    // Offline: anything but the page itself is refused, and recorded.
    await context.route('**/*', (route) => {
      const target = route.request().url();
      if (target === url || target.startsWith('data:')) return route.continue();
      report.requests.push(target);
      return route.abort();
    });
    const page = await context.newPage();
    page.on('console', (message) => {
      if (message.type() === 'error') report.consoleErrors.push(message.text());
    });
    page.on('pageerror', (error) => report.pageErrors.push(String(error)));
    const start = Date.now();
    await page.goto(url);
    await page.waitForFunction(() => ['ready', 'error'].includes(document.documentElement.dataset.medialStatus), null, { timeout: 120000 });
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
    report.loadMs = Date.now() - start;
    report.status = await page.evaluate(() => document.documentElement.dataset.medialStatus);
    report.webgl = await page.evaluate(() => {
      const gl = document.createElement('canvas').getContext('webgl2');
      return gl ? gl.getParameter(gl.VERSION) : null;
    });
    if (report.status !== 'ready') {
      report.error = await page.evaluate(() => (document.getElementById('medial-error') || {}).textContent);
      return report;
    }
    const snapshot = () => page.evaluate(() => window.medialViewer.layers());
    report.title = await page.title();
    report.controls = await page.evaluate(() => window.medialViewer.state.controls);
    report.manifest = await page.evaluate(() => window.medialViewer.manifest.layers);
    report.layers = await snapshot();
    report.decimation = await page.evaluate(() => (document.getElementById('balls-decimation') || {}).textContent || null);
    await page.locator('#medial-view').screenshot({ path: shotPath });
    const whole = options.indexOf('--page-shot');
    if (whole >= 0) await page.screenshot({ path: options[whole + 1] });
    if (options.includes('--plain')) return report;

    const setRange = (id, value) => page.$eval(`#${id}`, (input, v) => {
      input.value = String(v);
      input.dispatchEvent(new Event('input'));
    }, value);
    const checks = report.checks;
    // A toggle hides its layer and shows it again.
    const toggles = { 'surface-visible': 'surface', 'mesh-faces': 'mesh-faces', 'graph-arcs': 'graph-arcs', 'balls-visible': 'balls' };
    for (const [id, layer] of Object.entries(toggles)) {
      if (!report.controls.includes(id)) continue;
      const before = (await snapshot())[layer].visible;
      await page.click(`#${id}`);
      const after = (await snapshot())[layer].visible;
      await page.click(`#${id}`);
      checks[`toggle ${id}`] = before !== after && (await snapshot())[layer].visible === before;
    }
    // The radius filter: the smallest radius raised to the middle shows fewer balls.
    if (report.controls.includes('balls-min')) {
      const [lo, hi] = await page.$eval('#balls-min', (input) => [Number(input.min), Number(input.max)]);
      await setRange('balls-min', (lo + hi) / 2);
      const fewer = (await snapshot()).balls.shown;
      await setRange('balls-min', lo);
      const all = (await snapshot()).balls.shown;
      checks['radius filter'] = fewer < all && all === report.layers.balls.points;
      report.ballsAboveMiddleRadius = fewer;
    }
    // The thickness threshold: a higher threshold paints more of the surface thin.
    if (report.controls.includes('thickness-threshold')) {
      const [lo, hi] = await page.$eval('#thickness-threshold', (input) => [Number(input.min), Number(input.max)]);
      await setRange('thickness-threshold', lo + 0.1 * (hi - lo));
      const few = await page.evaluate(() => window.medialViewer.state.thinVertices);
      const fewText = await page.textContent('#thickness-readout');
      await setRange('thickness-threshold', lo + 0.9 * (hi - lo));
      const many = await page.evaluate(() => window.medialViewer.state.thinVertices);
      checks['thickness threshold'] = few < many;
      report.thicknessReadout = fewText;
    }
    // Picking with the mouse: a surface point gives its thickness; with the surface hidden,
    // a medial vertex (or ball, or graph point) gives its radius and type.
    // A click on the point of a layer nearest the camera (nothing hides it).
    const click = async (layer, index) => {
      const at = await page.evaluate(([l, i]) => window.medialViewer.screenOf(l, i), [layer, index]);
      if (!at) return null;
      await page.mouse.click(at.x, at.y);
      await page.waitForTimeout(50);
      return page.textContent('#medial-pick');
    };
    if (report.layers.surface && report.manifest.surface.thickness) {
      const text = await click('surface', 'front');
      checks['pick a surface point'] = /surface point[\s\S]*thickness \d/.test(text || '');
      report.pickSurface = text;
    }
    const medial = report.layers['mesh-faces'] ? 'mesh' : (report.layers['graph-arcs'] ? 'graph' : 'balls');
    if (report.controls.includes('surface-visible')) await page.click('#surface-visible');
    if (medial === 'balls' && !report.layers.balls.visible) await page.click('#balls-visible');
    const text = await click(medial, 'front');
    checks[`pick a ${medial} point`] = /radius\s+\d[\s\S]*type\s+\w/.test(text || '');
    report.pickMedial = text;
    if (report.controls.includes('surface-visible')) await page.click('#surface-visible');
    return report;
  } finally {
    await context.close();
    if (server) server.close();
    fs.rmSync(userData, { recursive: true, force: true });
  }
}

main().then((report) => {
  process.stdout.write(JSON.stringify(report, null, 1) + '\n');
}).catch((error) => {
  process.stdout.write(JSON.stringify({ failure: String(error && error.stack ? error.stack : error) }) + '\n');
  process.exit(1);
});
