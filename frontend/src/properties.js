// Building blocks of the property panel: module selects and parameter fields with the
// catalogue's domains (integer/real ranges, categorical values, active_if).
import { domainText, getCatalogue, parameterActive, twoDigits, findModule } from './catalogue.js';

export function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'testid') e.dataset.testid = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else if (k === 'text') e.textContent = v;
    else e.setAttribute(k, v);
  }
  e.append(...children);
  return e;
}

/// A <select> of every module of a kind, grouped by flavour.
export function moduleSelect(kind, current, onChange, testid) {
  const c = getCatalogue();
  const select = el('select', { testid, id: testid });
  for (const f of c.flavours) {
    const group = el('optgroup', { label: f.name });
    for (const m of (kind === 'behaviour' ? c.behaviours : c.conditions).filter((x) => x.flavour === f.name)) {
      const o = el('option', { value: m.id, text: `${twoDigits(m.id)} ${m.name}` });
      if (m.id === current) o.selected = true;
      group.append(o);
    }
    if (group.children.length) select.append(group);
  }
  select.addEventListener('change', () => onChange(Number(select.value)));
  return select;
}

export function validValue(spec, raw) {
  const v = Number(raw);
  if (raw === '' || !Number.isFinite(v)) return null;
  if (spec.type === 'categorical') return spec.values.includes(v) ? v : null;
  if (v < spec.min || v > spec.max) return null;
  if (spec.type === 'integer' && !Number.isInteger(v)) return null;
  return v;
}

/// Fields for the parameters of `module` ({id, parameters}); onChange(token, value) on a valid edit.
export function parameterFields(kind, module, onChange) {
  const spec = findModule(kind, module.id);
  const box = el('div', { class: 'params' });
  if (!spec) return box;
  box.append(el('div', { class: `flavour-badge flavour-${spec.flavour}`, testid: 'module-flavour', text: `flavour: ${spec.flavour}` }));
  if (!spec.parameters.length) box.append(el('p', { class: 'muted small', text: 'no parameters' }));
  for (const p of spec.parameters) {
    if (!parameterActive(p, module.parameters)) continue;
    const id = `param-${p.token}`;
    const value = module.parameters[p.token];
    let input;
    if (p.type === 'categorical') {
      input = el('select', { id, testid: id });
      for (const v of p.values) {
        const o = el('option', { value: v, text: String(v) });
        if (v === value) o.selected = true;
        input.append(o);
      }
    } else {
      input = el('input', { id, testid: id, type: 'number', min: p.min, max: p.max, step: p.type === 'integer' ? 1 : 'any' });
      input.value = value === undefined ? '' : String(value);
    }
    input.addEventListener('change', () => {
      const v = validValue(p, input.value);
      input.setCustomValidity(v === null ? `${p.token} must be ${domainText(p)}` : '');
      input.reportValidity();
      if (v !== null) onChange(p.token, v);
    });
    box.append(el('div', { class: 'param' },
      el('label', { for: id, text: `${p.token} — ${p.meaning}` }),
      input,
      el('div', { class: 'domain', text: domainText(p) })));
  }
  return box;
}
