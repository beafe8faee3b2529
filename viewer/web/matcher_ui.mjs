// Match RGB (thesis §6.2.2) and the metamer view (thesis fig. 6.3 as a tool): the server finds
// the light closest to the editor's whose RGB is the reference's; the metamer view shows the
// image under the applied light, under the editor's shape matched to that light's RGB, and the
// ΔE2000 map between the two.

import * as api from './api.mjs';

// Matches the editor's light to `target` and puts the result in the editor as samples.
export async function matchEditorLight(editor, wavelengths, target, conversion) {
    const result = await api.match(editor.lightAt(wavelengths), target, conversion);
    if (!result.reachable) throw new Error(`no non-negative light has this RGB: ${result.message}`);
    editor.multiply = 1;
    editor.setSamples(wavelengths, result.spectrum);
    return result;
}

export function describeMatch(result) {
    return `${result.newtonSteps} Newton steps, RGB residual ${result.rgbResidual.toExponential(1)}, ` +
           `complementarity ${result.complementarity.toExponential(1)}, ` +
           `changed ${(100 * result.relativeChange).toFixed(1)}%`;
}

// The ΔE2000 map's colour scale tops out here unless the map goes higher.
const DELTA_E_SCALE = 5;

export async function showMetamers(views, lightA, shape, matrix, conversion, relight) {
    const target = matrix.map((row) => row.reduce((s, m, i) => s + m * lightA[i], 0));
    const result = await api.match(shape, target, conversion);
    if (!result.reachable) throw new Error(`the metamer cannot be matched: ${result.message}`);
    const lightB = result.spectrum;
    views.a.showRgb(relight(lightA));
    views.b.showRgb(relight(lightB));
    const difference = await api.difference(lightA, lightB);
    views.de.showHeat(difference.map, Math.max(DELTA_E_SCALE, difference.max));
    return { lightB, difference, result };
}
