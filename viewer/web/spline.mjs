// The SPD editor's curve: the same cubic Hermite with Catmull-Rom tangents as
// spectral/catmull_rom.h's CatmullRomHermite (thesis §6.2.2, matrix corrected), so that a curve
// drawn here is the curve `gonio` reads from a saved `curve` file.

// The value at x over strictly increasing knots t with values p (at least 2); `before` and
// `after` are the phantom control points, each one neighbouring spacing beyond its end knot.
export function catmullRomHermite(t, p, before, after, x) {
    const n = t.length;
    let i = upperBound(t, x);
    i = Math.min(Math.max(i, 1), n - 1) - 1;  // segment [t[i], t[i+1]]
    const knot = (j) => (j < 0 ? t[0] - (t[1] - t[0]) : j >= n ? t[n - 1] + (t[n - 1] - t[n - 2]) : t[j]);
    const value = (j) => (j < 0 ? before : j >= n ? after : p[j]);
    const tangent = (j) => (value(j + 1) - value(j - 1)) / (knot(j + 1) - knot(j - 1));
    const h = t[i + 1] - t[i];
    const u = (x - t[i]) / h;
    const u2 = u * u, u3 = u2 * u;
    // Cubic Hermite basis (Foley et al., Computer Graphics, §11.2.1).
    const h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
    const h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    return h00 * p[i] + h10 * h * tangent(i) + h01 * p[i + 1] + h11 * h * tangent(i + 1);
}

// The index of the first knot greater than x (std::upper_bound).
function upperBound(t, x) {
    let lo = 0, hi = t.length;
    while (lo < hi) {
        const mid = (lo + hi) >> 1;
        if (t[mid] <= x) lo = mid + 1; else hi = mid;
    }
    return lo;
}

// A curve {points: [{nm, v}], before, after} at each wavelength: clamped at 0 (an SPD is never
// negative, thesis §6.2.2), 0 outside the knots (a light emits nothing where it is not given).
export function evaluateCurve(curve, wavelengths) {
    const t = curve.points.map((q) => q.nm);
    const p = curve.points.map((q) => q.v);
    return wavelengths.map((nm) => {
        if (nm < t[0] - 1e-9 || nm > t[t.length - 1] + 1e-9) return 0;
        const x = Math.min(Math.max(nm, t[0]), t[t.length - 1]);
        return Math.max(0, catmullRomHermite(t, p, curve.before, curve.after, x));
    });
}

// Piecewise-linear samples {wavelengths, values} at each wavelength, 0 outside them.
export function evaluateSamples(samples, wavelengths) {
    const w = samples.wavelengths, v = samples.values;
    return wavelengths.map((nm) => {
        if (nm < w[0] - 1e-9 || nm > w[w.length - 1] + 1e-9) return 0;
        const i = Math.min(Math.max(upperBound(w, nm), 1), w.length - 1) - 1;
        const u = (nm - w[i]) / (w[i + 1] - w[i]);
        return v[i] + Math.min(Math.max(u, 0), 1) * (v[i + 1] - v[i]);
    });
}
