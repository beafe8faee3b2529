// The relit image on a canvas, with zoom (mouse wheel, about the pointer) and pan (drag). The
// relighting is thesis §6.2.4's: one 3×n matrix C = M diag(l) per light (3×k, C B, for an image
// in a basis), one product per pixel.

import { encodeSrgb } from './colour.mjs';

// Linear RGB (3 floats per pixel) of every pixel of `spectra` (n floats per pixel: samples, or
// coefficients in a basis) under C (3×n).
export function relight(spectra, n, c) {
    const pixels = spectra.length / n;
    const rgb = new Float32Array(3 * pixels);
    for (let p = 0; p < pixels; ++p) {
        const base = p * n;
        let r = 0, g = 0, b = 0;
        for (let i = 0; i < n; ++i) {
            const s = spectra[base + i];
            r += c[i] * s;
            g += c[n + i] * s;
            b += c[2 * n + i] * s;
        }
        rgb[3 * p] = r; rgb[3 * p + 1] = g; rgb[3 * p + 2] = b;
    }
    return rgb;
}

// 8-bit sRGB bytes of linear RGB, as viewer/image_export.cpp writes a PNG.
function srgbBytes(rgb) {
    const bytes = new Uint8ClampedArray((rgb.length / 3) * 4);
    for (let p = 0, q = 0; p < rgb.length; p += 3, q += 4) {
        bytes[q] = Math.round(255 * encodeSrgb(rgb[p]));
        bytes[q + 1] = Math.round(255 * encodeSrgb(rgb[p + 1]));
        bytes[q + 2] = Math.round(255 * encodeSrgb(rgb[p + 2]));
        bytes[q + 3] = 255;
    }
    return bytes;
}

// A false-colour map of values in [0, max]: black to red to yellow to white.
function heatBytes(values, max) {
    const bytes = new Uint8ClampedArray(values.length * 4);
    values.forEach((v, p) => {
        const t = Math.min(Math.max(v / max, 0), 1) * 3;
        bytes[4 * p] = 255 * Math.min(t, 1);
        bytes[4 * p + 1] = 255 * Math.min(Math.max(t - 1, 0), 1);
        bytes[4 * p + 2] = 255 * Math.min(Math.max(t - 2, 0), 1);
        bytes[4 * p + 3] = 255;
    });
    return bytes;
}

export class ImageView {
    constructor(canvas, width, height) {
        this.canvas = canvas;
        this.width = width;
        this.height = height;
        this.offscreen = document.createElement('canvas');
        this.offscreen.width = width;
        this.offscreen.height = height;
        this.scale = 1;
        this.origin = { x: 0, y: 0 };  // canvas position of the image's top-left corner (CSS px)
        this.panFrom = null;
        canvas.addEventListener('wheel', (e) => this.wheel(e), { passive: false });
        canvas.addEventListener('pointerdown', (e) => {
            this.panFrom = { x: e.offsetX - this.origin.x, y: e.offsetY - this.origin.y };
            canvas.setPointerCapture(e.pointerId);
        });
        canvas.addEventListener('pointermove', (e) => {
            if (!this.panFrom) return;
            this.origin = { x: e.offsetX - this.panFrom.x, y: e.offsetY - this.panFrom.y };
            this.draw();
        });
        canvas.addEventListener('pointerup', () => { this.panFrom = null; });
        this.fit();
    }

    fit() {
        const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
        this.scale = Math.min(w / this.width, h / this.height);
        this.origin = { x: (w - this.scale * this.width) / 2, y: (h - this.scale * this.height) / 2 };
        this.draw();
    }

    wheel(e) {
        e.preventDefault();
        const factor = Math.exp(-e.deltaY * 0.002);
        const x = e.offsetX, y = e.offsetY;
        this.origin = { x: x - (x - this.origin.x) * factor, y: y - (y - this.origin.y) * factor };
        this.scale *= factor;
        this.draw();
    }

    showRgb(linearRgb) { this.showBytes(srgbBytes(linearRgb)); }
    showHeat(values, max) { this.showBytes(heatBytes(values, max)); }

    showBytes(bytes) {
        this.offscreen.getContext('2d').putImageData(new ImageData(bytes, this.width, this.height), 0, 0);
        this.draw();
    }

    draw() {
        const dpr = window.devicePixelRatio || 1;
        const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
        this.canvas.width = Math.round(w * dpr);
        this.canvas.height = Math.round(h * dpr);
        const ctx = this.canvas.getContext('2d');
        ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
        ctx.fillStyle = '#222';
        ctx.fillRect(0, 0, w, h);
        ctx.imageSmoothingEnabled = false;  // a zoomed pixel is a square of its own colour
        ctx.drawImage(this.offscreen, this.origin.x, this.origin.y, this.scale * this.width,
                      this.scale * this.height);
    }

    // The canvas position (CSS px) of the centre of image pixel (x, y).
    canvasPointOf(x, y) {
        return { x: this.origin.x + (x + 0.5) * this.scale, y: this.origin.y + (y + 0.5) * this.scale };
    }

    // The RGBA bytes the canvas shows at a CSS-pixel position.
    canvasPixel(cssX, cssY) {
        const dpr = window.devicePixelRatio || 1;
        const ctx = this.canvas.getContext('2d');
        return Array.from(ctx.getImageData(Math.floor(cssX * dpr), Math.floor(cssY * dpr), 1, 1).data);
    }
}
