// The mission editor (Missions tab): a mission written from the page for the common case —
// arena walls of the catalogue's kinds, floor patches, lights, start region, an objective of a
// catalogue kind — started from any mission (catalogue or one's own), drawn live by the server
// as it checks it (the upload's checks and one-line errors, nothing stored), and saved into a
// project as the same JSON file `swarmdesign set-mission` reads. The JSON below the form is
// the whole document: what the form does not cover is edited there, and both stay in step.
import { api } from './api.js';
import { el } from './properties.js';
import { quotaRefused, refreshQuota } from './quota.js';
import { clearError } from './toast.js';

const $ = (id) => document.getElementById(id);
const COLOURS = ['black', 'white', 'gray'];

/// JSON with // and /* */ comments (mission files have them), as JSON.parse reads it.
export function stripComments(text) {
  let out = '';
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (c === '"') {
      const start = i;
      for (i++; i < text.length && text[i] !== '"'; i++) if (text[i] === '\\') i++;
      out += text.slice(start, i + 1);
    } else if (c === '/' && text[i + 1] === '/') {
      while (i < text.length && text[i] !== '\n') i++;
      out += '\n';
    } else if (c === '/' && text[i + 1] === '*') {
      i = text.indexOf('*/', i + 2);
      if (i < 0) break;
      i++;
    } else {
      out += c;
    }
  }
  return out;
}

const num = (v, fallback = 0) => (Number.isFinite(Number(v)) && v !== '' ? Number(v) : fallback);

export function initMissionEditor({ onSaved }) {
  let doc = null;        // the mission being written
  let timer = null;
  let asked = 0;         // the last preview asked for: older answers are dropped
  const objectives = new Map();  // objective kind -> an objective of that kind from the catalogue

  // ---- the form, drawn from the document ----
  const field = (label, value, onInput, attrs = {}) => el('label', { class: 'inline small' }, label,
    el('input', { value: String(value), size: attrs.size || '5', ...attrs, oninput: (e) => onInput(e.target.value) }));

  function regionFields(region, onChange) {
    const kind = region.rectangle ? 'rectangle' : region.circle ? 'circle' : 'other';
    const shape = el('select', { onchange: (e) => {
      const c = (region.circle || region.rectangle || {}).center || [0, 0];
      const next = e.target.value === 'circle' ? { circle: { center: c, radius: 0.3 } } : { rectangle: { center: c, size: [0.5, 0.5] } };
      onChange(next, true);
    } }, ...['circle', 'rectangle'].map((k) => el('option', { value: k, text: k })));
    if (kind === 'other') return [el('span', { class: 'muted small', text: 'a polygon: edit it in the JSON' })];
    shape.value = kind;
    const r = region[kind];
    const set = (mutate) => { mutate(r); onChange(region, false); };
    const parts = [shape,
      field('x', r.center[0], (v) => set((o) => { o.center = [num(v), o.center[1]]; })),
      field('y', r.center[1], (v) => set((o) => { o.center = [o.center[0], num(v)]; }))];
    if (kind === 'circle') parts.push(field('radius', r.radius, (v) => set((o) => { o.radius = num(v, 0.1); })));
    else parts.push(field('w', r.size[0], (v) => set((o) => { o.size = [num(v, 0.1), o.size[1]]; })),
      field('h', r.size[1], (v) => set((o) => { o.size = [o.size[0], num(v, 0.1)]; })));
    return parts;
  }

  function renderForm() {
    const form = $('me-form');
    if (!doc) { form.replaceChildren(); return; }
    doc.arena = doc.arena || {};
    doc.arena.floor = doc.arena.floor || {};
    const floor = doc.arena.floor;
    floor.patches = floor.patches || [];
    doc.arena.lights = doc.arena.lights || [];
    doc.arena.walls = doc.arena.walls || [];
    const again = () => { renderForm(); changed(); };

    // Walls: the catalogue's dodecagon-like polygons, or a rectangle of four boxes.
    const polygon = doc.arena.walls.length === 1 && doc.arena.walls[0].regular_polygon;
    const rectangle = rectangleOf(doc.arena.walls);
    const wallKind = el('select', { testid: 'me-walls', onchange: (e) => {
      if (e.target.value === 'polygon') doc.arena.walls = [{ regular_polygon: { sides: 12, apothem: 1.231, thickness: 0.01, height: 0.08 } }];
      if (e.target.value === 'rectangle') doc.arena.walls = rectangleWalls(2.5, 2.5);
      if (e.target.value === 'none') doc.arena.walls = [];
      again();
    } }, ...[['polygon', 'regular polygon'], ['rectangle', 'rectangle'], ['none', 'no walls'], ['json', 'as in the JSON']]
      .map(([v, t]) => el('option', { value: v, text: t })));
    wallKind.value = polygon ? 'polygon' : doc.arena.walls.length === 0 ? 'none' : rectangle ? 'rectangle' : 'json';
    const wallFields = [];
    if (polygon) {
      const p = doc.arena.walls[0].regular_polygon;
      wallFields.push(field('sides', p.sides, (v) => { p.sides = Math.round(num(v, 12)); delete p.length; changed(); }, { testid: 'me-sides', size: '3' }),
        field('apothem (m)', p.apothem, (v) => { p.apothem = num(v, 1); delete p.length; changed(); }, { testid: 'me-apothem' }));
    } else if (rectangle) {
      const { w, h } = rectangle;
      const resize = (nw, nh) => { doc.arena.walls = rectangleWalls(nw, nh); changed(); };
      wallFields.push(field('width (m)', w, (v) => resize(num(v, 1), rectangleOf(doc.arena.walls).h), { testid: 'me-width' }),
        field('depth (m)', h, (v) => resize(rectangleOf(doc.arena.walls).w, num(v, 1)), { testid: 'me-depth' }));
    }

    const background = el('select', { testid: 'me-background', onchange: (e) => { floor.background = e.target.value; changed(); } },
      ...COLOURS.map((c) => el('option', { value: c, text: c })));
    background.value = floor.background || 'gray';

    const patches = floor.patches.map((p, i) => {
      const colour = el('select', { onchange: (e) => { p.color = e.target.value; changed(); } }, ...COLOURS.map((c) => el('option', { value: c, text: c })));
      colour.value = p.color;
      return el('div', { class: 'me-row', testid: `me-patch-${i}` }, ...regionFields(p.region, (region, redraw) => { p.region = region; if (redraw) again(); else changed(); }),
        colour, el('button', { type: 'button', class: 'icon', text: '✕', title: 'remove this patch', onclick: () => { floor.patches.splice(i, 1); again(); } }));
    });
    const lights = doc.arena.lights.map((l, i) => el('div', { class: 'me-row', testid: `me-light-${i}` },
      field('x', l.position[0], (v) => { l.position[0] = num(v); changed(); }),
      field('y', l.position[1], (v) => { l.position[1] = num(v); changed(); }),
      field('height', l.position[2] ?? 0.4, (v) => { l.position[2] = num(v, 0.4); changed(); }),
      field('intensity', l.intensity ?? 1, (v) => { l.intensity = num(v, 1); changed(); }),
      el('button', { type: 'button', class: 'icon', text: '✕', title: 'remove this light', onclick: () => { doc.arena.lights.splice(i, 1); again(); } })));

    const objective = el('select', { testid: 'me-objective', onchange: (e) => { doc.objective = fitted(objectives.get(e.target.value), floor.patches); again(); } },
      ...[...objectives.keys()].map((k) => el('option', { value: k, text: k.replaceAll('_', ' ') })));
    if (doc.objective && !objectives.has(doc.objective.type)) objective.append(el('option', { value: doc.objective.type, text: doc.objective.type }));
    objective.value = doc.objective ? doc.objective.type : '';
    const direction = el('select', { testid: 'me-direction', onchange: (e) => { doc.objective.direction = e.target.value; changed(); } },
      ...['maximize', 'minimize'].map((d) => el('option', { value: d, text: d })));
    direction.value = (doc.objective && doc.objective.direction) || 'maximize';

    form.replaceChildren(
      el('div', { class: 'me-row' },
        field('file name', $('me-name').value || doc.name, (v) => { $('me-name').value = v; doc.name = v; changed(); }, { testid: 'me-file-name', size: '14' }),
        field('title', doc.title || '', (v) => { doc.title = v; changed(); }, { testid: 'me-title', size: '28' })),
      el('div', { class: 'me-row' },
        field('duration (s)', doc.duration, (v) => { doc.duration = num(v, 120); changed(); }, { testid: 'me-duration' }),
        field('robots', doc.robots, (v) => { doc.robots = Math.round(num(v, 20)); changed(); }, { testid: 'me-robots', size: '4' })),
      el('h4', { text: 'Arena' }), el('div', { class: 'me-row' }, el('label', { class: 'inline small' }, 'walls', wallKind), ...wallFields),
      el('div', { class: 'me-row' }, el('label', { class: 'inline small' }, 'floor', background)),
      el('h4', {}, 'Floor patches ', el('button', { type: 'button', class: 'link small', testid: 'me-add-patch', text: '+ add',
        onclick: () => { floor.patches.push({ region: { circle: { center: [0, 0], radius: 0.3 } }, color: 'black' }); again(); } })),
      ...patches,
      el('h4', {}, 'Lights ', el('button', { type: 'button', class: 'link small', testid: 'me-add-light', text: '+ add',
        onclick: () => { doc.arena.lights.push({ position: [0, -1.5, 0.4], intensity: 3.0, color: 'yellow' }); again(); } })),
      ...lights,
      el('h4', { text: 'Start region' }),
      el('div', { class: 'me-row', testid: 'me-start' }, ...regionFields(doc.start || { circle: { center: [0, 0], radius: 1 } },
        (region, redraw) => { doc.start = region; if (redraw) again(); else changed(); })),
      el('h4', { text: 'Objective' }),
      el('div', { class: 'me-row' }, objective, direction),
      el('p', { class: 'muted small', text: 'A kind chosen here scores on this floor: its regions are the black patches (a foraging objective\'s sources; its nest stays the example\'s). Its other parameters are in the JSON below (objective), as the missions reference describes them.' }));
  }

  /// An objective of another mission's kind, its regions taken from this mission's floor: the
  /// example's regions belong to its own arena (another mission's black circles, say), and the
  /// mission edited would score robots on areas it does not have.
  function fitted(example, patches) {
    const objective = structuredClone(example);
    const black = patches.filter((p) => p.color === 'black').map((p) => structuredClone(p.region));
    if (!black.length) return objective;
    if (objective.region) objective.region = black[0];
    if (Array.isArray(objective.regions)) objective.regions = black;
    if (Array.isArray(objective.sources)) {
      const value = objective.sources.length ? objective.sources[0].value : 1;
      objective.sources = black.map((region) => ({ region, value }));
    }
    return objective;
  }

  /// Four boxes around a w × h rectangle centred on the origin.
  function rectangleWalls(w, h) {
    const t = 0.01;
    return [
      { box: { center: [0, h / 2], size: [w, t] } },
      { box: { center: [0, -h / 2], size: [w, t] } },
      { box: { center: [w / 2, 0], size: [t, h] } },
      { box: { center: [-w / 2, 0], size: [t, h] } },
    ];
  }

  /// {w, h} when the walls are rectangleWalls(w, h), else null.
  function rectangleOf(walls) {
    if (walls.length !== 4 || !walls.every((x) => x.box && x.box.center && x.box.size)) return null;
    const w = walls[0].box.size[0], h = walls[2].box.size[1];
    const same = JSON.stringify(walls.map((x) => [x.box.center, x.box.size])) === JSON.stringify(rectangleWalls(w, h).map((x) => [x.box.center, x.box.size]));
    return same ? { w, h } : null;
  }

  // ---- the document, the JSON text and the drawing ----
  const text = () => JSON.stringify(doc, null, 2);

  function changed() {
    $('me-json').value = text();
    clearTimeout(timer);
    timer = setTimeout(preview, 250);
  }

  async function preview() {
    const project = $('me-project').value;
    if (!doc || !project) return;
    const n = ++asked;
    try {
      const answer = await api(`/api/projects/${encodeURIComponent(project)}/missions/preview`,
        { body: { name: $('me-name').value || 'draft', text: $('me-json').value }, quiet: true });
      if (n !== asked) return;
      $('me-drawing').innerHTML = answer.svg;  // the server's own drawing (it escapes every text)
      say(`${answer.mission.title || answer.mission.name}: ${answer.mission.robots} robots, ${answer.mission.duration_s} s, ${answer.mission.objective} (${answer.mission.direction})`, 'done');
      $('me-save').disabled = false;
    } catch (e) {
      if (n !== asked) return;
      say(e.message, 'error');
      $('me-save').disabled = true;
    }
  }

  function say(message, kind) {
    $('me-status').textContent = message;
    $('me-status').className = `small ${kind}`;
  }

  async function startFrom(name) {
    try {
      const answer = await api(`/api/missions/text?name=${encodeURIComponent(name)}`, { quiet: true });
      doc = JSON.parse(stripComments(answer.text));
      delete doc.argos;  // the ARGoS loop functions score the original, not this mission
      doc.name = `my-${answer.name.replace(/[^A-Za-z0-9_-]/g, '-')}`.slice(0, 64);
      // Its own title, so that the missions list tells the copy from the original.
      doc.title = `${doc.title || answer.name} (copy)`;
      $('me-name').value = doc.name;
      renderForm();
      changed();
    } catch (e) {
      say(e.message, 'error');
    }
  }

  $('me-template').addEventListener('change', (e) => startFrom(e.target.value));
  $('me-json').addEventListener('input', () => {
    try {
      doc = JSON.parse(stripComments($('me-json').value));
      renderForm();
      clearTimeout(timer);
      timer = setTimeout(preview, 400);
    } catch (e) {
      say(`not valid JSON: ${e.message}`, 'error');
      $('me-save').disabled = true;
    }
  });
  $('me-project').addEventListener('change', preview);
  $('me-editor').addEventListener('submit', async (e) => {
    e.preventDefault();
    const project = $('me-project').value;
    try {
      const saved = await api(`/api/projects/${encodeURIComponent(project)}/missions`, { body: { name: $('me-name').value, text: $('me-json').value }, quiet: true });
      say(`saved as ${project}/missions/${saved.file_name}.json: choose it for a new project or try it in Exec`, 'done');
      clearError();  // a refusal shown before is stale
      refreshQuota();
      await onSaved(saved);
    } catch (err) {
      quotaRefused(err);
      say(err.message, 'error');
    }
  });

  return {
    /// The catalogue and the user's missions: templates, and the objective kinds they use.
    async setMissions(list) {
      const keep = $('me-template').value;
      $('me-template').replaceChildren(el('option', { value: '', text: 'start from…' }),
        ...list.map((m) => el('option', { value: m.name, text: `${m.source === 'catalogue' || !m.name.includes('/') ? m.name : m.name.split('/').slice(-3).join('/')} — ${m.title}` })));
      if (list.some((m) => m.name === keep)) $('me-template').value = keep;
      for (const m of list) {
        if (m.name.includes('/') || objectives.has(m.objective)) continue;
        try {
          const answer = await api(`/api/missions/text?name=${encodeURIComponent(m.name)}`, { quiet: true });
          const objective = JSON.parse(stripComments(answer.text)).objective;
          if (objective && !objectives.has(objective.type)) objectives.set(objective.type, objective);
        } catch { /* a kind fewer */ }
      }
      if (doc) renderForm();
    },
    async refreshProjects() {
      const projects = await api('/api/projects', { quiet: true }).catch(() => []);
      const before = $('me-project').value;
      $('me-project').replaceChildren(...projects.map((p) => el('option', { value: p.name, text: p.name })));
      if (projects.some((p) => p.name === before)) $('me-project').value = before;
      $('me-save').disabled = !projects.length || !doc;
    },
    get document() { return doc; },
  };
}
