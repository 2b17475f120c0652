// The module catalogue (GET /api/catalogue, made by the C++ catalogue) and the palette drawn from it.
import { api } from './api.js';

let catalogue = null;

export async function loadCatalogue() {
  catalogue = await api('/api/catalogue');
  return catalogue;
}
export function getCatalogue() { return catalogue; }
/// Installs a catalogue that is already at hand (the offline report embeds one).
export function setCatalogue(c) { catalogue = c; }

/// kind: 'behaviour' | 'condition'
export function findModule(kind, id) {
  if (!catalogue) return null;
  const list = kind === 'behaviour' ? catalogue.behaviours : catalogue.conditions;
  return list.find((m) => m.id === id) || null;
}

export function twoDigits(id) { return String(id).padStart(2, '0'); }

export function moduleLabel(kind, id) {
  const m = findModule(kind, id);
  return `${twoDigits(id)} ${m ? m.name : '?'}`;
}

/// Whether parameter spec applies given the other values (the catalogue's active_if rule).
export function parameterActive(spec, values) {
  if (!spec.active_if) return true;
  const v = values[spec.active_if];
  return v !== undefined && spec.active_values.includes(Number(v));
}

export function defaultValue(spec) {
  if (spec.type === 'categorical') return spec.values[0];
  if (spec.type === 'integer') return Math.floor((spec.min + spec.max) / 2);
  return Math.round(((spec.min + spec.max) / 2) * 100) / 100;
}

/// Parameters of a module instance with defaults filled in and inactive ones dropped.
export function completeParameters(kind, id, given = {}) {
  const m = findModule(kind, id);
  if (!m) return { ...given };
  const out = {};
  for (const spec of m.parameters) {
    const v = given[spec.token];
    out[spec.token] = v === undefined ? defaultValue(spec) : v;
  }
  for (const spec of m.parameters) if (!parameterActive(spec, out)) delete out[spec.token];
  return out;
}

export function domainText(spec) {
  if (spec.type === 'categorical') return `one of {${spec.values.join(', ')}}`;
  return `${spec.type === 'integer' ? 'integer' : 'real'} in [${spec.min}, ${spec.max}]`;
}

/// Draws the palette: per flavour, its behaviours and conditions with two-digit ids.
/// onPick(kind, module) is called on a click.
export function renderPalette(container, onPick) {
  container.replaceChildren();
  for (const flavour of catalogue.flavours) {
    const group = document.createElement('details');
    group.className = 'palette-group';
    group.dataset.flavour = flavour.name;
    group.open = flavour.name === 'chocolate';
    const summary = document.createElement('summary');
    summary.textContent = `${flavour.id} · ${flavour.name}`;
    group.append(summary);
    for (const kind of ['behaviour', 'condition']) {
      const list = (kind === 'behaviour' ? catalogue.behaviours : catalogue.conditions).filter((m) => m.flavour === flavour.name);
      if (!list.length) continue;
      const title = document.createElement('div');
      title.className = 'palette-kind';
      title.textContent = kind === 'behaviour' ? 'behaviours' : 'conditions';
      group.append(title);
      for (const m of list) {
        const item = document.createElement('button');
        item.className = `palette-item ${kind}`;
        item.dataset.testid = `palette-${kind}-${twoDigits(m.id)}`;
        item.dataset.kind = kind;
        item.dataset.id = m.id;
        item.title = m.parameters.length ? m.parameters.map((p) => `${p.token}: ${p.meaning}`).join('\n') : 'no parameters';
        const id = document.createElement('span');
        id.className = 'id';
        id.textContent = twoDigits(m.id);
        const name = document.createElement('span');
        name.textContent = m.name;
        const tag = document.createElement('span');  // the flavour, so that mixing flavours is visible
        tag.className = `flavour-tag flavour-${flavour.name}`;
        tag.textContent = flavour.name;
        item.dataset.flavour = flavour.name;
        item.append(id, name, tag);
        item.addEventListener('click', () => onPick(kind, m));
        group.append(item);
      }
    }
    container.append(group);
  }
}

/// Marks the condition that new transitions get.
export function markArmed(container, kind, id) {
  for (const el of container.querySelectorAll('.palette-item')) {
    el.classList.toggle('armed', el.dataset.kind === kind && Number(el.dataset.id) === id);
  }
}
