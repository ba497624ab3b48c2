// A small hand-drawn line chart on a canvas: the last `points` samples of
// a few series, the y axis scaled to the data (at least `minSpan`).
export class LineChart {
  constructor(canvas, { series, points = 100, minSpan = 1 }) {
    this.canvas = canvas;
    this.series = series;  // [{ label, color }]
    this.points = points;
    this.minSpan = minSpan;
    this.data = series.map(() => []);
  }
  push(values) {
    values.forEach((v, i) => {
      const d = this.data[i];
      d.push(v);
      if (d.length > this.points) d.shift();
    });
    this.draw();
  }
  draw() {
    const c = this.canvas.getContext('2d');
    const { width: w, height: h } = this.canvas;
    c.clearRect(0, 0, w, h);
    const all = this.data.flat().filter(Number.isFinite);
    if (all.length === 0) return;
    let lo = Math.min(...all, 0);
    let hi = Math.max(...all, 0);
    if (hi - lo < this.minSpan) hi = lo + this.minSpan;
    const pad = 16;
    const y = (v) => h - pad - ((v - lo) / (hi - lo)) * (h - 2 * pad);
    const x = (i) => 40 + (i / (this.points - 1)) * (w - 48);
    c.font = '10px sans-serif';
    c.fillStyle = '#666';
    c.strokeStyle = '#ddd';
    for (const v of [lo, 0, hi]) {
      c.beginPath();
      c.moveTo(40, y(v));
      c.lineTo(w - 8, y(v));
      c.stroke();
      c.fillText(v.toFixed(2), 2, y(v) + 3);
    }
    this.data.forEach((d, s) => {
      c.strokeStyle = this.series[s].color;
      c.beginPath();
      d.forEach((v, i) => (i === 0 ? c.moveTo(x(i), y(v)) : c.lineTo(x(i), y(v))));
      c.stroke();
    });
  }
}
