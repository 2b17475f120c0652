// A line plot with uPlot that follows its container's width; an optional marker line at x.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

export function linePlot(container, { xLabel, yLabel, height = 180, color = '#2563eb', points = false }) {
  let marker = null;
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
    scales: { x: { time: false } },
    axes: [{ label: xLabel }, { label: yLabel }],
    legend: { show: false },
    series: [{}, { label: yLabel, stroke: color, width: 2, points: { show: points } }],
  }, [[], []], container);
  const ro = new ResizeObserver(() => { if (container.clientWidth > 0) plot.setSize({ width: width(), height }); });
  ro.observe(container);
  return {
    plot,
    setData(xs, ys) { plot.setData([xs, ys]); },
    setMarker(x) { marker = x; plot.redraw(false, false); },
  };
}
