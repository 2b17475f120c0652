// A line plot with uPlot that follows its container's width; an optional marker line at x.
// integerX: ticks only at whole numbers (iterations). The y axis is as wide as its labels.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

/// Room for the longest tick label (uPlot's default 50 px clips "-0.00025" or "12000").
function axisWidth(self, values) {
  if (!values || !values.length) return 50;
  const longest = Math.max(...values.map((v) => String(v).length));
  return Math.ceil(longest * 7.5) + 18;
}

export function linePlot(container, { xLabel, yLabel, height = 180, color = '#2563eb', points = false, integerX = false }) {
  let marker = null;
  let xTicks = [];
  const markerPlugin = {
    hooks: {
      draw: (u) => {
        if (marker === null) return;
        const x = u.valToPos(marker, 'x', true);
        const { ctx } = u;
        ctx.save();
        ctx.strokeStyle = '#e0a000';
        ctx.lineWidth = 2;
        ctx.beginPath();
        ctx.moveTo(x, u.bbox.top);
        ctx.lineTo(x, u.bbox.top + u.bbox.height);
        ctx.stroke();
        ctx.restore();
      },
    },
  };
  const width = () => Math.max(200, container.clientWidth - 10);
  const plot = new uPlot({
    width: width(), height,
    plugins: [markerPlugin],
    scales: { x: integerX ? { time: false, range: (u, lo, hi) => [Math.floor(lo) - (lo === hi ? 1 : 0), Math.ceil(hi) + (lo === hi ? 1 : 0)] } : { time: false } },
    axes: [
      integerX
        ? { label: xLabel, incrs: [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000], values: (u, splits) => { xTicks = splits.filter(Number.isInteger); return splits.map((v) => (Number.isInteger(v) ? String(v) : '')); } }
        : { label: xLabel },
      { label: yLabel, size: axisWidth, labelSize: 22 },
    ],
    legend: { show: false },
    series: [{}, { label: yLabel, stroke: color, width: 2, points: { show: points } }],
  }, [[], []], container);
  const ro = new ResizeObserver(() => { if (container.clientWidth > 0) plot.setSize({ width: width(), height }); });
  ro.observe(container);
  return {
    plot,
    setData(xs, ys) { plot.setData([xs, ys]); },
    setMarker(x) { marker = x; plot.redraw(false, false); },
    /// The x tick values last drawn (integerX plots).
    xTicks() { return [...xTicks]; },
  };
}
