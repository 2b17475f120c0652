// The Exec tab: start a run (POST /api/runs), keep its stream, play / pause / step / scrub it on
// the canvas, plot the objective, show the final score and the robots per state.
import { api } from './api.js';
import { download, framePng, frameSvg, recordVideo } from './exec_export.js';
import { createGraph, renderModel, setCounts } from './graph.js';
import { shortName } from './missions.js';
import { linePlot } from './plot.js';
import { el } from './properties.js';
import { openRun } from './run_stream.js';
import { describeIndex } from './software_model.js';
import { Viewer } from './viewer.js';

const $ = (id) => document.getElementById(id);

export function initExec() {
  const viewer = new Viewer($('viewer'));
  const graph = createGraph($('exec-graph'), { readOnly: true });
  let plot = null;
  let stream = null;
  let run = null;
  let tick = 0;
  let playing = false;
  let ended = false;
  let selected = -1;
  let carry = 0;
  let last = 0;
  let dirty = true;
  let plotDirty = false;
  let recording = false;  // a video is being recorded: the download buttons wait
  const timeline = $('timeline');

  function speed() { return $('speed').value; }

  function setPlaying(on) {
    playing = on;
    $('play').textContent = playing ? 'Pause' : 'Play';
    last = performance.now();
    carry = 0;
  }

  function showRobot() {
    const box = $('robot-info');
    if (!run || selected < 0 || run.received === 0) {
      box.replaceChildren(el('p', { class: 'muted small', text: 'Click a robot.' }));
      return;
    }
    const t = Math.min(tick, run.received - 1);
    const i = t * run.robots + selected;
    const led = run.led[i];
    box.replaceChildren(
      el('div', { class: 'props-title', text: `Robot ${selected}` }),
      el('div', { testid: 'robot-state', id: 'robot-state', text: describeIndex(run.scene.software, run.state[i]) }),
      el('div', { class: 'small muted mono', text: `x ${run.x[i].toFixed(3)}  y ${run.y[i].toFixed(3)}  yaw ${run.yaw[i].toFixed(2)}` }),
      el('div', { class: 'small muted mono', text: `LED ${led ? `#${led.toString(16).padStart(6, '0')}` : 'off'}` }));
  }

  function counts() {
    const t = Math.min(tick, run.received - 1);
    const c = [];
    for (let r = 0; r < run.robots; r++) {
      const s = run.state[t * run.robots + r];
      c[s] = (c[s] || 0) + 1;
    }
    return c;
  }

  function render() {
    if (!run) { viewer.draw(0); return; }
    viewer.draw(tick, { trails: $('show-trails').checked, links: $('show-links').checked, selected });
    const shown = Math.min(tick, Math.max(0, run.received - 1));
    $('tick-label').textContent = `tick ${shown} / ${run.ticks}  ·  ${(shown * run.scene.tick_seconds).toFixed(1)} s`;
    timeline.value = String(shown);
    if (run.received > 0) {
      $('objective-now').textContent = String(run.objective[shown]);
      setCounts(graph, run.scene.software && run.scene.software.architecture !== 'nn' ? counts() : null);
      if (plot) plot.setMarker(shown * run.scene.tick_seconds);
    }
    showRobot();
  }

  function updatePlot() {
    if (!plot || !run) return;
    const n = run.received;
    const xs = new Array(n);
    for (let t = 0; t < n; t++) xs[t] = t * run.scene.tick_seconds;
    plot.setData(xs, Array.from(run.objective.subarray(0, n)));
  }

  function frame(now) {
    if (run && playing && run.received > 0) {
      const s = speed();
      const lastTick = run.received - 1;
      if (s === 'max') tick = lastTick;
      else if (s === 'frame') tick = Math.min(tick + 1, lastTick);
      else {
        carry += ((now - last) / 1000) * Number(s) / run.scene.tick_seconds;
        const whole = Math.floor(carry);
        carry -= whole;
        tick = Math.min(tick + whole, lastTick);
      }
      if (tick >= run.ticks || (ended && tick >= lastTick)) setPlaying(false);
      dirty = true;
    }
    last = now;
    if (plotDirty) { updatePlot(); plotDirty = false; }
    if (dirty) {
      render();
      dirty = false;
      window.__sdFramesDrawn = (window.__sdFramesDrawn || 0) + 1;  // bench/web_viewer.mjs
    }
    requestAnimationFrame(frame);
  }
  requestAnimationFrame(frame);

  /// Nothing of the previous run stays on screen once another is asked for (even if refused).
  function clearRun() {
    run = null;
    viewer.run = null;
    ended = false;
    tick = 0;
    selected = -1;
    setPlaying(false);
    $('final-score').textContent = '';
    delete $('final-score').dataset.value;
    $('tick-label').textContent = '';
    $('objective-now').textContent = '';
    $('export-status').textContent = '';  // "video saved" spoke of the run before
    timeline.max = '0';
    timeline.value = '0';
    delete timeline.dataset.received;
    setCounts(graph, null);
    graph.elements().remove();
    if (plot) { plot.setData([], []); plot.setMarker(null); }
    showRobot();
    updateDownloads();
  }

  function updateDownloads() {
    const ready = !!(run && run.received > 0) && !recording;
    for (const id of ['download-png', 'download-svg']) $(id).disabled = !ready;
    $('download-video').disabled = !ready || !ended;
  }

  async function start() {
    const text = $('exec-text').value.trim();
    const mission = $('exec-mission').value;
    const seed = Number($('exec-seed').value);
    const reality = $('exec-reality').value;
    const sample = Number($('exec-sample').value);
    if (stream) stream.close();
    stream = null;
    clearRun();
    $('exec-status').textContent = 'starting…';
    dirty = true;
    let answer;
    const started = performance.now();  // Exec pressed: the first frame is timed from here
    window.__sdFirstFrameMs = 0;
    try {
      answer = await api('/api/runs', { body: reality ? { text, mission, seed, pseudo_reality: reality, sample } : { text, mission, seed } });
    } catch (e) {
      $('exec-status').textContent = `refused: ${e.message}`;
      return;
    }
    const p = answer.pseudo_reality;
    const world = p ? `, in sample ${p.sample} of pseudo-reality ${p.name}` : '';
    $('exec-status').dataset.world = p ? `${p.spec}#${p.sample}` : '';
    $('exec-status').textContent = `run ${answer.id}: waiting for the scene…`;
    stream = openRun(answer.id, {
      scene(r) {
        run = r;
        viewer.setScene(r);
        viewer.onready = () => { dirty = true; };
        timeline.max = String(r.ticks);
        renderModel(graph, r.scene.software, { relayout: true });
        if (!plot) plot = linePlot($('objective-plot'), { xLabel: 'time (s)', yLabel: 'objective', height: 160 });
        $('exec-status').textContent = `run ${answer.id}: ${r.scene.mission.name}, seed ${r.scene.seed}, ${r.robots} robots${world}`;
        setPlaying(true);
        dirty = true;
      },
      frames(r) {
        if (r.received && !window.__sdFirstFrameMs) window.__sdFirstFrameMs = performance.now() - started;
        timeline.dataset.received = String(r.received);
        if ($('download-png').disabled) updateDownloads();
        plotDirty = true;
        dirty = true;
      },
      end(result) {
        ended = true;
        window.__sdEndMs = performance.now() - started;  // bench/web_viewer.mjs
        $('final-score').textContent = result.scoreText;
        $('final-score').dataset.value = String(result.score);
        $('exec-status').textContent = `run ${answer.id} complete: ${result.ticks} ticks${world}`;
        updateDownloads();
        dirty = true;
      },
      failure(message) {
        $('exec-status').textContent = `run failed: ${message}`;
        updateDownloads();
      },
    });
  }

  // ---- downloads ----
  const drawOptions = () => ({ trails: $('show-trails').checked, links: $('show-links').checked, selected });
  const shownTick = () => Math.min(tick, Math.max(0, run.received - 1));
  $('download-png').addEventListener('click', async () => {
    if (!run || !viewer.image) return;
    const { blob, name } = await framePng(viewer, run, shownTick(), drawOptions(), Number($('video-height').value));
    download(blob, name);
  });
  $('download-svg').addEventListener('click', () => {
    if (!run) return;
    const { blob, name } = frameSvg(run, shownTick(), drawOptions());
    download(blob, name);
  });
  $('download-video').addEventListener('click', async () => {
    if (!run || !ended || recording || !viewer.image) return;
    const recorded = run;
    const speedX = Number($('video-speed').value);
    const last = recorded.received - 1;
    const seconds = (last * recorded.scene.tick_seconds) / speedX;
    recording = true;
    updateDownloads();
    try {
      const { blob, name } = await recordVideo(viewer, recorded, {
        speed: speedX, height: Number($('video-height').value), options: drawOptions(), last,
        onProgress: (f) => { $('export-status').textContent = `recording the video (${seconds.toFixed(0)} s long): ${Math.round(f * 100)} %`; },
      });
      download(blob, name);
      $('export-status').textContent = `video saved: ${name} (${(blob.size / 1e6).toFixed(1)} MB)`;
    } catch (e) {
      $('export-status').textContent = `the video could not be recorded: ${e.message}`;
    } finally {
      recording = false;
      updateDownloads();
    }
  });

  $('exec-run').addEventListener('click', start);
  // The robot models a run may use: the mission's own, or a sample of a shipped pseudo-reality.
  $('exec-reality').addEventListener('change', () => { $('exec-sample').disabled = !$('exec-reality').value; });
  api('/api/pseudo-realities', { quiet: true }).then((list) => {
    $('exec-reality').append(...list.map((p) => el('option', { value: p.name, text: `pseudo-reality ${p.name}`, title: p.description })));
  }).catch(() => {});
  $('play').addEventListener('click', () => {
    if (!run) return;
    if (!playing && tick >= run.received - 1 && ended) tick = 0;
    setPlaying(!playing);
  });
  $('step').addEventListener('click', () => {
    if (!run) return;
    setPlaying(false);
    tick = Math.min(tick + 1, Math.max(0, run.received - 1));
    dirty = true;
  });
  timeline.addEventListener('input', () => {
    if (!run) return;
    setPlaying(false);
    tick = Math.min(Number(timeline.value), Math.max(0, run.received - 1));
    dirty = true;
  });
  for (const id of ['show-trails', 'show-links']) $(id).addEventListener('change', () => { dirty = true; });
  $('viewer').addEventListener('click', (e) => {
    selected = viewer.pick(e.clientX, e.clientY, tick);
    dirty = true;
  });
  window.addEventListener('resize', () => { dirty = true; });

  return {
    /// Fills the form; with `go` starts the run at once.
    prepare({ text, mission, seed, go = false }) {
      if (text !== undefined) $('exec-text').value = text;
      if (mission) $('exec-mission').value = mission;
      if (seed !== undefined) $('exec-seed').value = String(seed);
      if (go) start();
    },
    setMissions(missions) {
      const select = $('exec-mission');
      const keep = select.value;
      select.replaceChildren(...missions.map((m) => el('option', { value: m.name, text: `${shortName(m)} — ${m.title}`, title: m.name })));
      if (missions.some((m) => m.name === keep)) select.value = keep;
    },
    shown() { graph.resize(); graph.fit(undefined, 15); dirty = true; },
    graph,
    get run() { return run; },
    get tick() { return tick; },
    selectRobot(i) { selected = i; dirty = true; },
    seek(t) { setPlaying(false); tick = t; dirty = true; },
  };
}
