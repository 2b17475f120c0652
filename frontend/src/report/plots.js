// Plotly with the report's look: white, the page's font, no tool bar, fixed sizes that print.
import Plotly from 'plotly.js-cartesian-dist-min';

import { directionText } from './report_data.js';

const FONT = 'system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif';
const AXIS_COLOUR = '#444444';
const GRID_COLOUR = '#e6e6e6';

const pending = [];

export function axis(title, extra = {}) {
  return {
    title: { text: title, font: { size: 12 } },
    showline: true, linecolor: AXIS_COLOUR, linewidth: 1, mirror: false,
    ticks: 'outside', tickcolor: AXIS_COLOUR, ticklen: 4,
    gridcolor: GRID_COLOUR, zeroline: false, automargin: true,
    ...extra,
  };
}

export function baseLayout(extra = {}) {
  return {
    font: { family: FONT, size: 12, color: '#222222' },
    paper_bgcolor: '#ffffff', plot_bgcolor: '#ffffff',
    margin: { l: 60, r: 16, t: 36, b: 48 },
    showlegend: false,
    hoverlabel: { font: { family: FONT } },
    ...extra,
  };
}

export function plotTitle(text) {
  return { text, x: 0, xref: 'paper', xanchor: 'left', font: { size: 14 } };
}

/// Written across an empty plot (a mission without finished designs yet).
export function emptyNote(text) {
  return [{ text, showarrow: false, xref: 'paper', yref: 'paper', x: 0.5, y: 0.5, font: { color: '#888888', size: 13 } }];
}

/// Draws into container; the promise is remembered so the page knows when all plots are done.
/// A condition's colour with some transparency (box fills, joining lines).
export function translucent(hex, alpha) {
  const n = parseInt(hex.slice(1), 16);
  return `rgba(${(n >> 16) & 255},${(n >> 8) & 255},${n & 255},${alpha})`;
}

/// The layout of a mission's plot with one slot per condition along x (box plots).
export function conditionsLayout(report, mission, container, ticks, empty) {
  return baseLayout({
    title: plotTitle(mission.name),
    width: container.clientWidth, height: 340,
    xaxis: axis('', {
      tickmode: 'array', tickvals: report.conditions.map((_, i) => i), ticktext: ticks,
      range: [-0.6, report.conditions.length - 0.4], showgrid: false, ticks: '',
    }),
    yaxis: axis(`score (${directionText(mission)})`),
    annotations: empty ? emptyNote(empty) : [],
  });
}

export function drawPlot(container, traces, layout) {
  const done = Plotly.newPlot(container, traces, layout, {
    displayModeBar: false, responsive: false, showTips: false, scrollZoom: false,
  });
  pending.push(done);
  return done;
}

export function allPlotsDrawn() { return Promise.all(pending); }
