// The page: loads the image and wires the editor, the image and the buttons of Appendix D.1
// together. window.gonio exposes the parts to scripts and the browser test.

import * as api from './api.mjs';
import { basisLightMatrix, cssColour, lightMatrix, normalisedToMax, rgbOf } from './colour.mjs';
import { flatCurve, RANGE, SpdEditor } from './editor.mjs';
import { ImageView, relight } from './image_view.mjs';
import { describeMatch, matchEditorLight, showMetamers } from './matcher_ui.mjs';

const $ = (id) => document.getElementById(id);

// Appendix D.1.2's sliders are logarithmic: Zoom 1 at the left, Multiply 1 in the middle.
const zoomOf = (position) => Math.pow(10, 2 * position / 1000);           // 1 .. 100
const multiplyOf = (position) => Math.pow(10, 2 * (position - 500) / 500);  // 0.01 .. 100

const format = (values, digits = 4) => values.map((v) => v.toFixed(digits)).join(' ');

function download(blob, name) {
    const link = document.createElement('a');
    link.href = URL.createObjectURL(blob);
    link.download = name;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

function report(message) { $('status').textContent = message; }

// Runs an action of a control, showing its failure in the status line. body[data-pending]
// counts the actions still running, so that a script can wait for the page to settle.
let pending = 0;
function guarded(action) {
    return async (...args) => {
        document.body.dataset.pending = String(++pending);
        try {
            report('');
            await action(...args);
        } catch (e) {
            report(e.message);
        } finally {
            document.body.dataset.pending = String(--pending);
        }
    };
}

async function start() {
    const info = await api.imageInfo();
    const wavelengths = info.wavelengths;
    const n = wavelengths.length;
    // An image in a basis (info.basis: k vectors of n samples) relights from its k coefficients
    // per pixel with the 3×k matrix C B (thesis §6.2.4), an image of samples from its n samples.
    const basis = info.basis;
    const values = basis ? await api.coefficients() : await api.spectra();
    const components = basis ? basis.length : n;
    $('file').textContent = `${info.file} (${info.width}×${info.height}, ${n} wavelengths)`;

    const conversion = () => $('conversion').value;
    const matrix = () => info.toRgb[conversion()];
    const relit = (light) => {
        const c = lightMatrix(matrix(), light);
        return relight(values, components, basis ? basisLightMatrix(c, basis) : c);
    };
    const imageView = new ImageView($('image'), info.width, info.height);
    const metamerViews = { a: new ImageView($('metamer-a'), info.width, info.height),
                           b: new ImageView($('metamer-b'), info.width, info.height),
                           de: new ImageView($('metamer-de'), info.width, info.height) };
    let applied = new Array(n).fill(1);  // the equal-energy light the image was rendered with

    const reference = () => ['r', 'g', 'b'].map((c) => $(`ref-${c}`).value / 1000);
    function showReference() {
        const rgb = reference();
        ['r', 'g', 'b'].forEach((c, k) => { $(`ref-${c}-value`).textContent = rgb[k].toFixed(3); });
        $('ref-patch').style.background = cssColour(rgb);
    }

    function showLight() {
        const rgb = rgbOf(matrix(), editor.lightAt(wavelengths));
        const patch = normalisedToMax(rgb);
        $('patch').style.background = cssColour(patch);
        $('rgb').textContent = format(rgb);
        $('rgb-normalised').textContent = format(patch);
        $('power').textContent = (rgb[0] + rgb[1] + rgb[2]).toFixed(4);  // App. D.1.2 (12)
        $('save-curve').disabled = !editor.isCurve();
    }
    const editor = new SpdEditor($('spd'), showLight);

    async function showImage() {
        if ($('view').value === 'single') {
            imageView.showRgb(relit(applied));
            return;
        }
        const shape = editor.lightAt(wavelengths);
        const { difference } = await showMetamers(metamerViews, applied, shape, matrix(),
                                                  conversion(), relit);
        $('metamer-caption').textContent =
            `ΔE2000 mean ${difference.mean.toFixed(2)}, max ${difference.max.toFixed(2)}`;
    }

    function setSlider(id, position) {
        $(id).value = position;
        $(id).dispatchEvent(new Event('input'));
    }
    $('zoom').addEventListener('input', () => {
        const z = zoomOf(Number($('zoom').value));
        $('zoom-value').textContent = z.toPrecision(3);
        editor.setZoom(z);
    });
    $('multiply').addEventListener('input', () => {
        const m = multiplyOf(Number($('multiply').value));
        $('multiply-value').textContent = m.toPrecision(3);
        editor.setMultiply(m);
    });
    ['r', 'g', 'b'].forEach((c) => $(`ref-${c}`).addEventListener('input', showReference));
    $('conversion').addEventListener('change', guarded(async () => { showLight(); await showImage(); }));
    $('view').addEventListener('change', guarded(async () => {
        const single = $('view').value === 'single';
        $('single-view').hidden = !single;
        $('metamer-view').hidden = single;
        if (single) imageView.fit(); else Object.values(metamerViews).forEach((v) => v.fit());
        await showImage();
    }));

    $('apply').addEventListener('click', guarded(async () => {
        applied = editor.lightAt(wavelengths);
        await showImage();
    }));
    function reset() {
        setSlider('multiply', 500);
        setSlider('zoom', 0);
        $('preset').value = '';
        editor.setCurve(flatCurve());
    }
    $('reset').addEventListener('click', reset);
    $('curve').addEventListener('click', () => editor.backToCurve());

    for (const name of await api.illuminantNames()) $('preset').add(new Option(name, name));
    $('preset').addEventListener('change', guarded(async () => {
        if (!$('preset').value) return;
        const preset = await api.illuminant($('preset').value);
        setSlider('multiply', 500);
        editor.setSamples(wavelengths, preset.values);
    }));

    $('load').addEventListener('change', guarded(async () => {
        const file = $('load').files[0];
        if (!file) return;
        const light = await api.loadLight(await file.text(), file.name);
        $('load').value = '';
        setSlider('multiply', 500);
        if (light.kind === 'curve')
            editor.setCurve({ points: light.wavelengths.map((nm, i) => ({ nm, v: light.values[i] })),
                              before: light.before, after: light.after });
        else
            editor.setSamples(light.wavelengths, light.values);
        if (light.note) report(light.note);
    }));
    $('save-light').addEventListener('click', guarded(async () => {
        // Point samples at 1 nm, as the thesis's Save Light (which covers 400-700 nm).
        const nm = [];
        for (let w = RANGE.start; w <= RANGE.end; ++w) nm.push(w);
        const text = await api.saveLight({ format: 'cspec', start: RANGE.start, step: 1,
                                           values: editor.lightAt(nm) });
        download(new Blob([text], { type: 'text/plain' }), 'light.cspec');
    }));
    $('save-curve').addEventListener('click', guarded(async () => {
        const { points, before, after } = editor.curve;
        const m = editor.multiply;
        const text = await api.saveLight({ format: 'curve', wavelengths: points.map((q) => q.nm),
                                           values: points.map((q) => q.v * m), before: before * m,
                                           after: after * m });
        download(new Blob([text], { type: 'text/plain' }), 'light.curve');
    }));
    for (const kind of ['png', 'exr'])
        $(`save-${kind}`).addEventListener('click', guarded(async () => {
            download(await api.exportImage(applied, conversion(), kind), `relit.${kind}`);
        }));
    $('match').addEventListener('click', guarded(async () => {
        const result = await matchEditorLight(editor, wavelengths, reference(), conversion());
        $('multiply').value = 500;  // the matched light holds the factor: the slider is back at 1
        $('multiply-value').textContent = multiplyOf(500).toPrecision(3);
        $('match-report').textContent = describeMatch(result);
    }));

    showReference();
    showLight();
    await showImage();
    window.gonio = { info, editor, imageView, metamerViews, wavelengths, applied: () => applied };
    document.body.dataset.ready = 'true';
}

start().catch((e) => report(`cannot start: ${e.message}`));
