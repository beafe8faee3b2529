// The viewer's page in a real browser: Debian's chromium driven by playwright-core under
// node --test. Starts `gonio view` on 127.0.0.1 port 0, reads the URL it prints, and checks the
// editor, Match RGB, Apply Light and the metamer view against the server. Screenshots go to
// $ARTEFACTS. Environment: GONIO (the binary), GONIO_IMAGE (a reflectance EXR), ARTEFACTS.

import { spawn } from 'node:child_process';
import { mkdtempSync, mkdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { chromium } from 'playwright-core';

const artefacts = process.env.ARTEFACTS || path.join(tmpdir(), 'gonio-viewer-artefacts');
let server, url, context, page, userDataDir;
const consoleErrors = [];

function startServer() {
    return new Promise((resolve, reject) => {
        server = spawn(process.env.GONIO, ['view', process.env.GONIO_IMAGE, '--bind', '127.0.0.1',
                                           '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
        let output = '';
        server.stdout.on('data', (chunk) => {
            output += chunk;
            const found = output.match(/gonio view: (http:\/\/127\.0\.0\.1:\d+\/)/);
            if (found) resolve(found[1]);
        });
        server.on('exit', (code) => reject(new Error(`gonio view exited with ${code}: ${output}`)));
    });
}

before(async () => {
    mkdirSync(artefacts, { recursive: true });
    url = await startServer();
    userDataDir = mkdtempSync(path.join(tmpdir(), 'gonio-chromium-'));
    context = await chromium.launchPersistentContext(userDataDir, {
        executablePath: '/usr/bin/chromium',
        headless: true,
        viewport: { width: 1400, height: 800 },
        args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
               '--disable-background-networking', '--disable-component-update', '--disable-sync'],
    });
    page = context.pages()[0] || (await context.newPage());
    page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
    page.on('pageerror', (e) => consoleErrors.push(e.message));
    await page.goto(url);
    await page.waitForSelector('body[data-ready="true"]', { timeout: 20000 });
});

after(async () => {
    if (context) await context.close();
    if (server) server.kill('SIGTERM');
    if (userDataDir) rmSync(userDataDir, { recursive: true, force: true });
});

// Waits until every action the page started (a preset's fetch, a match) has finished.
const settled = () => page.waitForFunction(() => (document.body.dataset.pending || '0') === '0');

const readout = async (id) => (await page.textContent(`#${id}`)).trim().split(/\s+/).map(Number);

test('the spline passes through its control points and is never negative, as gonio reads it', async () => {
    const curveFile = 'curve 7 380 780\n0 0.2\n0 0.2\n0.2 1.5\n0.45 0.01\n0.7 2\n1 0.3\n1 0.3\n';
    const loaded = await (await fetch(`${url}api/light/load?name=t.curve`, { method: 'POST',
                                                                             body: curveFile })).json();
    const check = await page.evaluate(async ({ loaded }) => {
        const { evaluateCurve } = await import('/spline.mjs');
        const curve = { points: loaded.wavelengths.map((nm, i) => ({ nm, v: loaded.values[i] })),
                        before: loaded.before, after: loaded.after };
        const atKnots = evaluateCurve(curve, loaded.wavelengths);
        const dense = [];
        for (let nm = 380; nm <= 780; nm += 0.25) dense.push(nm);
        const values = evaluateCurve(curve, dense);
        const atImage = evaluateCurve(curve, window.gonio.wavelengths);
        return { knotError: Math.max(...atKnots.map((v, i) => Math.abs(v - loaded.values[i]))),
                 min: Math.min(...values),
                 serverError: Math.max(...atImage.map((v, i) => Math.abs(v - loaded.atImage[i]))) };
    }, { loaded });
    assert.ok(check.knotError <= 1e-12, `through the control points: ${check.knotError}`);
    assert.ok(check.min >= 0, `never negative: ${check.min}`);
    assert.ok(check.serverError <= 1e-12, `the same curve as spectral/catmull_rom.h: ${check.serverError}`);
});

test('dragging a control point changes the curve and the readout', async () => {
    const box = await page.locator('#spd').boundingBox();
    const state = () => page.evaluate(() => ({ point: { ...window.gonio.editor.curve.points[2] },
                                                at: window.gonio.editor.lightAt([580])[0],
                                                position: window.gonio.editor.pointOnCanvas(2) }));
    const start = await state();
    const rgbBefore = await readout('rgb');
    await page.mouse.move(box.x + start.position.x, box.y + start.position.y);
    await page.mouse.down();
    await page.mouse.move(box.x + start.position.x + 400, box.y + start.position.y - 60, { steps: 5 });
    await page.mouse.up();
    const end = await state();
    assert.ok(end.point.v > start.point.v + 0.05, `the point moved up: ${start.point.v} → ${end.point.v}`);
    assert.notEqual(end.at, start.at, 'the curve changed');
    const neighbour = await page.evaluate(() => window.gonio.editor.curve.points[3].nm);
    assert.ok(end.point.nm < neighbour, 'the point stays left of its right neighbour');
    assert.notDeepEqual(await readout('rgb'), rgbBefore, 'the readout changed');
    await page.screenshot({ path: path.join(artefacts, 'viewer-dragged.png') });
});

test('Match RGB makes the readout equal the target', async () => {
    await page.click('#reset');
    const target = [0.9, 0.6, 0.3];
    await page.evaluate((target) => {
        ['r', 'g', 'b'].forEach((c, k) => {
            const slider = document.getElementById(`ref-${c}`);
            slider.value = String(1000 * target[k]);
            slider.dispatchEvent(new Event('input'));
        });
    }, target);
    await page.click('#match');
    await settled();
    const normalised = await readout('rgb-normalised');
    const max = Math.max(...target);
    target.forEach((t, k) => assert.ok(Math.abs(normalised[k] - t / max) <= 1e-3,
                                       `component ${k}: ${normalised[k]} vs ${t / max}`));
    assert.equal(await page.textContent('#status'), '');
});

function encodeSrgb(linear) {
    const v = Math.min(Math.max(linear, 0), 1);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
}

test('Apply Light shows the pixel the server computes', async () => {
    await page.selectOption('#preset', 'F11');
    await settled();
    await page.click('#apply');
    await settled();
    const light = await page.evaluate(() => window.gonio.applied());
    const response = await fetch(`${url}api/relight`, { method: 'POST',
        body: JSON.stringify({ light, conversion: 'cie' }) });
    assert.equal(response.status, 200);
    const rgb = new Float32Array(await response.arrayBuffer());
    const { width, height } = await page.evaluate(() => window.gonio.info);
    for (const [x, y] of [[width / 14, height / 4], [width / 2, (3 * height) / 4], [width - 20, height / 4]]) {
        const px = Math.floor(x), py = Math.floor(y);
        const shown = await page.evaluate(([px, py]) => {
            const view = window.gonio.imageView;
            const c = view.canvasPointOf(px, py);
            return view.canvasPixel(c.x, c.y);
        }, [px, py]);
        const p = 3 * (py * width + px);
        for (let k = 0; k < 3; ++k) {
            const expected = 255 * encodeSrgb(rgb[p + k]);
            assert.ok(Math.abs(shown[k] - expected) <= 1, `pixel (${px}, ${py}) channel ${k}: ` +
                      `canvas ${shown[k]}, server ${expected.toFixed(2)}`);
        }
    }
    await page.screenshot({ path: path.join(artefacts, 'viewer-f11.png') });
});

test('the metamer view shows two lights of one RGB and their ΔE2000 map', async () => {
    await page.selectOption('#preset', 'D65');
    await settled();
    await page.selectOption('#view', 'metamer');
    await settled();
    const caption = await page.textContent('#metamer-caption');
    const mean = Number(caption.match(/mean ([0-9.]+)/)[1]);
    assert.ok(mean >= 3, `D65's shape matched to F11's RGB looks different: mean ΔE2000 ${mean}`);
    await page.screenshot({ path: path.join(artefacts, 'viewer-metamers.png') });
    await page.selectOption('#view', 'single');
});

test('no console errors', () => {
    assert.deepEqual(consoleErrors, []);
});
