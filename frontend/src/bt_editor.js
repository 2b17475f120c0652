// Behaviour-tree editing (Maple's shape by default: a sequence* root over selectors of a
// condition and an action): palette modules become children of the selected composite node.
import { getCatalogue } from './catalogue.js';
import { el, moduleSelect, parameterFields } from './properties.js';
import * as sm from './software_model.js';
import { showError } from './toast.js';

const COMPOSITES = ['selector', 'selector*', 'sequence', 'sequence*', 'negation'];

export function btEditor(ctx) {
  const { cy } = ctx;

  function targetParent(model) {
    const sel = cy.$('node:selected');
    if (sel.length && sm.isComposite(model.nodes[sel.data('index')])) return sel.data('index');
    return 0;
  }
  function add(node) {
    const model = ctx.model();
    const parent = targetParent(model);
    if ((model.nodes[parent].children || []).length >= getCatalogue().limits.bt_children) {
      showError(`a node has at most ${getCatalogue().limits.bt_children} children`);
      return;
    }
    ctx.commit(sm.addBtChild(model, parent, node), { select: `n${model.nodes.length}` });
  }

  return {
    pick(kind, module) { add(sm.btNode(kind, module.id)); },
    addComposite(type) { add({ type, children: [] }); },
    remove(element) {
      if (element.data('index') === 0) { showError('the root stays; start a new tree instead'); return; }
      ctx.commit(sm.removeBtNode(ctx.model(), element.data('index')));
    },
    properties(element, panel) {
      if (element.data('kind') !== 'btnode') return;
      const model = ctx.model();
      const i = element.data('index');
      const node = model.nodes[i];
      const name = sm.btNodeNames(model)[i] ?? `node ${i}`;  // as the configuration string names it
      panel.append(el('div', { class: 'props-title', testid: 'node-name', text: `Node ${name}: ${node.type}` }));
      if (sm.isComposite(node)) {
        const select = el('select', { testid: 'bt-type', id: 'bt-type' });
        for (const t of COMPOSITES) {
          const o = el('option', { value: t, text: t });
          if (t === node.type) o.selected = true;
          select.append(o);
        }
        select.addEventListener('change', () => ctx.commit(sm.setBtType(model, i, select.value)));
        panel.append(el('label', { text: 'Type' }), select,
          el('p', { class: 'muted small', text: 'Palette clicks add children to this node.' }));
      } else {
        const kind = node.type === 'action' ? 'behaviour' : 'condition';
        panel.append(el('label', { text: kind === 'behaviour' ? 'Behaviour' : 'Condition' }),
          moduleSelect(kind, node.module.id, (id) => ctx.commit(sm.setBtModule(model, i, id)), 'module-select'),
          parameterFields(kind, node.module, (token, v) =>
            ctx.commit(sm.setParameter(model, (m) => m.nodes[i].module, kind, token, v))));
        if (node.type === 'action') {
          const input = el('input', { id: 'bt-success', testid: 'bt-success', type: 'number', min: 0, max: 1, step: 'any' });
          input.value = String(node.success ?? 0);
          input.addEventListener('change', () => {
            const v = Number(input.value);
            if (input.value !== '' && v >= 0 && v <= 1) ctx.commit(sm.setBtSuccess(model, i, v));
          });
          panel.append(el('label', { for: 'bt-success', text: 'success probability' }), input);
        }
      }
      if (i !== 0) panel.append(el('div', { class: 'row' }, el('button', { testid: 'delete-node', text: 'Delete node', onclick: () => this.remove(element) })));
    },
    hint() { return 'Select a composite node, then click a behaviour (action) or a condition to add it as a child.'; },
  };
}
