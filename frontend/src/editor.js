// The Editor tab: palette, drawing, property panel and the configuration string, kept in sync
// both ways through the server (POST /api/parse and /api/print), with undo/redo.
import { api } from './api.js';
import { getCatalogue, markArmed, renderPalette } from './catalogue.js';
import { createGraph, layout, renderModel } from './graph.js';
import { History } from './history.js';
import { fsmEditor } from './fsm_editor.js';
import { btEditor } from './bt_editor.js';
import { el } from './properties.js';
import { refreshQuota } from './quota.js';
import * as sm from './software_model.js';
import { confirmDelete } from './confirm_dialog.js';
import { downloadSvg } from './svg_export.js';
import { showError } from './toast.js';

export const DEFAULT_TEXT = '--fsm-config --nstates 1 --s0 10 --rwm0 50';
const $ = (id) => document.getElementById(id);

export function initEditor({ onExec }) {
  const cy = createGraph($('graph'));
  const history = new History();
  const textarea = $('config-text');
  const errorBox = $('config-error');
  let current = { model: null, text: '' };
  let parseSerial = 0;
  let lastParsed = null; // {text as typed, canonical}

  const ctx = {
    cy,
    model: () => current.model,
    mode: () => current.model && current.model.architecture,
    commit,
    arm: (kind, id) => markArmed($('palette'), kind, id),
  };
  const editors = { fsm: fsmEditor(ctx), bt: btEditor(ctx) };
  const active = () => editors[ctx.mode()];

  function showParseError(error) {
    if (!error) { errorBox.hidden = true; errorBox.textContent = ''; return; }
    const body = error.body || {};
    let message = body.error || error.message;
    if (body.token && !message.includes(body.token)) message += ` (token: ${body.token})`;
    errorBox.textContent = message;
    errorBox.dataset.token = body.token || '';
    errorBox.hidden = false;
  }

  function updateChrome() {
    const mode = ctx.mode();
    $('mode-fsm').classList.toggle('on', mode === 'fsm');
    $('mode-bt').classList.toggle('on', mode === 'bt');
    for (const g of document.querySelectorAll('#palette details')) if (mode === 'bt' && g.dataset.flavour === 'maple') g.open = true;
    $('draw-transitions').hidden = mode !== 'fsm';
    for (const id of ['bt-add-selector', 'bt-add-sequence', 'bt-maple']) $(id).hidden = mode !== 'bt';
    $('undo').disabled = !history.canUndo();
    $('redo').disabled = !history.canRedo();
  }

  function showFlavoursUsed() {
    const used = sm.flavoursUsed(current.model, getCatalogue());
    $('flavours-used').textContent = current.model ? `This drawing uses: ${used.join(', ') || 'no modules'}` : '';
    $('flavours-used').classList.toggle('mixed', used.length > 1);
  }

  function renderProperties() {
    const panel = $('properties');
    panel.replaceChildren();
    const sel = cy.$(':selected');
    const editor = active();
    if (!current.model && textarea.value.trim()) {
      panel.append(el('p', { class: 'muted small', text: 'The configuration string does not parse: the drawing comes back once it does.' }));
      return;
    }
    if (!sel.length || !editor) {
      panel.append(el('p', { class: 'muted small', text: editor ? editor.hint() : 'This control software (a neural network) is shown as text only.' }));
      return;
    }
    editor.properties(sel[0], panel);
  }

  /// Shows a snapshot: drawing, string (unless the user is typing it), panels.
  function apply(snapshot, { relayout = false, select = null, keepText = false } = {}) {
    current = snapshot;
    if (select) cy.$(':selected').unselect();
    renderModel(cy, current.model, { relayout });
    if (select) cy.getElementById(select).select();
    if (!keepText) textarea.value = current.text;
    $('config-description').textContent = current.model && current.model.architecture === 'nn' ? 'A neural network: shown as text only.' : '';
    showFlavoursUsed();
    updateChrome();
    renderProperties();
  }

  /// A drawing edit: the server prints the MODEL; its canonical string becomes the text.
  async function commit(model, { select = null, relayout = false } = {}) {
    try {
      const answer = await api('/api/print', { body: { software: model }, quiet: true });
      history.push({ model: answer.software, text: answer.text });
      showParseError(null);
      apply(history.present, { select, relayout });
    } catch (e) {
      showError(`not a valid control software: ${e.message}`);
      renderProperties();
    }
  }

  /// A text edit: the server parses; the drawing follows.
  async function parseText(text, { relayout = true } = {}) {
    const serial = ++parseSerial;
    try {
      const answer = await api('/api/parse', { body: { text }, quiet: true });
      if (serial !== parseSerial) return;
      showParseError(null);
      lastParsed = { text, canonical: answer.text };
      history.push({ model: answer.software, text: answer.text });
      apply(history.present, { relayout, keepText: document.activeElement === textarea });
      if (answer.description) $('config-description').textContent = answer.description;
    } catch (e) {
      if (serial !== parseSerial) return;
      if (e.status === 400) {
        showParseError(e);
        // The old drawing is not what the text says any more: clear it (undo brings it back).
        current = { model: null, text };
        cy.elements().remove();
        $('config-description').textContent = '';
        showFlavoursUsed();
        updateChrome();
        renderProperties();
      } else showError(e.message);
    }
  }

  let debounce = null;
  textarea.addEventListener('input', () => {
    clearTimeout(debounce);
    debounce = setTimeout(() => parseText(textarea.value.trim()), 400);
  });
  textarea.addEventListener('blur', () => {
    if (lastParsed && lastParsed.text === textarea.value.trim()) textarea.value = lastParsed.canonical;
  });

  cy.on('select unselect', () => { clearTimeout(renderProperties.t); renderProperties.t = setTimeout(renderProperties, 0); });

  function undo() { const s = history.undo(); if (s) apply(s); }
  function redo() { const s = history.redo(); if (s) apply(s); }
  function removeSelected() {
    const sel = cy.$(':selected');
    if (sel.length && active()) active().remove(sel[0]);
  }

  $('undo').addEventListener('click', undo);
  $('redo').addEventListener('click', redo);
  $('delete-selected').addEventListener('click', removeSelected);
  $('relayout').addEventListener('click', () => layout(cy, current.model));
  $('fit').addEventListener('click', () => cy.fit(undefined, 30));
  $('export-svg').addEventListener('click', () => downloadSvg(cy));
  $('to-exec').addEventListener('click', () => onExec(current.text));
  $('mode-fsm').addEventListener('click', () => { if (ctx.mode() !== 'fsm') commit(sm.newFsm(), { relayout: true }); });
  $('mode-bt').addEventListener('click', () => { if (ctx.mode() !== 'bt') commit(sm.newMapleTree(), { relayout: true }); });
  $('bt-maple').addEventListener('click', () => commit(sm.newMapleTree(), { relayout: true }));
  $('bt-add-selector').addEventListener('click', () => editors.bt.addComposite('selector'));
  $('bt-add-sequence').addEventListener('click', () => editors.bt.addComposite('sequence'));
  let drawing = false;
  $('draw-transitions').addEventListener('click', () => {
    drawing = !drawing;
    $('draw-transitions').classList.toggle('on', drawing);
    editors.fsm.setDrawMode(drawing);
  });

  document.addEventListener('keydown', (e) => {
    if ($('page-editor').hidden) return;
    const typing = /^(INPUT|TEXTAREA|SELECT)$/.test(document.activeElement?.tagName || '');
    if (typing) return;
    const key = e.key.toLowerCase();
    if ((e.ctrlKey || e.metaKey) && key === 'z' && !e.shiftKey) { e.preventDefault(); undo(); }
    else if ((e.ctrlKey || e.metaKey) && (key === 'y' || (key === 'z' && e.shiftKey))) { e.preventDefault(); redo(); }
    else if (key === 'delete' || key === 'backspace') { e.preventDefault(); removeSelected(); }
  });

  renderPalette($('palette'), (kind, module) => {
    const editor = active();
    if (editor) editor.pick(kind, module);
  });

  // ---- control software saved in a project ----
  const projectSelect = $('software-project');
  // The list is swapped in one step once the answer is here (never emptied while it loads), and an
  // answer that a later refresh overtook is dropped, so two quick refreshes never show both lists.
  let softwareGeneration = 0;
  async function refreshSoftware() {
    const list = $('software-list');
    const generation = ++softwareGeneration;
    if (!projectSelect.value) { list.replaceChildren(); return; }
    const items = await api(`/api/projects/${encodeURIComponent(projectSelect.value)}/software`);
    if (generation !== softwareGeneration) return;
    const rows = [];
    for (const item of items) {
      const project = projectSelect.value;
      const remove = el('button', { type: 'button', class: 'icon', testid: `software-delete-${item.name}`, text: '✕', title: `delete ${item.name}`,
        onclick: async (e) => {
          e.stopPropagation();
          if (!await confirmDelete({ title: `Delete ${item.name}?`, text: `The control software saved as ${item.name} in project ${project} is deleted.` })) return;
          try { await api(`/api/projects/${encodeURIComponent(project)}/software/${encodeURIComponent(item.name)}/delete`, { body: {} }); } catch { return; }
          refreshQuota();
          await refreshSoftware();
        } });
      rows.push(el('li', { title: item.text, testid: `software-${item.name}`, onclick: () => { textarea.value = item.text; parseText(item.text); } },
        el('span', { text: item.name }), el('span', { class: 'muted small' }, 'load', remove)));
    }
    if (!items.length) rows.push(el('li', { class: 'muted small', text: 'nothing saved yet' }));
    list.replaceChildren(...rows);
  }
  async function refreshProjects() {
    const projects = await api('/api/projects');
    const list = Array.isArray(projects) ? projects : projects.projects || [];
    const keep = projectSelect.value;
    projectSelect.replaceChildren(...list.map((p) => el('option', { value: p.name, text: p.name })));
    if (!list.length) projectSelect.append(el('option', { value: '', text: '(create a project in Designs)' }));
    if (list.some((p) => p.name === keep)) projectSelect.value = keep;
    await refreshSoftware();
  }
  projectSelect.addEventListener('change', refreshSoftware);
  $('software-save').addEventListener('click', async () => {
    const name = $('software-name').value.trim();
    if (!projectSelect.value || !name) { showError('choose a project and a name'); return; }
    try {
      await api(`/api/projects/${encodeURIComponent(projectSelect.value)}/software`, { body: { name, text: current.text } });
      refreshQuota();
      await refreshSoftware();
    } catch { /* shown */ }
  });

  updateChrome();
  return {
    cy,
    editors,
    get current() { return current; },
    load(text) { textarea.value = text; return parseText(text); },
    refreshProjects: () => refreshProjects().catch(() => {}),
    resize() { cy.resize(); },
  };
}
