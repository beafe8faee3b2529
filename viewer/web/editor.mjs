// The SPD editor of Appendix D.1.2: a Catmull-Rom curve over 380-780 nm whose control points
// are dragged (never past a neighbour, the end points only vertically, never below 0), added
// (middle button, or shift-click) at the curve's value and removed (right button). A light given
// as samples (a loaded `cspec`, a matched light) is shown but not edited until "Curve" brings the
// last curve back. The light is the curve (or samples) times the Multiply factor.

import { evaluateCurve, evaluateSamples } from './spline.mjs';

export const RANGE = { start: 380, end: 780 };
const PICK_RADIUS = 7;    // px: how near the pointer must be to grab a control point
const MIN_GAP_NM = 1;     // control points stay this far apart, so the knots stay increasing
const MARGIN = { left: 44, right: 12, top: 10, bottom: 26 };

export function flatCurve(value = 1) {
    const points = [380, 480, 580, 680, 780].map((nm) => ({ nm, v: value }));
    return { points, before: value, after: value };
}

export class SpdEditor {
    constructor(canvas, onChange) {
        this.canvas = canvas;
        this.onChange = onChange;
        this.curve = flatCurve();
        this.samples = null;  // {wavelengths, values} while a sampled light is shown
        this.multiply = 1;
        this.top = 1.2;       // the value at the editor's top row, before zoom
        this.zoom = 1;
        this.dragging = -1;
        canvas.addEventListener('pointerdown', (e) => this.pointerDown(e));
        canvas.addEventListener('pointermove', (e) => this.pointerMove(e));
        canvas.addEventListener('pointerup', () => { this.dragging = -1; });
        canvas.addEventListener('contextmenu', (e) => e.preventDefault());
        canvas.addEventListener('auxclick', (e) => e.preventDefault());
        this.draw();
    }

    isCurve() { return this.samples === null; }

    // The light at `wavelengths`, Multiply applied.
    lightAt(wavelengths) {
        const values = this.isCurve() ? evaluateCurve(this.curve, wavelengths)
                                      : evaluateSamples(this.samples, wavelengths);
        return values.map((v) => v * this.multiply);
    }

    setCurve(curve) {
        this.curve = { points: curve.points.map((q) => ({ ...q })), before: curve.before,
                       after: curve.after };
        this.samples = null;
        this.fitTop();
        this.changed();
    }

    setSamples(wavelengths, values) {
        this.samples = { wavelengths: [...wavelengths], values: [...values] };
        this.fitTop();
        this.changed();
    }

    backToCurve() {
        this.samples = null;
        this.changed();
    }

    setMultiply(factor) { this.multiply = factor; this.changed(); }
    setZoom(factor) { this.zoom = factor; this.draw(); }

    // The top row shows the light's largest value with some room (Zoom divides it).
    fitTop() {
        const nm = [];
        for (let w = RANGE.start; w <= RANGE.end; w += 1) nm.push(w);
        const max = Math.max(...this.lightAt(nm));
        this.top = max > 0 ? 1.2 * max : 1.2;
    }

    changed() {
        this.draw();
        this.onChange();
    }

    // Canvas coordinates (CSS pixels) of a wavelength and value, and back.
    plotArea() {
        const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
        return { x0: MARGIN.left, x1: w - MARGIN.right, y0: h - MARGIN.bottom, y1: MARGIN.top };
    }
    toCanvas(nm, v) {
        const a = this.plotArea();
        const top = this.top / this.zoom;
        return { x: a.x0 + (nm - RANGE.start) / (RANGE.end - RANGE.start) * (a.x1 - a.x0),
                 y: a.y0 - v * this.multiply / top * (a.y0 - a.y1) };
    }
    fromCanvas(x, y) {
        const a = this.plotArea();
        const top = this.top / this.zoom;
        return { nm: RANGE.start + (x - a.x0) / (a.x1 - a.x0) * (RANGE.end - RANGE.start),
                 v: (a.y0 - y) / (a.y0 - a.y1) * top / this.multiply };
    }
    pointOnCanvas(i) { return this.toCanvas(this.curve.points[i].nm, this.curve.points[i].v); }

    pick(x, y) {
        return this.curve.points.findIndex((q) => {
            const c = this.toCanvas(q.nm, q.v);
            return Math.abs(c.x - x) <= PICK_RADIUS && Math.abs(c.y - y) <= PICK_RADIUS;
        });
    }

    pointerDown(e) {
        if (!this.isCurve()) return;
        const i = this.pick(e.offsetX, e.offsetY);
        if (e.button === 2) return this.removePoint(i);
        if (e.button === 1 || (e.button === 0 && e.shiftKey)) return this.addPoint(e.offsetX);
        if (e.button === 0 && i >= 0) {
            this.dragging = i;
            this.canvas.setPointerCapture(e.pointerId);
        }
    }

    pointerMove(e) {
        if (this.dragging < 0) return;
        const { nm, v } = this.fromCanvas(e.offsetX, e.offsetY);
        this.movePoint(this.dragging, nm, v);
    }

    // Moves point i as far towards (nm, v) as the rules allow.
    movePoint(i, nm, v) {
        const points = this.curve.points;
        const last = points.length - 1;
        const q = points[i];
        if (i > 0 && i < last)
            q.nm = Math.min(Math.max(nm, points[i - 1].nm + MIN_GAP_NM), points[i + 1].nm - MIN_GAP_NM);
        q.v = Math.max(0, v);
        if (i === 0) this.curve.before = q.v;  // the phantom repeats its end point
        if (i === last) this.curve.after = q.v;
        this.changed();
    }

    addPoint(x) {
        const nm = this.fromCanvas(x, 0).nm;
        const points = this.curve.points;
        const at = points.findIndex((q) => q.nm > nm);
        if (at <= 0 || nm - points[at - 1].nm < MIN_GAP_NM || points[at].nm - nm < MIN_GAP_NM) return;
        const v = evaluateCurve(this.curve, [nm])[0];
        points.splice(at, 0, { nm, v });
        this.changed();
    }

    removePoint(i) {
        if (i <= 0 || i >= this.curve.points.length - 1) return;  // the end points stay
        this.curve.points.splice(i, 1);
        this.changed();
    }

    draw() {
        const ctx = this.canvas.getContext('2d');
        const dpr = window.devicePixelRatio || 1;
        const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
        this.canvas.width = Math.round(w * dpr);
        this.canvas.height = Math.round(h * dpr);
        ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
        ctx.clearRect(0, 0, w, h);
        this.drawAxes(ctx);
        this.drawCurve(ctx);
        if (this.isCurve()) this.drawPoints(ctx);
    }

    drawAxes(ctx) {
        const a = this.plotArea();
        ctx.strokeStyle = '#888';
        ctx.fillStyle = '#444';
        ctx.font = '11px sans-serif';
        ctx.strokeRect(a.x0, a.y1, a.x1 - a.x0, a.y0 - a.y1);
        for (let nm = 400; nm <= 750; nm += 50) {
            const { x } = this.toCanvas(nm, 0);
            ctx.fillText(String(nm), x - 10, a.y0 + 14);
        }
        ctx.fillText('nm', a.x1 - 16, a.y0 + 24);
        const top = this.top / this.zoom;
        ctx.fillText(top.toPrecision(3), 2, a.y1 + 8);
        ctx.fillText('0', 30, a.y0);
    }

    drawCurve(ctx) {
        const nm = [];
        for (let w = RANGE.start; w <= RANGE.end; w += 1) nm.push(w);
        const values = this.lightAt(nm);
        ctx.strokeStyle = this.isCurve() ? '#1a4fa0' : '#a05a1a';
        ctx.lineWidth = 2;
        ctx.beginPath();
        values.forEach((v, k) => {
            const c = this.toCanvas(nm[k], v / this.multiply);
            if (k === 0) ctx.moveTo(c.x, c.y); else ctx.lineTo(c.x, c.y);
        });
        ctx.stroke();
        ctx.lineWidth = 1;
    }

    drawPoints(ctx) {
        ctx.fillStyle = '#fff';
        ctx.strokeStyle = '#000';
        this.curve.points.forEach((q) => {
            const c = this.toCanvas(q.nm, q.v);
            ctx.fillRect(c.x - 4, c.y - 4, 8, 8);
            ctx.strokeRect(c.x - 4, c.y - 4, 8, 8);
        });
    }
}
