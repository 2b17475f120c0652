// One run's stream (server-sent events: scene, frames, end, failure), kept whole in typed arrays
// so that the viewer can scrub over it without asking again.
export class RunData {
  constructor(scene) {
    this.scene = scene;
    this.robots = scene.robots;
    this.ticks = scene.ticks;
    const size = (scene.ticks + 1) * scene.robots;
    this.x = new Float64Array(size);
    this.y = new Float64Array(size);
    this.yaw = new Float64Array(size);
    this.led = new Int32Array(size);
    this.state = new Int32Array(size);
    this.objective = new Float64Array(scene.ticks + 1);
    this.received = 0; // ticks 0 .. received-1 are here
  }

  addFrames(f) {
    const n = this.robots;
    const at = f.first * n;
    this.x.set(f.x, at);
    this.y.set(f.y, at);
    this.yaw.set(f.yaw, at);
    this.led.set(f.led, at);
    this.state.set(f.state, at);
    this.objective.set(f.objective, f.first);
    this.received = Math.max(this.received, f.first + f.count);
  }
}

/// Opens /api/runs/ID/stream; handlers: scene(run), frames(run), end({score, scoreText, ticks}), failure(message).
export function openRun(id, handlers) {
  const source = new EventSource(`/api/runs/${encodeURIComponent(id)}/stream`);
  let run = null;
  let done = false;
  const finish = () => { done = true; source.close(); };
  source.addEventListener('scene', (e) => {
    run = new RunData(JSON.parse(e.data));
    handlers.scene(run);
  });
  source.addEventListener('frames', (e) => {
    if (!run) return;
    run.addFrames(JSON.parse(e.data));
    handlers.frames(run);
  });
  source.addEventListener('end', (e) => {
    finish();
    const data = JSON.parse(e.data);
    // The number exactly as the server wrote it (17 significant digits), not re-printed.
    const raw = /"score"\s*:\s*([-+0-9.eE]+)/.exec(e.data);
    handlers.end({ ...data, scoreText: raw ? raw[1] : String(data.score) });
  });
  source.addEventListener('failure', (e) => {
    finish();
    let message = e.data;
    try { message = JSON.parse(e.data).error; } catch { /* keep the text */ }
    handlers.failure(message);
  });
  source.onerror = () => {
    if (done) return;
    finish();
    handlers.failure('the run stream broke off');
  };
  return { close: finish };
}
