// Colour arithmetic of the page: the RGB of a light under a 3×n conversion matrix, the patch of
// Appendix D.1.2 (normalised so its largest component is 1), and sRGB encoding for the canvas.

// M l for a matrix given as 3 rows of n.
export function rgbOf(matrix, light) {
    return matrix.map((row) => row.reduce((sum, m, i) => sum + m * light[i], 0));
}

// Appendix D.1.2: "normalized in a way that the maximum component ... is 1.0".
export function normalisedToMax(rgb) {
    const max = Math.max(...rgb);
    return max > 0 ? rgb.map((c) => c / max) : [0, 0, 0];
}

// IEC 61966-2-1's transfer function, clamped to [0, 1] (as viewer/image_export.cpp's).
export function encodeSrgb(linear) {
    const v = Math.min(Math.max(linear, 0), 1);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
}

export function cssColour(linearRgb) {
    const [r, g, b] = linearRgb.map((c) => Math.round(255 * encodeSrgb(c)));
    return `rgb(${r}, ${g}, ${b})`;
}

// The 3×n matrix C = M diag(l) of thesis §6.2.4, flattened row by row.
// C B (3×k, flat like C): the light's matrix C (3×n, flat) applied to an image's basis, k vectors
// of n samples, so that a pixel's k coefficients relight with k products per channel.
export function basisLightMatrix(c, basis) {
    const n = c.length / 3, k = basis.length;
    const cb = new Float64Array(3 * k);
    for (let j = 0; j < 3; ++j)
        for (let m = 0; m < k; ++m) {
            let sum = 0;
            for (let i = 0; i < n; ++i) sum += c[j * n + i] * basis[m][i];
            cb[j * k + m] = sum;
        }
    return cb;
}

export function lightMatrix(matrix, light) {
    const n = light.length;
    const c = new Float64Array(3 * n);
    for (let k = 0; k < 3; ++k) for (let i = 0; i < n; ++i) c[k * n + i] = matrix[k][i] * light[i];
    return c;
}
